#pragma once
// NFM wall pressure term (4.22): du_i += -(1/rho_i) s_q (P_p + P_i) W_iq n_out, with the
// wall pressure P_p of the normal flux (4.14) from the MUSCL state (4.30)-(4.32,
// kernels/WallPressure.hpp), and 2 P_min inside the bracket with the background pressure
// (2.105): its wall counterpart keeps the shift of the fluid sum from pushing particles
// into the wall (sum_P w grad W + sum_S s W n = 0). P_min = 0 without it.
#include "kernels/WallPressure.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/wall/WallPointData.hpp"

namespace ondine::wall {

struct PressureFlux {
  static constexpr const char* name = "wall_pressure";
  template <int D>
  static PressureFlux from(const PassContext<D>& c) { return PressureFlux{c.P_min}; }
  double P_min;
  template <int D>
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    const double P_p = normal_flux_pressure<D>(p.rho_i, p.P_i, p.c2, p.c_i, p.grad_rho, w.xiq, w.un);
    s.du += (-(P_p + p.P_i + 2.0 * P_min) * w.Wq / p.rho_i) * w.n;
  }
};

}  // namespace ondine::wall
