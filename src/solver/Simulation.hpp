#pragma once
// Weakly-compressible SPH: the particle state and the parts that act on it, each in a
// file of its own (docs/design.md): the domain (solver/Domain.hpp: cells, lists,
// decomposition, halos), set-up (SimulationSetup.hpp), lists by level
// (SimulationLists.hpp), the derivative evaluation (SimulationEvaluate.hpp), the time
// integrators (SimulationStep.hpp) and the observers (SimulationObservers.hpp).
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
#include "kernels/WallPressure.hpp"
#include "io/Checkpoint.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/ParticleExchange.hpp"
#include "particles/ParticleSet.hpp"
#include "kernels/FluidRegion.hpp"
#include "scene/Scene.hpp"
#include "solver/AdaptiveRefinement.hpp"
#include "solver/Domain.hpp"
#include "solver/StepHook.hpp"
#include "solver/WallModel.hpp"

namespace ondine {

// Integral quantities of the particle set (Kokkos reductions).
struct Diagnostics {
  double mass = 0;
  double fluid_mass = 0;  // with open boundaries: the fluid region's (buffer layers excluded); = mass otherwise
  Vec3 momentum{0, 0, 0};
  double kinetic_energy = 0;
  double max_speed = 0;
  double rho_min = 0, rho_max = 0;
  std::int64_t outside_domain = 0;  // particles beyond a non-periodic domain face
  bool finite = true;               // no NaN/Inf in positions, velocities, densities
};

struct ProbeSample {
  double pressure = 0, density = 0;
  Vec3 velocity{0, 0, 0};
  double shepard = 0;  // sum_j w_j W: 0 means no fluid around the probe
};

// Force of the fluid on one wall (the reaction of the wall terms of 4.22 and 4.85).
struct WallForce {
  std::string name;
  Vec3 pressure{0, 0, 0}, viscous{0, 0, 0};  // N (per metre of span in 2D)
  Vec3 moment{0, 0, 0};  // of pressure + viscous about the wall's moment_centre, N m (2D: z only, N m per metre)
};

// Thrown by step() when the state blows up; the particles hold the last good
// state (the start of the failed step) when it is caught.
struct BlowUp : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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
  WallPoints<D> wall;      // the wall quadrature points of the level (its spacing)
  CellList<D> wall_cells;  // those points binned at R
};

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
  std::int64_t global_size() const { return comm().sum(static_cast<std::int64_t>(n_own_)); }
  const Communicator& comm() const { return domain_.comm(); }
  const Domain<D>& domain() const { return domain_; }
  // distributed runs: balance indicator tau (5.30) at the last list build, rebalances,
  // particles migrated, wall seconds in migration and halo exchange, halo copies here
  double balance() const { return domain_.balance(); }
  int rebalances() const { return domain_.rebalances(); }
  std::int64_t migrated() const { return domain_.exchange().migrated(); }
  double exchange_seconds() const { return domain_.exchange().seconds(); }
  double halo_seconds() const { return domain_.exchange().halo_seconds(); }
  double migration_seconds() const { return domain_.exchange().migration_seconds(); }
  double rebalance_seconds() const { return domain_.rebalance_seconds(); }
  int halo_count() const { return domain_.exchange().halo_count(); }
  const Decomposition& decomposition() const { return domain_.decomposition(); }
  // the neighbour list is rebuilt at the next evaluation (a checkpoint does it, so
  // that a restarted run takes the same path)
  // (with refinement zones: the next step starts with a bookkeeping, as a restart's does)
  void invalidate_neighbours() {
    domain_.invalidate_lists();
    bookkeeping_due_ = true;
  }
  // owned rows of the state fields (io/Checkpoint.hpp) on the host: name -> (rows, components);
  // with refinement zones, of the APR fields too (checkpoint_refinement_fields())
  std::map<std::string, std::pair<std::vector<double>, int>> state_rows() const;
  // order-independent checksum of the state fields (position, velocity, density, mass, id), all ranks
  std::uint64_t state_checksum() const;
  // with refinement zones: the APR state a checkpoint carries (all but the zone text), with
  // the checksum of the APR fields (kernels/StateHash.hpp)
  CheckpointRefinement refinement_state() const;
  std::uint64_t refinement_checksum() const;
  std::int64_t pair_count() const;            // pairs within R (both ways) at the last list build
  std::int64_t neighbour_builds() const { return domain_.builds(); }
  // lattice quadrature factor of the Morris Laplacian (kernels/MorrisLatticeFactor.hpp); 1 without it
  double morris_factor() const { return scheme_.morris_factor; }
  // the levels of the evaluation (one without refinement zones)
  std::vector<LevelSpan<D>> levels() const;
  double R() const { return R_; }
  const Diagnostics& initial_diagnostics() const { return initial_; }

  // Observers (solver/SimulationObservers.hpp): they read the state and change none of it.
  Diagnostics diagnostics() const;
  std::vector<ProbeSample> sample_probes() const;
  std::vector<ProbeSample> sample_at(const std::vector<Vec3>& points) const;
  // free-surface elevation at each of the scene's wave gauges (kernels/WaveGauge.hpp)
  std::vector<double> wave_elevations();
  // x of the leading edge of the fluid (max x + dx/2), for the dam-break front
  double front_position() const;

  // Derivatives (du/dt, drho/dt, pressure) at the current state; public for tests.
  // later_stage: a stage after the first of a time step, where scheme.density_gradient: step
  // keeps the density gradient of the step's first stage.
  void evaluate(bool later_stage = false);

  // NFM walls
  bool has_walls() const { return !walls_.empty(); }
  const WallModel<D>& walls() const { return walls_; }
  std::vector<WallForce> wall_forces();
  // particles on the solid side of a wall or closer than `clearance` (default 0.1 dx) to one
  std::int64_t wall_leaks(double clearance = -1) const;
  // free-surface flag (4.86-4.87) into field::FreeSurface, at output times
  void update_free_surface();

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

  // adaptive particle refinement (only with refinement zones; docs/apr.md)
  bool refinement_on() const { return apr_on_; }
  const AdaptiveRefinement<D>& refinement() const { return apr_; }
  // SPH particles (guards excluded) and guards on this rank
  std::int64_t sph_particles() const;

  // Several ranks with zones: migrate before an output, as if the lists had not been rebuilt.
  // Public only because it holds KOKKOS_LAMBDAs, which nvcc refuses in a private member.
  void relist_for_output();

 private:
  template <int>
  friend class OutputFrame;
  template <int>
  friend class StepState;
  // before a snapshot: pressure from the EOS, Shepard factor and walls at time t, free surface;
  // with refinement zones, every guard interpolated from the stored state (5.24)
  void prepare_output();
  // after the output: puts back what prepare_output changed that the next step reads (the
  // guards' velocity, density and density gradient with refinement zones), so that an
  // output, a checkpoint or a restart does not change the run; nothing without zones
  void finish_output();

  // set-up (solver/SimulationSetup.hpp)
  void fill(std::int64_t first, std::int64_t end);
  void load_checkpoint(const CheckpointSlice& restart);
  void remove_outside_fluid();
  void check_wall_sides();
  // f(tag) for each field a checkpoint carries: the state, and with zones the APR fields
  // (level, role, mother flag and mother's id of each particle)
  template <class F>
  void for_each_checkpoint_field(F&& f) const {
    f(field::Position{});
    f(field::Velocity{});
    f(field::Density{});
    f(field::Mass{});
    f(field::GlobalId{});
    if (p_.has(field::OpenRole{})) f(field::OpenRole{});  // allocated by the open boundaries
    if (!apr_on_) return;
    f(field::AprBirthLevel{});
    f(field::AprLevel{});
    f(field::AprGuard{});
    f(field::AprMother{});
    f(field::AprParent{});
  }
  void build_fluid_region();
  // the next global id of the first hook that hands ids out (the open boundaries), -1 if none
  std::int64_t hooks_next_id() const;
  // lists (solver/SimulationLists.hpp): one path, uniform or by level
  void ensure_neighbours();
  // roles: recomputed at a bookkeeping (zones only), kept otherwise
  void rebuild_lists(bool roles, bool may_rebalance);
  void decompose(bool by_pairs);
  void refinement_step_start();
  long space_guards();  // kernels/apr/GuardSpacing.hpp: the daughter guards shifted once per step
  void refinement_bookkeeping();
  void refresh_guard_halos();       // several ranks: the interpolated fields of the guards' halo copies
  void build_level_walls();
  // evaluation (solver/SimulationEvaluate.hpp)
  void update_walls(double t);
  bool consistent_laplacian() const;
  WallEos wall_eos() const;
  // the consistent Laplacian's weights sized for n particles (grown with some slack)
  void size_laplacian_weights(int n);
  double background_pressure_min(const field_view_t<field::Pressure, D>& P, int n) const;
  // the named context of a pass over a level's SPH particles (Scheme.hpp)
  PassContext<D> pass_context(const LevelSpan<D>& level) const;
  // stepping (solver/SimulationStep.hpp)
  double time_step() const;
  void stage_update(double c_dt, double acc_weight, bool first);
  RungeKuttaViews<D> stage_views() const;
  void allocate_stage_storage();
  void check_state(double dt);

  const Scene scene_;  // as parsed: what the solver derives lives in its own members
  Domain<D> domain_;
  ParticleSet<D> p_;
  int n_own_ = 0;
  std::int64_t lattice_first_ = 0;
  double R_, skin_len_ = 0;
  double wall_spacing_ = 0;  // the wall quadrature's spacing (wall_quadrature_spacing)
  CompiledScheme<D> scheme_;  // every kernel-dependent pass, chosen once (Scheme.hpp)
  WallModel<D> walls_;
  LaplacianWeightView<D> laplacian_weights_;  // scratch of evaluate() (kernels/ConsistentLaplacian.hpp)
  FluidRegion<D> region_;
  double stage_time_ = 0;
  double t_ = 0;
  std::int64_t steps_ = 0;
  Diagnostics initial_;
  // APR: the next step start runs the bookkeeping even if the lists are valid (after a
  // checkpoint, a restart, or a list rebuild at an output)
  bool bookkeeping_due_ = false;
  // APR: the guards' fields before prepare_output's interpolation (finish_output puts them back)
  bool output_saved_ = false;
  field_view_t<field::Velocity, D> saved_u_;
  field_view_t<field::Density, D> saved_rho_;
  field_view_t<field::DensityGradient, D> saved_grad_rho_;
  AdaptiveRefinement<D> apr_;
  bool apr_on_ = false;
  std::vector<std::unique_ptr<StepHook<D>>> hooks_;  // in the order their points run
  Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace> guard_shift_;  // per particle: GuardSpacing's shift
  // APR with walls: the walls of each level l >= 1, their quadrature at the level's spacing
  // (3D; in 2D at the finest level's, as level 0's) and their points binned at R_l
  std::vector<WallModel<D>> level_walls_;
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
  explicit OutputFrame(Simulation<D>& sim) : sim_(sim) { sim_.prepare_output(); }
  ~OutputFrame() { sim_.finish_output(); }
  OutputFrame(const OutputFrame&) = delete;
  OutputFrame& operator=(const OutputFrame&) = delete;

 private:
  Simulation<D>& sim_;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace ondine
