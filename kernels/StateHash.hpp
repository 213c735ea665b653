#pragma once
// Order-independent checksum of the particle state: the sum (mod 2^64) over
// particles of a 64-bit mix (splitmix64's finaliser) of the bits of its id,
// position, velocity, density and mass. Any changed bit of a checkpoint's state
// changes it; the order of particles and their split among ranks do not.
#include <cstdint>

#include "kernels/Fields.hpp"

namespace ondine {

KOKKOS_INLINE_FUNCTION std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

KOKKOS_INLINE_FUNCTION std::uint64_t bits_of(double v) {
  union {
    double d;
    std::uint64_t u;
  } c{v};
  return c.u;
}

template <int D>
struct StateHash {
  using value_type = unsigned long long;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::GlobalId, D> id;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type& h) const {
    std::uint64_t a = mix64(static_cast<std::uint64_t>(id(i)));
    for (int k = 0; k < D; ++k) a = mix64(a ^ bits_of(x(i, k)));
    for (int k = 0; k < D; ++k) a = mix64(a ^ bits_of(u(i, k)));
    a = mix64(a ^ bits_of(rho(i)));
    a = mix64(a ^ bits_of(m(i)));
    h += a;
  }
};

// The same over the APR fields of a run with refinement zones (docs/apr.md): each
// particle's id, birth level, current level, role, mother flag and mother's id.
template <int D>
struct AprStateHash {
  using value_type = unsigned long long;
  field_view_t<field::GlobalId, D> id;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprLevel, D> level;
  field_view_t<field::AprGuard, D> guard;
  field_view_t<field::AprMother, D> mother;
  field_view_t<field::AprParent, D> parent;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type& h) const {
    std::uint64_t a = mix64(static_cast<std::uint64_t>(id(i)) ^ 0x5bd1e9955bd1e995ULL);
    a = mix64(a ^ static_cast<std::uint64_t>(birth(i)));
    a = mix64(a ^ static_cast<std::uint64_t>(level(i)));
    a = mix64(a ^ static_cast<std::uint64_t>(guard(i)));
    a = mix64(a ^ static_cast<std::uint64_t>(mother(i)));
    a = mix64(a ^ static_cast<std::uint64_t>(parent(i)));
    h += a;
  }
};

// The same over the rows of the fields a checkpoint carries beyond the state (the open
// boundaries' roles, k and epsilon, the Langevin model's path-averaged gradient), each packed as
// doubles (rows(e, col .. col + width)): per particle a mix of its id, the field's salt and the
// bits of each value.
template <int D>
struct FieldRowsHash {
  using value_type = unsigned long long;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> rows;
  field_view_t<field::GlobalId, D> id;
  std::uint64_t salt;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type& h) const {
    std::uint64_t a = mix64(static_cast<std::uint64_t>(id(i)) ^ salt);
    for (int k = 0; k < static_cast<int>(rows.extent(1)); ++k) a = mix64(a ^ bits_of(rows(i, k)));
    h += a;
  }
};

}  // namespace ondine
