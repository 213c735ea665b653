#pragma once
// The wall state of the Normal Flux Method, shared by the wall flux, the wall
// forces and the time-step bound so that each formula lives in one place.
#include "kernels/Math.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

// Equation-of-state data for the wall pressure: c^2 = c0^2 (rho/rho0)^(gamma-1)
// (thesis 1.9; gamma = 1 for the linear law).
struct WallEos {
  double rho0, c0, eos_gamma;
  KOKKOS_INLINE_FUNCTION double c2(double rho) const { return c0 * c0 * kmath::pow(rho / rho0, eos_gamma - 1.0); }
};

// Wall pressure of the normal flux (4.14), P_p = P_f + rho_f c (u_f - u_q).n_out, with the
// fluid state reconstructed at the wall point by MUSCL (4.30) from the renormalised
// density gradient and limited by (4.31)-(4.32): rho_f within 1 % of rho_i, the normal
// relative velocity within 0.1 c_i; P_f = P_i + c_i^2 (rho_f - rho_i) (first order in
// rho_f - rho_i <= 1 %, exact for the linear law). xiq = x_i - x_q; un = (u_f - u_q).n_out,
// the velocity's MUSCL state (kernels/WallVelocityState.hpp).
template <int D>
KOKKOS_INLINE_FUNCTION double normal_flux_pressure(double rho_i, double P_i, double c2, double c_i, const Vec<D>& grad_rho,
                                                   const Vec<D>& xiq, double un) {
  double rho_f = rho_i - dot(grad_rho, xiq);
  rho_f = kmath::fmax(0.99 * rho_i, kmath::fmin(rho_f, 1.01 * rho_i));
  un = kmath::fmax(-0.1 * c_i, kmath::fmin(un, 0.1 * c_i));
  return P_i + c2 * (rho_f - rho_i) + rho_f * c_i * un;
}

// d_n = (x_i - x_q).n_out of the NFM Laplacian's wall term (4.85), negative on the
// fluid side, kept at most -min_dn so that the term stays bounded on the wall.
template <int D>
KOKKOS_INLINE_FUNCTION double fluid_side_dn(const Vec<D>& xiq, const Vec<D>& n_out, double min_dn) {
  const double dn = dot(xiq, n_out);
  return dn > -min_dn ? -min_dn : dn;
}

}  // namespace ondine
