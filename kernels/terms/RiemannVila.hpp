#pragma once
// Riemann-SPH of Vila in ALE form (thesis 2.84-2.89, with the MUSCL states and the solver of
// RiemannLeduc.hpp): the particles move with the transport velocity u0 (u0 = u + du0 with
// scheme.transport: ale, u0 = u otherwise), the interface of (i, j) with u0_ij = (u0_i + u0_j)/2,
// and mass crosses it:
//   dw_i/dt      =  w_i sum_j w_j (u0_j - u0_i) . grad_i W_ij                                 (2.85)
//   d(m_i)/dt    = -w_i sum_j 2 w_j rho_E (u_E - u0_ij) . grad_i W_ij                          (2.86)
//   d(m_i u_i)/dt = m_i g - w_i sum_j 2 w_j (rho_E u_E (u_E - u0_ij) + P_E I) . grad_i W_ij    (2.87)
// with m_i = w_i rho_i. The state is (x, u, rho, m): drho/dt = (dm/dt - rho dw/dt) / w and
// du/dt = (d(m u)/dt - u dm/dt) / m, both linear in the pair sums, so one pair term adds its part
// of each. (u_E, P_E) solve (2.100) along n_ij; the interface state is the star state upwind of
// the interface (the side the flow through it comes from): rho_E = rho_K + (P_E - P_K) / c_K^2,
// u_E = u_E n + the tangential part of u_K, K = L where (u_E - u0_ij . n) >= 0, K = R otherwise
// (the acoustic solver's star states; the seed does not spell them out). The mass and momentum
// fluxes are antisymmetric in the pair: mass and momentum (sum m u) are conserved to round-off by
// the rates; the integrator advances u and m, so sum m u drifts at the time-step error only.
#include "kernels/terms/RiemannLeduc.hpp"
#include "kernels/PassContext.hpp"

namespace ondine {
namespace term {

template <int D, bool Muscl>
struct RiemannVila {
  static constexpr const char* name = Muscl ? "riemann_vila_muscl" : "riemann_vila";
  // u0 = u + du0 enters the fluxes with the transport velocity (scheme.transport: ale)
  static RiemannVila from(const PassContext<D>& c) { return RiemannVila{RiemannLeduc<D, Muscl>::from(c), c.m, c.du0}; }
  RiemannLeduc<D, Muscl> riemann;                     // the midpoint states and the solver
  field_view_t<field::Mass, D> m;                     // m_i: w_i = m_i / rho_i
  field_view_t<field::TransportCorrection, D> du0;    // u0 = u + du0 when allocated (scheme.transport: ale)

  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    const typename RiemannLeduc<D, Muscl>::Solution z = riemann.solve(q);
    Vec<D> u0_i = q.u_i, u0_j = q.u_j;
    if (du0.data() != nullptr) {
      u0_i += load<D>(du0, q.i);
      u0_j += load<D>(du0, q.j);
    }
    const double u0n = 0.5 * (dot(u0_i, z.n) + dot(u0_j, z.n));
    const double rel = z.E.u - u0n;  // the normal velocity of the fluid through the interface
    const bool left = rel >= 0.0;
    const double rho_E = left ? z.rho_L + (z.E.P - z.P_L) / (z.c_L * z.c_L) : z.rho_R + (z.E.P - z.P_R) / (z.c_R * z.c_R);
    const Vec<D> uK = left ? z.u_L : z.u_R;
    const Vec<D> u_E = uK + (z.E.u - dot(uK, z.n)) * z.n;
    const double nG = dot(z.n, q.gradW);
    const double mass_flux = 2.0 * q.omega_j * rho_E * rel * nG;  // per unit volume of i: -d(m_i)/dt / w_i
    const double omega_i = m(q.i) * q.inv_rho_i;
    s.dm -= omega_i * mass_flux;
    // drho/dt = (dm/dt - rho_i dw_i/dt) / w_i
    s.drho -= mass_flux + q.rho_i * q.omega_j * dot(u0_j - u0_i, q.gradW);
    // du/dt = (d(m u)/dt - u_i dm/dt) / m_i
    s.du += (-q.inv_rho_i) * (mass_flux * (u_E - q.u_i) + (2.0 * q.omega_j * z.E.P) * q.gradW);
  }
};

}  // namespace term
}  // namespace ondine
