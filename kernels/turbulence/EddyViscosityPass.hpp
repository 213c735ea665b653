#pragma once
// The eddy viscosity of the mixing-length and Smagorinsky models (V&I §4.1.1):
//   nu_T,i = L(x_i)^2 sqrt(2 S_i:S_i),   S = (<grad u> + <grad u>^T) / 2,
// with <grad u>_i the renormalised velocity gradient (2.42-2.44; kernels/VelocityGradientSum.hpp),
// exact for a linear field on a support cut by a wall or the free surface, and
//   L = kappa z sqrt(1 - z/H) (the channel's mixing length, z above the bed, 0 <= z <= H; in a
//       plane channel between walls at the bed and the bed + 2 H, z from the nearer wall),
//   L = a constant length (the mixing length's general form), or C_s dx (Smagorinsky);
// with k-epsilon (KEps) nu_T = C_mu k^2 / epsilon of the particle's own k and epsilon
// (kernels/turbulence/KEpsilon.hpp), no neighbour loop.
// With the log-law wall function (Walls), also the friction velocity u_* and y+ = y u_* / nu of
// the particle's nearest no-slip wall point (kernels/turbulence/LogLaw.hpp), y = |(x_i - x_q).n_out|
// (at least 0.05 R), from the tangential part of u_i - u_q: read by kernels/wall/WallFunction.hpp.
#include "kernels/Fields.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/turbulence/LogLaw.hpp"

namespace ondine {

// L(x) of the model
template <int D>
struct MixingLength {
  double constant = 0;  // used where axis < 0
  int axis = -1;
  double kappa = 0.41, bed = 0, depth = 1;
  bool plane = false;  // depth is the half-width of a plane channel
  KOKKOS_INLINE_FUNCTION double operator()(const Vec<D>& x) const {
    if (axis < 0) return constant;
    double z = x[axis] - bed;
    if (plane && z > depth) z = 2.0 * depth - z;
    z = z < 0.0 ? 0.0 : z > depth ? depth : z;
    return kappa * z * kmath::sqrt(1.0 - z / depth);
  }
};

// sqrt(2 S:S) of a velocity gradient
template <int D>
KOKKOS_INLINE_FUNCTION double strain_rate_magnitude(const Mat<D>& g) {
  double s2 = 0;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      const double S = 0.5 * (g.a[a][b] + g.a[b][a]);
      s2 += S * S;
    }
  return kmath::sqrt(2.0 * s2);
}

template <int D, class Kernel, bool Walls, bool KEps = false>
struct EddyViscosityPass {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  MixingLength<D> length;
  field_view_t<field::EddyViscosity, D> nu_T;
  // the wall function (Walls only)
  WallPoints<D> wall = {};
  CellList<D> wall_cells = {};
  LogLaw law = {};
  double min_dn = 0;
  field_view_t<field::FrictionVelocity, D> u_star = {};
  field_view_t<field::YPlus, D> y_plus = {};
  // k-epsilon (KEps only)
  field_view_t<field::TurbulentKineticEnergy, D> k = {};
  field_view_t<field::DissipationRate, D> eps = {};
  double c_mu = 0.09;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    if constexpr (KEps) {
      nu_T(i) = c_mu * k(i) * k(i) / eps(i);
    } else {
      VelocityGradientSum<D> S;
      for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
        S.add(m(j) / rho(j), xij, (W.derivative(r) / r) * xij, load<D>(u, j) - ui);
      });
      const double L = length(xi);
      nu_T(i) = L * L * strain_rate_magnitude<D>(S.gradient());
    }
    if constexpr (Walls) {
      double r_near = 1e300, us = 0.0, y = 0.0;
      for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
        if (!wall.no_slip(q) || r >= r_near) return;
        r_near = r;
        const Vec<D> n = load<D>(wall.n_out, q);
        const Vec<D> rel = ui - load<D>(wall.u, q);
        const Vec<D> ut = rel - dot(rel, n) * n;
        y = -fluid_side_dn<D>(xiq, n, min_dn);
        us = law.friction_velocity(kmath::sqrt(norm2(ut)), y);
      });
      u_star(i) = us;
      y_plus(i) = y * us / law.nu;
    }
  }
};

}  // namespace ondine
