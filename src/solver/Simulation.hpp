#pragma once
// Weakly-compressible SPH: the particle state and the parts that act on it, each in a
// file of its own (docs/design.md): the domain (solver/Domain.hpp: cells, lists,
// decomposition, halos), set-up (SimulationSetup.hpp), lists by level
// (SimulationLists.hpp), the derivative evaluation (SimulationEvaluate.hpp), the time
// integrators (SimulationStep.hpp) and the preparation of an output (SimulationOutput.hpp);
// the measures observers read are free functions (Measures.hpp).
// Templated on dimension only; the physics is chosen once, in FluxDispatch.
// On several MPI ranks each rank owns the particles of its ORB subdomain
// (indices 0 .. owned()-1) followed by halo copies of its neighbours'; every
// public call is collective and returns global figures.
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/CellList.hpp"
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/WallFluxPass.hpp"
#include "solver/Scheme.hpp"
#include "kernels/Integrator.hpp"
#include "kernels/NeighbourList.hpp"
#include "kernels/OrbLookup.hpp"
#include "kernels/SymmetricFluxPass.hpp"
#include "kernels/WallPressure.hpp"
#include "io/Checkpoint.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/ParticleExchange.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"
#include "solver/AdaptiveRefinement.hpp"
#include "solver/BlowUpCheck.hpp"
#include "solver/Measures.hpp"
#include "solver/Domain.hpp"
#include "solver/StepHook.hpp"
#include "solver/WallModel.hpp"

namespace ondine {

// One level of the evaluation: a uniform run has one, level 0, over all its owned
// particles; with refinement zones there is one per level (particles sorted by level,
// each level's SPH particles first, then its guards; docs/apr.md). Every pass of an
// evaluation runs once per level with the level's radius, list and wall cells.
template <int D>
struct LevelSpan {
  int level = 0;
  int first = 0, active_end = 0, end = 0;  // SPH particles [first, active_end), guards [active_end, end)
  double R = 0, dx = 0;
  NeighbourList<D> list;   // the level's SPH pairs (L. with zones; the uniform list otherwise)
  NeighbourList<D> half_list;  // scheme.pair_list: half (uniform runs): each pair of the level once
  WallPoints<D> wall;      // the wall quadrature points of the level (its spacing)
  CellList<D> wall_cells;  // those points binned at R
};

template <int D>
class Refinement;

template <int D>
class Simulation {
 public:
  // A new run from the scene's fluid blocks, or, with `restart`, this rank's
  // share of a checkpoint (io/Checkpoint.hpp).
  explicit Simulation(const Scene& scene, const CheckpointSlice* restart = nullptr);

  // Advances one time step; returns the step taken. `t_stop` caps the step so
  // that output instants are hit exactly.
  double step(double t_stop);

  double time() const { return t_; }
  std::int64_t steps() const { return steps_; }
  const Scene& scene() const { return scene_; }
  ParticleSet<D>& particles() { return p_; }
  const ParticleSet<D>& particles() const { return p_; }
  std::size_t size() const { return static_cast<std::size_t>(n_own_); }  // particles this rank owns
  const Communicator& comm() const { return domain_.comm(); }
  const Domain<D>& domain() const { return domain_; }
  // the neighbour list is rebuilt at the next evaluation (a checkpoint does it, so
  // that a restarted run takes the same path)
  // (with refinement zones: the next step starts with a bookkeeping, as a restart's does)
  void invalidate_neighbours();
  // the passes chosen once for the scene (Scheme.hpp)
  const CompiledScheme<D>& scheme() const { return scheme_; }
  // the levels of the evaluation (one without refinement zones)
  std::vector<LevelSpan<D>> levels() const;
  double R() const { return R_; }
  const Diagnostics& initial_diagnostics() const { return initial_; }
  // the named context of a pass over a level's SPH particles (Scheme.hpp)
  PassContext<D> context(const LevelSpan<D>& level) const;

  // Derivatives (du/dt, drho/dt, pressure) at the current state; public for tests.
  // later_stage: a stage after the first of a time step, where scheme.density_gradient: step
  // keeps the density gradient of the step's first stage.
  void evaluate(bool later_stage = false);

  // NFM walls
  const WallModel<D>& walls() const { return walls_; }

  // the step hooks (hooks/StepHooks.hpp): the one of type H, or null where the scene has none
  template <class H>
  const H* find_hook() const {
    for (const auto& h : hooks_)
      if (const H* f = dynamic_cast<const H*>(h.get())) return f;
    return nullptr;
  }
  // a hook beyond the scene's (a test's, a coupling's), run after them; added after the set-up,
  // so only its allocate point runs now (not start nor started)
  void add_hook(std::unique_ptr<StepHook<D>> h) {
    h->allocate(p_);
    hooks_.push_back(std::move(h));
  }
  // what the hooks carry in a checkpoint's header (collective)
  void save_hooks(CheckpointHeader& h) const {
    for (const auto& k : hooks_) k->save(comm(), h);
  }
  // the global id the next new particle gets (with refinement zones the APR's counter, which
  // a hook that creates particles shares); 0 where nothing creates particles
  std::int64_t next_id() const;

