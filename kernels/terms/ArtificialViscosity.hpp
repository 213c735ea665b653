#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Monaghan artificial viscosity, thesis (2.58)-(2.59), one radius R for all particles:
//   Pi_ij = -(1/16) alpha (rho_i + rho_j)(2R)(c_i + c_j) mu_ij, mu_ij = u_ij.x_ij/(r^2 + eps R^2) if < 0,
//   du_i/dt += -(1/rho_i) w_j Pi_ij grad_i W_ij.
// The sound speed is taken as c0 (Ma <= 0.1 keeps c within 1 % of c0); eps = 0.01.
struct ArtificialViscosity {
  static constexpr const char* name = "artificial_viscosity";
  template <int D>
  static ArtificialViscosity from(const PassContext<D>& c) { return ArtificialViscosity{c.av_alpha_R_c0, 0.01 * c.R * c.R}; }
  double alpha_R_c0;  // alpha * R * c0
  double eps_R2;      // 0.01 R^2
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    const double ux = dot(q.u_i - q.u_j, q.xij);
    if (ux >= 0.0) return;
    const double mu = ux / (q.r * q.r + eps_R2);
    // -(1/16) alpha (rho_i+rho_j) (2R) (2 c0) mu = -(1/4) alpha R c0 (rho_i+rho_j) mu
    const double Pi = -0.25 * alpha_R_c0 * (q.rho_i + q.rho_j) * mu;
    s.du += (-q.omega_j * Pi * q.inv_rho_i) * q.gradW;
  }
  // both sides: Pi_ji = Pi_ij, grad_j W_ji = -grad_i W_ij
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    const double ux = dot(q.u_i - q.u_j, q.xij);
    if (ux >= 0.0) return;
    const double Pi = -0.25 * alpha_R_c0 * (q.rho_i + q.rho_j) * (ux / (q.r * q.r + eps_R2));
    si.du += (-q.omega_j * Pi * q.inv_rho_i) * q.gradW;
    sj.du += (q.omega_i * Pi * q.inv_rho_j) * q.gradW;
  }
};
}  // namespace ondine::term
