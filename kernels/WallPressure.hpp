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

// Wall pressure of the normal flux (4.14), P_p = P_f + c (rho (u_f - u_q)).n_out, with the
// fluid state phi = (rho, rho u) reconstructed at the wall point by MUSCL (4.30) from the
// renormalised gradients of rho and u (grad(rho u) = rho_i G_i + u_i (x) grad rho) and limited
// by (4.31)-(4.32): rho_f within 1 % of rho_i, the wall-normal momentum relative to the
// wall within 0.1 rho_i c_i (the reading of the OCR-ambiguous 4.32, nfm.md section 3);
// P_f = P_i + c_i^2 (rho_f - rho_i) (first order in rho_f - rho_i <= 1 %, exact for the
// linear law). xiq = x_i - x_q; G(a, b) = du_a/dx_b (zero: density-only reconstruction).
template <int D>
KOKKOS_INLINE_FUNCTION double normal_flux_pressure(double rho_i, double P_i, double c2, double c_i, const Vec<D>& grad_rho,
                                                   const Mat<D>& G, const Vec<D>& xiq, const Vec<D>& ui,
                                                   const Vec<D>& uq, const Vec<D>& n_out) {
  const double drho = dot(grad_rho, xiq);
  double rho_f = rho_i - drho;
  rho_f = kmath::fmax(0.99 * rho_i, kmath::fmin(rho_f, 1.01 * rho_i));
  // n . G x_iq: the change of u.n from x_i to the wall point, with the sign of x_i - x_q
  double nGx = 0.0;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) nGx += n_out[a] * G.a[a][b] * xiq[b];
  const double uin = dot(ui, n_out);
  // (rho u)_f . n - rho_f u_q . n
  double mn = rho_i * (uin - nGx) - uin * drho - rho_f * dot(uq, n_out);
  const double bound = 0.1 * rho_i * c_i;
  mn = kmath::fmax(-bound, kmath::fmin(mn, bound));
  return P_i + c2 * (rho_f - rho_i) + c_i * mn;
}

// d_n = (x_i - x_q).n_out of the NFM Laplacian's wall term (4.85), negative on the
// fluid side, kept at most -min_dn so that the term stays bounded on the wall.
template <int D>
KOKKOS_INLINE_FUNCTION double fluid_side_dn(const Vec<D>& xiq, const Vec<D>& n_out, double min_dn) {
  const double dn = dot(xiq, n_out);
  return dn > -min_dn ? -min_dn : dn;
}

}  // namespace ondine
