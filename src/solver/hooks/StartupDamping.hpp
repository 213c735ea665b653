#pragma once
// time.damping: the velocities relaxed at the end of each step while t < t_damp, by
// exp(-dt / (0.1 t_damp)), to take out the start-up acoustic wave of a fluid at rest.
#include <cmath>

#include "kernels/Integrator.hpp"
#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class StartupDamping final : public StepHook<D> {
 public:
  const char* name() const override { return "startup_damping"; }
  void step_end(StepState<D>& s, double dt) override {
    const double t_damp = s.scene().damping_time;
    if (s.time() >= t_damp) return;
    VelocityDamping<D>{s.particles().get(field::Velocity{}), std::exp(-dt / (0.1 * t_damp))}.run(s.owned());
    s.domain().halos_stale();
  }
};

}  // namespace ondine
