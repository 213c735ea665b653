#pragma once
#include "kernels/PairData.hpp"
#include "kernels/PassContext.hpp"
namespace ondine::term {
// Conservative pressure gradient G+ (thesis 2.38, 2.48): -(1/rho_i) w_j (P_i + P_j) grad_i W_ij.
// With scheme.tensile_instability_control, a free-surface particle (4.86)-(4.87) in tension
// reads (P_j - P_i) instead: the tensile instability control of Sun et al. (2017, the
// delta-plus-SPH model), so that surface particles and droplets in tension do not pull each
// other together; momentum is then exchanged unevenly for those pairs only.
struct PressureGradient {
  static constexpr const char* name = "pressure_gradient";
  Kokkos::View<const double*, MemSpace> free_surface;  // unset: no control
  template <int D>
  static PressureGradient from(const PassContext<D>& c) {
    PressureGradient g;
    if (c.tensile_control) g.free_surface = c.free_surface;
    return g;
  }
  // P_i as particle i's own side of the pair reads it
  KOKKOS_INLINE_FUNCTION double own(int i, double P) const {
    return (P < 0.0 && free_surface.data() != nullptr && free_surface(i) > 0.5) ? -P : P;
  }
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    s.du += (-q.omega_j * (own(q.i, q.P_i) + q.P_j) * q.inv_rho_i) * q.gradW;
  }
  // both sides of the pair at once (grad_j W_ji = -grad_i W_ij)
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    si.du += (-q.omega_j * (own(q.i, q.P_i) + q.P_j) * q.inv_rho_i) * q.gradW;
    sj.du += (q.omega_i * (q.P_i + own(q.j, q.P_j)) * q.inv_rho_j) * q.gradW;
  }
};
}  // namespace ondine::term
