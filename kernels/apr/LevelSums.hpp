#pragma once
// Reductions of an APR particle set that must tell levels and species apart:
// Shepard sums at a probe over the SPH particles, each with its own level's
// radius (a guard or a passive mother would count the same fluid twice), the
// integral quantities over the leaves (particles that are not mothers: each
// mother's mass and momentum are carried by its daughters), the maximum of a
// criterion inside a zone's search region, and a minimum over a range.
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

// sum_j w_j q_j W(|x - x_j|, R_j) over SPH particles, q = 1, P, rho or u_k (what = 0, 1, 2, 3 + k)
template <int D, class UnitKernel>
struct ProbeSum {
  using value_type = double;
  RefinementZones<D> zones;
  UnitKernel W1;
  Vec<D> xp;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprGuard, D> guard;
  int what;
  KOKKOS_INLINE_FUNCTION void operator()(const int j, double& acc) const {
    if (guard(j)) return;
    const double r = kmath::sqrt(norm2(zones.box.delta(xp, load<D>(x, j))));
    if (r >= zones.R[birth(j)]) return;
    const double q = what == 0 ? 1.0 : what == 1 ? P(j) : what == 2 ? rho(j) : u(j, what - 3);
    acc += m(j) / rho(j) * q * level_kernel<D>(zones, W1, birth(j), r);
  }
};

// sum over the leaves of m, m u_k (k = 0 .. D-1), m |u|^2 / 2 or -m g.x (what = 0, 1 + k, D + 1, D + 2)
template <int D>
struct LeafSum {
  using value_type = double;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprMother, D> mother;
  int what;
  field_view_t<field::Position, D> x = {};  // what = D + 2 only
  Vec<D> g = Vec<D>::zero();
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& acc) const {
    if (mother(i)) return;
    if (what == 0) acc += m(i);
    else if (what <= D) acc += m(i) * u(i, what - 1);
    else if (what == D + 1) acc += 0.5 * m(i) * norm2(load<D>(u, i));
    else acc -= m(i) * dot(g, load<D>(x, i));
  }
};

// the SPH particle of largest |P| (speed = false) or |u| (speed = true) inside a box
template <int D>
struct MaxInBox {
  using value_type = Kokkos::MaxLoc<double, int>::value_type;
  double lo[D], hi[D];
  bool speed;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::AprGuard, D> guard;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type& best) const {
    if (guard(i)) return;
    for (int k = 0; k < D; ++k)
      if (x(i, k) < lo[k] || x(i, k) > hi[k]) return;
    const double v = speed ? norm2(load<D>(u, i)) : (P(i) < 0 ? -P(i) : P(i));
    if (v > best.val) {
      best.val = v;
      best.loc = i;
    }
  }
};

struct MinOf {
  Kokkos::View<double*, MemSpace> v;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mn) const {
    if (v(i) < mn) mn = v(i);
  }
};

struct CountGuards {
  Kokkos::View<int*, MemSpace> guard;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, long& c) const { c += guard(i) != 0 ? 1 : 0; }
};

}  // namespace apr

}  // namespace ondine
