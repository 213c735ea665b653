#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Monaghan-Gingold laminar viscosity, thesis (2.32): 2(N+2) nu w_j (u_ij . x_ij)/r^2 grad_i W_ij,
// with w_j (rho_i + rho_j)/(2 rho_i) in place of w_j so that momentum is conserved exactly.
struct MonaghanGingoldViscosity {
  static constexpr const char* name = "monaghan_gingold_viscosity";
  template <int D>
  static MonaghanGingoldViscosity from(const PassContext<D>& c) { return MonaghanGingoldViscosity{c.nu_pair}; }
  double nu;
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    const double pi_ij = dot(q.u_i - q.u_j, q.xij) / (q.r * q.r);
    const double f = (D + 2) * nu * q.omega_j * (q.rho_i + q.rho_j) * q.inv_rho_i * pi_ij;
    s.du += f * q.gradW;
  }
};
}  // namespace ondine::term
