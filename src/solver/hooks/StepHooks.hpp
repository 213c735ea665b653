#pragma once
// The step hooks a scene asks for, in the order their points run (solver/StepHook.hpp): one
// line each. A new hook is one file in this folder and one line here.
#include <memory>
#include <stdexcept>
#include <vector>

#include "solver/hooks/EddyViscosity.hpp"
#include "solver/hooks/ImpermeabilityGuard.hpp"
#include "solver/hooks/OpenBoundaryStep.hpp"
#include "solver/hooks/ParticleShifting.hpp"
#include "solver/hooks/Refinement.hpp"
#include "solver/hooks/StartupDamping.hpp"
#include "solver/hooks/TransportVelocity.hpp"

namespace ondine {

template <int D>
std::vector<std::unique_ptr<StepHook<D>>> make_step_hooks(const Scene& s, const CheckpointSlice* restart) {
  std::vector<std::unique_ptr<StepHook<D>>> list;
  if (s.turbulence.on()) list.push_back(std::make_unique<EddyViscosity<D>>(s));
  if (s.ale) list.push_back(std::make_unique<TransportVelocity<D>>());
  if (s.shifting) list.push_back(std::make_unique<ParticleShifting<D>>());
  if (!s.walls.empty()) list.push_back(std::make_unique<ImpermeabilityGuard<D>>());
  if (s.damping_time > 0) list.push_back(std::make_unique<StartupDamping<D>>());
  if (!s.open_boundaries.empty()) list.push_back(std::make_unique<OpenBoundaryStep<D>>(s, restart));
  else if (restart && restart->header.open.present)
    throw std::runtime_error("the checkpoint was written by a run with open boundaries; the case has none");
  // last: its step start sorts what the others created or removed
  if (!s.refinement_zones.empty()) list.push_back(std::make_unique<Refinement<D>>(s, restart));
  return list;
}

}  // namespace ondine
