#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Morris et al. (1997) laminar viscosity, the Laplacian L_MEA of thesis (2.31)
// in its momentum-conserving form: nu w_j (rho_i + rho_j)/rho_i (x_ij . grad_i W_ij)/r^2 u_ij,
// which equals nu L_MEA(u)_i when rho_i = rho_j.
struct MorrisViscosity {
  static constexpr const char* name = "morris_viscosity";
  template <int D>
  static MorrisViscosity from(const PassContext<D>& c) { return MorrisViscosity{c.nu_pair}; }
  double nu;
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    // x_ij . grad_i W_ij / r^2 = W'(r) / r
    const double f = nu * q.omega_j * (q.rho_i + q.rho_j) * q.inv_rho_i * q.dWdr / q.r;
    s.du += f * (q.u_i - q.u_j);
  }
  // both sides: u_ji = -u_ij
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    const double f = nu * (q.rho_i + q.rho_j) * q.dWdr / q.r;
    const Vec<D> uij = q.u_i - q.u_j;
    si.du += (f * q.omega_j * q.inv_rho_i) * uij;
    sj.du -= (f * q.omega_i * q.inv_rho_j) * uij;
  }
};
}  // namespace ondine::term
