#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Conservative pressure gradient G+ (thesis 2.38, 2.48): -(1/rho_i) w_j (P_i + P_j) grad_i W_ij.
struct PressureGradient {
  static constexpr const char* name = "pressure_gradient";
  template <int D>
  static PressureGradient from(const PassContext<D>&) { return PressureGradient{}; }
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    s.du += (-q.omega_j * (q.P_i + q.P_j) * q.inv_rho_i) * q.gradW;
  }
  // both sides of the pair at once (grad_j W_ji = -grad_i W_ij)
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    const double P = q.P_i + q.P_j;
    si.du += (-q.omega_j * P * q.inv_rho_i) * q.gradW;
    sj.du += (q.omega_i * P * q.inv_rho_j) * q.gradW;
  }
};
}  // namespace ondine::term
