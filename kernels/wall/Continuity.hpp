#pragma once
// NFM wall continuity term (4.25): drho_i += -rho_i s_q ((u_q - u_i).n_out) W_iq.
// In Vila's ALE form (kernels/terms/RiemannVila.hpp) no mass crosses a wall and the wall part of
// the volume equation (2.85) moves with the particle's transport velocity u0_i = u_i + du0_i:
// drho_i += -rho_i s_q ((u_q - u0_i).n_out) W_iq, so that a particle the transport velocity
// carries towards a wall is compressed by it as the fluid particles compress each other.
#include "kernels/Fields.hpp"
#include "kernels/wall/WallPointData.hpp"

namespace ondine::wall {

template <int D>
struct Continuity {
  static constexpr const char* name = "wall_continuity";
  field_view_t<field::TransportCorrection, D> du0 = {};  // Vila's ALE form with scheme.transport: ale only
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    double un = dot(w.uq - p.ui, w.n);
    if (du0.data() != nullptr)
      for (int k = 0; k < D; ++k) un -= du0(p.i, k) * w.n[k];
    s.drho -= p.rho_i * un * w.Wq;
  }
};

}  // namespace ondine::wall
