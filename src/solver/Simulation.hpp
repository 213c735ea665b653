#pragma once
// Weakly-compressible SPH: state, neighbour structures, the derivative
// evaluation (EOS, optional density-gradient pass, flux pass) and the time
// integrators (classical RK4, explicit midpoint predictor-corrector). Templated
// on dimension only; the physics is chosen once, in FluxDispatch.
// On several MPI ranks each rank owns the particles of its ORB subdomain
// (indices 0 .. owned()-1) followed by halo copies of its neighbours'; every
// public call is collective and returns global figures.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/CellList.hpp"
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/FluxArgs.hpp"
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
#include "solver/WallModel.hpp"

namespace ondine {

// Integral quantities of the particle set (Kokkos reductions).
struct Diagnostics {
  double mass = 0;
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
};

// Thrown by step() when the state blows up; the particles hold the last good
// state (the start of the failed step) when it is caught.
struct BlowUp : std::runtime_error {
  using std::runtime_error::runtime_error;
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
  std::int64_t global_size() const { return comm_.sum(static_cast<std::int64_t>(n_own_)); }
  const Communicator& comm() const { return comm_; }
  // distributed runs: balance indicator tau (5.30) at the last list build, rebalances,
  // particles migrated, wall seconds in migration and halo exchange, halo copies here
  double balance() const { return tau_; }
  int rebalances() const { return rebalances_; }
  std::int64_t migrated() const { return exchange_.migrated(); }
  double exchange_seconds() const { return exchange_.seconds(); }
  int halo_count() const { return exchange_.halo_count(); }
  const Decomposition& decomposition() const { return decomposition_; }
  // the neighbour list is rebuilt at the next evaluation (a checkpoint does it, so
  // that a restarted run takes the same path)
  // (with refinement zones: the next step starts with a bookkeeping, as a restart's does)
  void invalidate_neighbours() {
    list_valid_ = false;
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
  std::int64_t neighbour_builds() const { return builds_; }
  // lattice quadrature factor of the Morris Laplacian (kernels/MorrisLatticeFactor.hpp); 1 without it
  double morris_factor() const { return morris_factor_; }

  Diagnostics diagnostics() const;
  const Diagnostics& initial_diagnostics() const { return initial_; }
  std::vector<ProbeSample> sample_probes() const;
  std::vector<ProbeSample> sample_at(const std::vector<Vec3>& points) const;
  // free-surface elevation at each of the scene's wave gauges (kernels/WaveGauge.hpp)
  std::vector<double> wave_elevations();
  // Error figures against the analytic solution the scene has, if any.
  std::map<std::string, double> errors() const;

  // Derivatives (du/dt, drho/dt, pressure) at the current state; public for tests.
  void evaluate();

  // NFM walls
  bool has_walls() const { return !walls_.empty(); }
  std::vector<WallForce> wall_forces();
  // impermeability corrections since t = 0 (kernels/WallImpermeability.hpp), all ranks; carried by checkpoints
  std::int64_t wall_corrections() const { return comm_.sum(wall_corrections_); }
  // particles on the solid side of a wall or closer than `clearance` (default 0.1 dx) to one
  std::int64_t wall_leaks(double clearance = -1) const;
  // free-surface flag (4.86-4.87) into field::FreeSurface, at output times
  void update_free_surface();
  // before a snapshot: pressure from the EOS, Shepard factor and walls at time t, free surface;
  // with refinement zones, every guard interpolated from the stored state (5.24)
  void prepare_output();
  // after the output: puts back what prepare_output changed that the next step reads (the
  // guards' velocity, density and density gradient with refinement zones), so that an
  // output, a checkpoint or a restart does not change the run; nothing without zones
  void finish_output();
  // x of the leading edge of the fluid (max x + dx/2), for the dam-break front
  double front_position() const;

  // adaptive particle refinement (only with refinement zones; docs/apr.md)
  bool refinement_on() const { return apr_on_; }
  const AdaptiveRefinement<D>& refinement() const { return apr_; }
  // SPH particles (guards excluded) and guards on this rank
  std::int64_t sph_particles() const;

  // Several ranks with zones: migrate before an output, as if the lists had not been rebuilt.
  // Public only because it holds KOKKOS_LAMBDAs, which nvcc refuses in a private member.
  void relist_for_output();

 private:
  void fill(std::int64_t first, std::int64_t end);
  void load_checkpoint(const CheckpointSlice& restart);
  void remove_outside_fluid();
  void update_walls(double t);
  void ensure_neighbours();
  void rebuild_neighbours(bool may_rebalance);
  void decompose(bool by_pairs);
  template <class Relist>
  void check_balance(std::int64_t pairs, bool may_rebalance, Relist&& relist);
  void refresh_halos();
  void reorder_by_cell();
  double time_step() const;
  void stage_update(double c_dt, double acc_weight, bool first);
  RungeKuttaViews<D> stage_views() const;
  void check_state(double dt);
  // APR: the per-level derivative evaluation, the bookkeeping at a step start, the lists
  void evaluate_levels();
  bool consistent_laplacian() const;
  WallEos wall_eos() const;
  FluxArgs<D> state_flux_args(int n);
  void refinement_step_start();
  long space_guards();  // kernels/apr/GuardSpacing.hpp: the daughter guards shifted once per step
  void refinement_bookkeeping();
  // roles: computed at a bookkeeping, kept otherwise; several ranks: migration, sort by
  // (level, role), halos with their levels and roles, then the lists
  void rebuild_level_lists(bool roles, bool may_rebalance);
  void refresh_guard_halos();       // several ranks: the interpolated fields of the guards' halo copies
  void allocate_stage_storage();
  void update_free_surface_levels();
  std::vector<ProbeSample> sample_levels(const std::vector<Vec3>& points) const;
  void build_level_wall_cells();
  const CellList<D>& wall_cells(int level) const { return level == 0 ? walls_.cells() : level_wall_cells_[level]; }

  Scene scene_;
  Communicator comm_;
  ParticleSet<D> p_;
  PeriodicBox<D> box_;
  double R_, cutoff_, skin_len_ = 0;
  double morris_factor_ = 1.0;  // kappa of kernels/MorrisLatticeFactor.hpp (Morris viscosity only)
  CellList<D> cells_;
  NeighbourList<D> list_;
  field_view_t<field::Position, D> x_at_build_;
  // decomposition: global grid, this rank's grid (own cells + halo ring) and the
  // box its integrator wraps positions in (periodic only along axes it spans)
  CellGrid<D> global_grid_, local_grid_;
  PeriodicBox<D> local_box_;
  Decomposition decomposition_;
  OrbLookup<D> orb_;
  ParticleExchange<D> exchange_;
  int n_own_ = 0;
  std::int64_t lattice_first_ = 0;
  bool halos_fresh_ = true;
  double tau_ = 1.0, achieved_tau_ = 2.0;
  int rebalances_ = 0;
  FluxFunction<D> flux_ = nullptr;
  WallModel<D> walls_;
  LaplacianWeightView<D> laplacian_weights_;  // scratch of evaluate() (kernels/ConsistentLaplacian.hpp)
  FluidRegion<D> region_;
  double stage_time_ = 0;
  double t_ = 0;
  std::int64_t steps_ = 0, builds_ = 0;
  std::int64_t wall_corrections_ = 0;  // this rank's impermeability corrections (kernels/WallImpermeability.hpp)
  bool list_valid_ = false;
  // APR: the next step start runs the bookkeeping even if the lists are valid (after a
  // checkpoint, a restart, or a list rebuild at an output)
  bool bookkeeping_due_ = false;
  // APR: the guards' fields before prepare_output's interpolation (finish_output puts them back)
  bool output_saved_ = false;
  field_view_t<field::Velocity, D> saved_u_;
  field_view_t<field::Density, D> saved_rho_;
  field_view_t<field::DensityGradient, D> saved_grad_rho_;
  Diagnostics initial_;
  AdaptiveRefinement<D> apr_;
  bool apr_on_ = false;
  Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace> guard_shift_;  // per particle: GuardSpacing's shift
  std::vector<CellList<D>> level_wall_cells_;  // APR with walls: wall points binned at each level's radius
};

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace ondine
