#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Tensile-instability correction, thesis (2.105): -(2 P_min / rho_i) w_j grad_i W_ij with
// P_min = max(0, -min_k P_k), a global reduction before the pass. Flows without a free surface only.
struct BackgroundPressure {
  static constexpr const char* name = "background_pressure";
  template <int D>
  static BackgroundPressure from(const PassContext<D>& c) { return BackgroundPressure{c.P_min}; }
  double P_min;
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    s.du += (-2.0 * P_min * q.omega_j * q.inv_rho_i) * q.gradW;
  }
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    si.du += (-2.0 * P_min * q.omega_j * q.inv_rho_i) * q.gradW;
    sj.du += (2.0 * P_min * q.omega_i * q.inv_rho_j) * q.gradW;
  }
};
}  // namespace ondine::term
