#pragma once
// Initial state of one fluid block: a lattice of cnt[0] x ... x cnt[D-1] particles
// at (k + 1/2) dx from the block's low corner, numbered from `offset` (a
// distributed run fills its share of the points, [first, first + n)), with its
// initial velocity (uniform, or the Taylor-Green vortex u = -U cos kx sin ky,
// v = U sin kx cos ky) and pressure (zero, hydrostatic rho0 g.(x - x_top) below
// the free surface, or Taylor-Green -rho0 U^2/4 (cos 2kx + cos 2ky)); the density
// inverts the equation of state (Tait 1.8 or linear 6.5, without p_b) and
// m = rho dx^D.
#include <cstdint>

#include "kernels/Fields.hpp"
#include "kernels/Math.hpp"
#include "kernels/InitialKinds.hpp"

namespace ondine {

template <int D>
struct InitialFill {
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::GlobalId, D> id;
  std::int64_t offset;  // global index of the block's first particle
  std::int64_t first = 0;  // lattice index (within the block) of the first point filled
  std::int64_t dst = 0;    // storage index of the first point filled
  int cnt[D];
  double lo[D];
  double dx, volume;  // volume = dx^D
  double g[D];        // gravity + body force
  double top;         // -g . x_top: the free surface is the block face facing against g
  InitialVelocity velocity_kind;
  double velocity[D];  // uniform velocity
  InitialPressure pressure_kind;
  double tg_amplitude, k_tg;  // Taylor-Green U and 2 pi / L
  bool tait;
  double rho0, c0, gam;

  KOKKOS_INLINE_FUNCTION void operator()(const std::int64_t a) const {
    const std::int64_t i = dst + a;
    std::int64_t rest = first + a;
    double pos[D];
    for (int k = 0; k < D; ++k) {
      pos[k] = lo[k] + (static_cast<double>(rest % cnt[k]) + 0.5) * dx;
      rest /= cnt[k];
    }
    for (int k = 0; k < D; ++k) x(i, k) = pos[k];
    double P = 0.0;
    if (velocity_kind == InitialVelocity::TaylorGreen) {
      const double U = tg_amplitude;
      u(i, 0) = -U * kmath::cos(k_tg * pos[0]) * kmath::sin(k_tg * pos[1]);
      u(i, 1) = U * kmath::sin(k_tg * pos[0]) * kmath::cos(k_tg * pos[1]);
      for (int k = 2; k < D; ++k) u(i, k) = 0.0;
    } else {
      for (int k = 0; k < D; ++k) u(i, k) = velocity[k];
    }
    if (pressure_kind == InitialPressure::Hydrostatic) {
      double h = top;  // depth below the free surface along g: (x - x_top) . g
      for (int k = 0; k < D; ++k) h += pos[k] * g[k];
      P = rho0 * h;  // rho0 * (g . (x - x_top)) >= 0 inside the block
    } else if (pressure_kind == InitialPressure::TaylorGreen) {
      const double U = tg_amplitude;
      P = -0.25 * rho0 * U * U * (kmath::cos(2.0 * k_tg * pos[0]) + kmath::cos(2.0 * k_tg * pos[1]));
    }
    const double r = tait ? rho0 * kmath::pow(1.0 + gam * P / (rho0 * c0 * c0), 1.0 / gam) : rho0 + P / (c0 * c0);
    rho(i) = r;
    m(i) = r * volume;
    id(i) = offset + first + a;
  }

  void run(std::int64_t n) const {
    Kokkos::parallel_for("ondine::InitialFill", Kokkos::RangePolicy<ExecSpace>(0, n), *this);
  }
};

}  // namespace ondine
