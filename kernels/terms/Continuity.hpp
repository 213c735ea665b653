#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Continuity with the divergence D- (thesis 2.39, 2.49): -rho_i w_j (u_j - u_i) . grad_i W_ij.
struct Continuity {
  static constexpr const char* name = "continuity";
  template <int D>
  static Continuity from(const PassContext<D>&) { return Continuity{}; }
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    s.drho -= q.rho_i * q.omega_j * dot(q.u_j - q.u_i, q.gradW);
  }
  // both sides: (u_i - u_j) . grad_j W_ji = (u_j - u_i) . grad_i W_ij
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    const double div = dot(q.u_j - q.u_i, q.gradW);
    si.drho -= q.rho_i * q.omega_j * div;
    sj.drho -= q.rho_j * q.omega_i * div;
  }
};
}  // namespace ondine::term
