#pragma once
// scheme.transport: ale: the transport velocity's correction du0 of Oger's law (2.112)-(2.115),
// with NFM walls (4.89) (kernels/OgerVelocityLaw.hpp), at every stage before the flux, level by
// level; with a free surface possible, from the flags (4.86)-(4.87) of the step's first stage.
// The integrator moves the particles with u + du0 (kernels/Integrator.hpp).
#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class TransportVelocity final : public StepHook<D> {
 public:
  const char* name() const override { return "transport_velocity"; }
  void allocate(ParticleSet<D>& p) override { p.allocate(field::TransportCorrection{}); }
  void before_flux(StepState<D>& s, bool later_stage) override {
    ParticleSet<D>& p = s.particles();
    const std::vector<LevelSpan<D>> levels = s.levels();
    if (p.has(field::FreeSurface{})) {
      if (!later_stage)
        for (const LevelSpan<D>& L : levels)
          if (L.active_end > L.first) s.scheme().free_surface(s.context(L));
      // at every stage: a list rebuilt since may have made new halo copies
      s.domain().refresh(p, field::FreeSurface{});
    }
    for (const LevelSpan<D>& L : levels)
      if (L.active_end > L.first) s.scheme().transport_velocity(s.context(L));
    s.domain().refresh(p, field::TransportCorrection{});
  }
};

}  // namespace ondine
