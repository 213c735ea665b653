#pragma once
// The impermeability guard of the NFM walls (kernels/WallImpermeability.hpp) at the end of
// each step (with local time stepping, of each level's step): a particle whose path over the
// step crossed a wall is put back on the fluid side. Counts its corrections since t = 0
// (carried by checkpoints). Runs with walls.
#include "kernels/WallImpermeability.hpp"
#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class ImpermeabilityGuard final : public StepHook<D> {
 public:
  const char* name() const override { return "impermeability_guard"; }
  void start(StepState<D>& s, const CheckpointSlice* restart) override {
    if (restart) corrections_ = s.comm().rank() == 0 ? restart->header.wall_corrections : 0;  // a global count, carried by rank 0
  }
  void step_end(StepState<D>& s, double dt) override {
    if (!s.scene().refinement_local_time_stepping) check(s, 0, s.owned(), s.time(), dt);
  }
  // local time stepping: each level's path over its own step (its stage storage holds the
  // step's start), which ends at the stage time
  void level_step_end(StepState<D>& s, int, int first, int end, double dt) override { check(s, first, end, s.stage_time() - dt, dt); }
  void save(const Communicator& comm, CheckpointHeader& h) const override { h.wall_corrections = corrections(comm); }
  // corrections since t = 0, all ranks
  std::int64_t corrections(const Communicator& comm) const { return comm.sum(corrections_); }

 private:
  // the particles [first, end), whose step of dt started at t0
  void check(StepState<D>& s, int first, int end, double t0, double dt) {
    s.update_walls(t0 + dt);
    const WallModel<D>& w = s.walls();
    ParticleSet<D>& p = s.particles();
    const long c = WallImpermeability<D>{w.facets(), w.facet_cells(), w.wall_velocity(), dt, s.domain().box(), p.get(field::StagePosition{}),
                                         p.get(field::Position{}), p.get(field::Velocity{}), w.wall_spin()}
                       .run(first, end);
    if (c > 0) s.domain().halos_stale();
    corrections_ += c;
  }
  std::int64_t corrections_ = 0;  // this rank's
};

}  // namespace ondine
