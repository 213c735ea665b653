#pragma once
// Step hooks (LAMMPS' Fix): a feature that changes the state at named points of the set-up
// and of a time step. Simulation keeps a list of them (solver/hooks/StepHooks.hpp) and calls each
// point in the list's order; it does not know which features exist. A hook reaches the
// state through StepState (solver/StepState.hpp), never through Simulation itself.
// Every point is collective: each rank calls it with its own particles.
#include <cstdint>

#include "io/Checkpoint.hpp"
#include "parallel/Communicator.hpp"
#include "particles/ParticleSet.hpp"

namespace ondine {

template <int D>
class StepState;
struct Diagnostics;

// The state particle shifting proposes for the particles [first, end), before it replaces theirs.
template <int D>
struct ShiftedState {
  int first = 0, end = 0;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
};

template <int D>
class StepHook {
 public:
  virtual ~StepHook() = default;
  virtual const char* name() const = 0;

  // set-up: the fields the hook adds to the particle set (before a checkpoint is read into it)
  virtual void allocate(ParticleSet<D>&) {}
  // set-up, after the first decomposition (before the refinement's first levels); `restart`:
  // the checkpoint the run starts from, or null
  virtual void start(StepState<D>&, const CheckpointSlice* /*restart*/) {}
  // set-up done: the initial diagnostics of a new run (none at a restart)
  virtual void started(const Diagnostics& /*initial*/) {}
  // a new particle's global id, where the hook hands them out (-1: it does not)
  virtual std::int64_t next_id() const { return -1; }

  // a step's start, before its lists: particles created or removed
  virtual void step_start(StepState<D>&) {}
  // the step's lists and levels in place (after the refinement's bookkeeping)
  virtual void after_lists(StepState<D>&) {}
  // each stage's evaluation, its gradients in place, before the flux (the first stage of a
  // step: later_stage false)
  virtual void before_flux(StepState<D>&, bool /*later_stage*/) {}
  // after each derivative evaluation (every stage)
  virtual void after_evaluation(StepState<D>&) {}
  // a shifted state, before it replaces the particles' own
  virtual void shifted(StepState<D>&, const ShiftedState<D>&) {}
  // the step integrated over dt, before the state check
  virtual void step_end(StepState<D>&, double /*dt*/) {}
  // local time stepping (refinement.local_time_stepping): the particles of `level` (its SPH
  // particles and guards, [first, end) as sorted now) integrated over their own step dt, inside
  // the coarse step that step_end closes
  virtual void level_step_end(StepState<D>&, int /*level*/, int /*first*/, int /*end*/, double /*dt*/) {}

  // what the hook carries in a checkpoint's header (collective: global counters are summed)
  virtual void save(const Communicator&, CheckpointHeader&) const {}
};

}  // namespace ondine
