#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// The Reynolds-averaged viscous term with a particle's own eddy viscosity (V&I §4.1.1), in the
// momentum-conserving Morris form of kernels/terms/MorrisViscosity.hpp with mu = rho (nu + nu_T):
//   du_i += w_j (rho_i nu_i + rho_j nu_j) / rho_i  W'(r)/r  u_ij,   nu_k = f_M (nu + nu_T,k),
// f_M the Morris lattice factor; with nu_T = 0 it is MorrisViscosity.
template <int D>
struct EddyMorrisViscosity {
  static constexpr const char* name = "eddy_morris_viscosity";
  static EddyMorrisViscosity from(const PassContext<D>& c) { return EddyMorrisViscosity{c.nu * c.morris_factor, c.morris_factor, c.nu_T}; }
  double nu;      // f_M nu
  double factor;  // f_M
  field_view_t<field::EddyViscosity, D> nu_T;
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    const double mu = q.rho_i * (nu + factor * nu_T(q.i)) + q.rho_j * (nu + factor * nu_T(q.j));
    const double f = q.omega_j * mu * q.inv_rho_i * q.dWdr / q.r;
    s.du += f * (q.u_i - q.u_j);
  }
};
}  // namespace ondine::term