  // adaptive particle refinement (only with refinement zones; hooks/Refinement.hpp, docs/apr.md)
  bool refinement_on() const { return refinement_ != nullptr; }
  const AdaptiveRefinement<D>& refinement() const;
  // local time stepping: the steps each level has taken since t = 0 (empty without it)
  const std::vector<std::int64_t>& level_steps() const { return level_steps_; }
  // with refinement zones: the sum over this process's steps of each level's SPH particles
  // (this rank's) that took the step, the work each level cost
  const std::vector<double>& level_particle_steps() const { return level_particle_steps_; }

 private:
  template <int>
  friend class OutputFrame;
  template <int>
  friend class StepState;
  // lists (solver/SimulationLists.hpp): one path, uniform or by level
  void ensure_neighbours();
  // roles: recomputed at a bookkeeping (zones only), kept otherwise
  void rebuild_lists(bool roles, bool may_rebalance);
  // evaluation (solver/SimulationEvaluate.hpp)
  void update_walls(double t);
  // stepping (solver/SimulationStep.hpp); only >= 0: that level's own step
  double time_step(int only = -1) const;
  double capped_step(double dt, double t_stop) const;
  void finish_step(double dt);
  // the integrator's stages from t0 over h (RK4 or the midpoint scheme): stage(c_dt, w, first),
  // evaluate_at(t) before each later stage, rk4_final() (solver/SimulationStep.hpp)
  template <class Stage, class EvaluateAt, class Final>
  void integrate(double t0, double h, const Stage& stage, const EvaluateAt& evaluate_at, const Final& rk4_final);
  // LevelEnd* <- state (keep) or state <- LevelEnd* over [first, end) (local time stepping)
  void level_end_copy(int first, int end, bool keep);
  // local time stepping by level (solver/SimulationLocalSteps.hpp)
  double step_local(double t_stop);
  void advance_level(int l, double t0, double h, bool fresh, std::vector<double>& start, std::vector<double>& span);
  void hold_coarser_at(int l, double tau, const std::vector<double>& start, const std::vector<double>& span);

  const Scene scene_;  // as parsed: what the solver derives lives in its own members
  Domain<D> domain_;
  ParticleSet<D> p_;
  int n_own_ = 0;
  std::int64_t lattice_first_ = 0;
  double R_, skin_len_ = 0;
  double wall_spacing_ = 0;  // the wall quadrature's spacing (wall_quadrature_spacing)
  CompiledScheme<D> scheme_;  // every kernel-dependent pass, chosen once (Scheme.hpp)
  WallModel<D> walls_;
  LaplacianWeightView<D> laplacian_weights_;
  mutable PairScatter<D> pair_scatter_;  // scheme.pair_list: half: the flux pass's scattered sums  // scratch of evaluate() (kernels/ConsistentLaplacian.hpp)
  double stage_time_ = 0;
  double t_ = 0;
  std::int64_t steps_ = 0;
  Diagnostics initial_;
  std::vector<std::unique_ptr<StepHook<D>>> hooks_;  // in the order their points run
  Refinement<D>* refinement_ = nullptr;  // the refinement hook (one of hooks_), with refinement zones
  int eval_level_ = -1;  // local time stepping: the one level evaluate() passes over (-1: all)
  std::vector<std::int64_t> level_steps_;  // local time stepping: steps each level has taken since t = 0
  std::vector<double> level_particle_steps_;  // with zones: SPH particles x steps, per level, this rank since t = 0 (after a restart rank 0 holds the earlier all-rank totals)
  void count_particle_steps(int level);  // level < 0: every level (a global step)
};

// An output instant of a simulation, as a scope: while the frame lives, the simulation's
// derived fields are those of its stored state (pressure from the EOS, the walls' Shepard
// factor and the free-surface flag at time t; with refinement zones, every guard
// interpolated from the stored state, 5.24), for the snapshot and the observers to read;
// when it ends, the run goes on from its own state (the guards' fields as the next step
// reads them are put back), so an output never changes the run. One frame at a time.
template <int D>
class OutputFrame {
 public:
  // before the output: pressure from the EOS, the walls and their Shepard factor at time t,
  // the free surface (flags false: not the free-surface flags, which only a snapshot writes);
  // with refinement zones every guard interpolated from the stored state
  explicit OutputFrame(Simulation<D>& sim, bool flags = true);
  // after it: puts back what the frame changed that the next step reads (with zones the
  // guards' velocity, density and density gradient), so that an output, a checkpoint or a
  // restart does not change the run
  ~OutputFrame();
  OutputFrame(const OutputFrame&) = delete;
  OutputFrame& operator=(const OutputFrame&) = delete;

 private:
  Simulation<D>& sim_;
};

// The free-surface flag (4.86-4.87) into field::FreeSurface (flags false: not it) and the walls'
// Shepard factor, at the stored state (solver/SimulationOutput.hpp); at output times, and after
// shifting.
template <int D>
void update_free_surface(Simulation<D>& sim, bool flags = true, int only = -1);

extern template class Simulation<2>;
extern template class Simulation<3>;
extern template class OutputFrame<2>;
extern template class OutputFrame<3>;

}  // namespace ondine
