#pragma once
// What a step hook (solver/StepHook.hpp) may read and change of a simulation: the particle
// set and the owned count, the domain (lists, halos), the compiled passes and the walls.
// A view on the Simulation for the duration of one call; Included by hooks only.
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
class StepState {
 public:
  explicit StepState(Simulation<D>& sim) : sim_(sim) {}
  const Scene& scene() const { return sim_.scene_; }
  const Communicator& comm() const { return sim_.comm(); }
  double time() const { return sim_.t_; }
  // the time of the state being evaluated or just integrated (a stage's; with local time
  // stepping the end of a level's step inside the coarse one)
  double stage_time() const { return sim_.stage_time_; }
  std::int64_t steps() const { return sim_.steps_; }
  ParticleSet<D>& particles() { return sim_.p_; }
  int owned() const { return sim_.n_own_; }
  void set_owned(int n) { sim_.n_own_ = n; }
  Domain<D>& domain() { return sim_.domain_; }
  const CompiledScheme<D>& scheme() const { return sim_.scheme_; }
  double R() const { return sim_.R_; }
  // the levels of the evaluation (one without refinement zones) and the context of a pass over
  // a level's SPH particles; context(): the first level's (all particles without zones)
  std::vector<LevelSpan<D>> levels() const { return sim_.levels(); }
  PassContext<D> context(const LevelSpan<D>& L) const { return sim_.context(L); }
  PassContext<D> context() const { return sim_.context(sim_.levels().front()); }
  // the lists of the current positions (rebuilt if some particle moved too far)
  void ensure_lists() { sim_.ensure_neighbours(); }
  // particles were created or removed: the lists (and with zones the roles) are redone
  void particles_changed() { sim_.invalidate_neighbours(); }
  // the lists rebuilt now (with zones: `roles`, new roles); `may_rebalance`: several ranks
  // may rebalance the decomposition after it
  void rebuild_lists(bool roles, bool may_rebalance) { sim_.rebuild_lists(roles, may_rebalance); }
  // the next global id of the first hook that hands ids out (the open boundaries), -1 if none
  std::int64_t hooks_next_id() const {
    for (const auto& h : sim_.hooks_)
      if (h->next_id() >= 0) return h->next_id();
    return -1;
  }
  // the counter new particles take their global ids from where another part hands them out
  // too (the refinement's), or null
  std::int64_t* shared_id_counter() { return sim_.refinement_ ? &sim_.refinement_->apr().id_counter() : nullptr; }
  // the refinement's bookkeeping, or null without refinement zones
  AdaptiveRefinement<D>* adaptive_refinement() { return sim_.refinement_ ? &sim_.refinement_->apr() : nullptr; }
  bool has_walls() const { return !sim_.walls_.empty(); }
  const WallModel<D>& walls() const { return sim_.walls_; }
  void update_walls(double t) { sim_.update_walls(t); }
  // (only >= 0: that level's particles, local time stepping)
  void update_free_surface(int only = -1) { ondine::update_free_surface(sim_, true, only); }
  // the hooks' `shifted` point, for the hook that shifts
  void shifted(const ShiftedState<D>& s) {
    for (auto& h : sim_.hooks_) h->shifted(*this, s);
  }

 private:
  Simulation<D>& sim_;
};

}  // namespace ondine
