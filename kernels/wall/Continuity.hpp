#pragma once
// NFM wall continuity term (4.25): drho_i += -rho_i s_q ((u_q - u_i).n_out) W_iq.
// Also in Vila's ALE form with the transport velocity: the wall part of the volume equation
// with u0_i = u_i + du0_i in place of u_i was measured worse (a feedback: du0 carries a particle
// towards the wall, the wall compresses it, its speed and so du0 grow; docs/validation.md,
// "Design choices in the kernels, measured").
#include "kernels/wall/WallPointData.hpp"
#include "kernels/PassContext.hpp"

namespace ondine::wall {

struct Continuity {
  static constexpr const char* name = "wall_continuity";
  template <int D>
  static Continuity from(const PassContext<D>&) { return Continuity{}; }
  template <int D>
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    s.drho -= p.rho_i * dot(w.uq - p.ui, w.n) * w.Wq;
  }
};

}  // namespace ondine::wall
