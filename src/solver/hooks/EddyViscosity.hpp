#pragma once
// turbulence: the eddy viscosity nu_T of the mixing-length or Smagorinsky model (V&I §4.1.1) at
// every stage before the flux, from that stage's velocities (kernels/turbulence/EddyViscosityPass.hpp),
// read by the Morris term with nu + nu_T (kernels/terms/EddyMorrisViscosity.hpp); with the log-law
// wall function also u_* and y+ next to no-slip walls (kernels/wall/WallFunction.hpp). The halo
// copies get nu_T, which the pair term reads on both sides.
#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class EddyViscosity final : public StepHook<D> {
 public:
  const char* name() const override { return "eddy_viscosity"; }
  void allocate(ParticleSet<D>& p) override {
    p.allocate(field::EddyViscosity{});
    p.allocate(field::FrictionVelocity{});
    p.allocate(field::YPlus{});
  }
  void before_flux(StepState<D>& s, bool /*later_stage*/) override {
    for (const LevelSpan<D>& L : s.levels())
      if (L.active_end > L.first) s.scheme().eddy_viscosity(s.context(L));
    s.domain().refresh(s.particles(), field::EddyViscosity{});
  }
};

}  // namespace ondine
