#pragma once
// NFM wall continuity term (4.25): drho_i += -rho_i s_q ((u_q - u_i).n_out) W_iq.
#include "kernels/wall/WallPointData.hpp"

namespace ondine::wall {

struct Continuity {
  static constexpr const char* name = "wall_continuity";
  template <int D>
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    s.drho -= p.rho_i * dot(w.uq - p.ui, w.n) * w.Wq;
  }
};

}  // namespace ondine::wall
