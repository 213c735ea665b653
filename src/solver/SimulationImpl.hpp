#pragma once
// Definitions of Simulation<D>; included by Simulation2d.cpp and Simulation3d.cpp only.
#include <climits>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "kernels/DensityGradientPass.hpp"
#include "kernels/RenormalisedContinuity.hpp"
#include "kernels/MorrisLatticeFactor.hpp"
#include "kernels/WallImpermeability.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "kernels/EquationOfState.hpp"
#include "kernels/FreeSurfacePass.hpp"
#include "kernels/WallFluxPass.hpp"
#include "kernels/WallForces.hpp"
#include "kernels/InitialFill.hpp"
#include "kernels/StateHash.hpp"
#include "kernels/Integrator.hpp"
#include "kernels/Permute.hpp"
#include "kernels/ShiftingPass.hpp"
#include "kernels/StateCheck.hpp"
#include "kernels/ProbeSum.hpp"
#include "kernels/TimeStep.hpp"
#include "kernels/WaveGauge.hpp"
#include "scene/CaseFile.hpp"
#include "solver/FluxSelect.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/References.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

namespace detail {


template <int D, class F>
void with_eos(const Scene& s, F&& f) {
  if (s.eos == EosLaw::Tait) f(TaitEos{s.rho0, s.c0, s.tait_gamma, s.eos_background_pressure});
  else f(LinearEos{s.rho0, s.c0, s.eos_background_pressure});
}

}  // namespace detail

template <int D>
Simulation<D>::Simulation(const Scene& scene, const CheckpointSlice* restart) : scene_(scene) {
  if (scene.dimension != D) throw std::logic_error("Simulation<D>: scene dimension mismatch");
  R_ = scene.R();
  if (scene.viscous_term == ViscousTerm::Morris)
    morris_factor_ = with_kernel<D>(scene.kernel, R_, [&](auto W) { return morris_lattice_factor<D>(W, R_, scene.dx); });
  // with refinement zones the skin and the wall quadrature follow the finest spacing
  apr_on_ = !scene.refinement_zones.empty();
  const double dx_finest = scene.dx / std::ldexp(1.0, scene.max_refinement_level());
  skin_len_ = scene.neighbour_skin * (apr_on_ ? dx_finest : scene.dx);
  cutoff_ = R_ + skin_len_;
  if (apr_on_) {
    if (restart && !restart->header.refinement.present)
      throw std::logic_error("Simulation<D>: a checkpoint without the APR state for a scene with refinement zones");
    if (scene_.wall_quadrature_spacing == 0) scene_.wall_quadrature_spacing = dx_finest / 4;
  }
  for (int k = 0; k < D; ++k) {
    box_.lo[k] = scene.domain.min[k];
    box_.len[k] = scene.domain.max[k] - scene.domain.min[k];
    box_.periodic[k] = scene.periodic[k];
    if (box_.periodic[k] && box_.len[k] < 2.0 * cutoff_)
      throw std::invalid_argument("a periodic axis must be at least 2 (R + skin) long");
  }
  global_grid_ = make_cell_grid(box_, cutoff_);
  local_grid_ = global_grid_;
  local_box_ = box_;
  // this rank's share of the lattice or of the checkpoint; migrate() then sends
  // every particle to the owner of its cell
  const std::int64_t lattice = count_particles(scene);
  lattice_first_ = lattice * comm_.rank() / comm_.size();
  const std::int64_t lattice_end = lattice * (comm_.rank() + 1) / comm_.size();
  p_ = ParticleSet<D>(restart ? static_cast<std::size_t>(restart->rows) : static_cast<std::size_t>(lattice_end - lattice_first_));
  p_.allocate(field::Position{});
  p_.allocate(field::Velocity{});
  p_.allocate(field::Density{});
  p_.allocate(field::Pressure{});
  p_.allocate(field::Mass{});
  p_.allocate(field::GlobalId{});
  p_.allocate(field::Acceleration{});
  p_.allocate(field::DensityRate{});
  const bool walls = !scene.walls.empty();
  // the density gradient feeds delta-SPH and the MUSCL wall state (4.30)
  if (scene.delta_sph > 0 || walls) p_.allocate(field::DensityGradient{});
  if (walls) p_.allocate(field::ShepardGamma{});
  bool free_surface_possible = false;
  for (int k = 0; k < D; ++k) free_surface_possible = free_surface_possible || !scene.periodic[k];
  if (free_surface_possible) p_.allocate(field::FreeSurface{});
  flux_ = with_kernel<D>(scene.kernel, R_, [&](auto W) { return select_flux<D, decltype(W)>(scene); });
  if (walls) {
    walls_ = WallModel<D>(scene_, box_, R_);
    region_.seg = walls_.segments();
    region_.behind = scene.dx;
    // closed walls as segment ranges (host loop over walls)
    std::vector<int> first, count, inside;
    int s0 = 0;
    for (const Wall& w : scene.walls) {
      const int ns = static_cast<int>(w.closed ? w.points.size() : w.points.size() - 1);
      if (w.closed) {
        first.push_back(s0);
        count.push_back(ns);
        inside.push_back(w.fluid_inside ? 1 : 0);
      }
      s0 += ns;
    }
    auto dev = [](const std::vector<int>& v, const std::string& label) {
      Kokkos::View<int*, MemSpace> d(label, v.size());
      Kokkos::deep_copy(d, Kokkos::View<const int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(v.data(), v.size()));
      return d;
    };
    region_.closed.first = dev(first, "ondine::NFM::closed_first");
    region_.closed.count = dev(count, "ondine::NFM::closed_count");
    region_.closed.fluid_inside = dev(inside, "ondine::NFM::closed_inside");
    region_.closed.walls = static_cast<int>(first.size());
  }
  if (restart) {
    load_checkpoint(*restart);
  } else {
    fill(lattice_first_, lattice_end);
    if (walls) remove_outside_fluid();
  }
  n_own_ = static_cast<int>(p_.size());
  if (!comm_.serial()) {
    // first decomposition: weighted by the particles in each cell
    decompose(false);
    n_own_ = exchange_.migrate(p_, n_own_, orb_, box_, comm_);
  }
  if (apr_on_ && restart) {
    // the APR fields came with the checkpoint (load_checkpoint); the zones, counters and
    // level ranges as saved (on several ranks after the first migration: each rank sorts
    // the particles it owns by their stored level and role). The first step starts with
    // the bookkeeping that the saved run would have done after writing the checkpoint.
    apr_ = AdaptiveRefinement<D>(scene_, box_, skin_len_);
    apr_.restore(p_, n_own_, restart->header.refinement);
    apr_.count_guard_shifts(comm_.rank() == 0 ? restart->header.refinement.guard_shifts : 0);
    list_valid_ = false;
    bookkeeping_due_ = true;
  } else if (apr_on_) {
    // every particle starts as a coarse SPH particle; one bookkeeping pass per
    // level creates the daughters of each nested level in turn (on several ranks,
    // after the first decomposition: each rank refines the particles it owns)
    apr_ = AdaptiveRefinement<D>(scene_, box_, skin_len_);
    apr_.initialise(p_, comm_.sum(static_cast<std::int64_t>(n_own_)));
    for (int l = 1; l < apr_.levels(); ++l) refinement_bookkeeping();
  }
  detail::with_eos<D>(scene_, [&](auto eos) {
    update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), n_own_);
  });
  initial_ = diagnostics();
  if (restart) {
    t_ = restart->header.time;
    steps_ = restart->header.step;
    stage_time_ = t_;
    initial_.mass = restart->header.initial_mass;
    for (int k = 0; k < 3; ++k) initial_.momentum[k] = restart->header.initial_momentum[k];
    wall_corrections_ = comm_.rank() == 0 ? restart->header.wall_corrections : 0;  // a global count, carried by rank 0
    if (walls_.moving()) update_walls(t_);
  }
}

// Lattice fill of each block at (k + 1/2) dx, with its initial velocity and pressure.
template <int D>
void Simulation<D>::fill(std::int64_t first, std::int64_t end) {
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto m = p_.get(field::Mass{});
  const auto id = p_.get(field::GlobalId{});
  const Scene s = scene_;
  const double dx = s.dx;
  const double volume = std::pow(dx, D);
  double g[D];
  for (int k = 0; k < D; ++k) g[k] = s.gravity[k] + s.body_force[k];
  std::int64_t offset = 0;
  for (const FluidBlock& b : s.blocks) {
    int cnt[D];
    double lo[D], top = 0;
    std::int64_t nb = 1;
    for (int k = 0; k < D; ++k) {
      cnt[k] = static_cast<int>(std::llround((b.box.max[k] - b.box.min[k]) / dx));
      lo[k] = b.box.min[k];
      nb *= cnt[k];
    }
    // hydrostatic column: the free surface is the block face facing against gravity
    for (int k = 0; k < D; ++k) top += (g[k] > 0 ? b.box.min[k] : b.box.max[k]) * (-g[k]);
    // the part of this block's lattice [offset, offset + nb) in this rank's share [first, end)
    const std::int64_t a = std::max(first, offset), e = std::min(end, offset + nb);
    if (e <= a) {
      offset += nb;
      continue;
    }
    InitialFill<D> f;
    f.x = x;
    f.u = u;
    f.rho = rho;
    f.m = m;
    f.id = id;
    f.offset = offset;
    f.first = a - offset;
    f.dst = a - first;
    for (int k = 0; k < D; ++k) {
      f.cnt[k] = cnt[k];
      f.lo[k] = lo[k];
      f.g[k] = g[k];
      f.velocity[k] = b.velocity[k];
    }
    f.dx = dx;
    f.volume = volume;
    f.top = top;
    f.velocity_kind = b.velocity_kind;
    f.pressure_kind = b.pressure_kind;
    f.tg_amplitude = b.tg_amplitude;
    f.k_tg = b.tg_wavelength > 0 ? 2.0 * M_PI / b.tg_wavelength : 0.0;
    f.tait = s.eos == EosLaw::Tait;
    f.rho0 = s.rho0;
    f.c0 = s.c0;
    f.gam = s.tait_gamma;
    f.run(e - a);
    offset += nb;
  }
}

// Drops lattice points outside the fluid region or closer to a wall than their
// block's wall_clearance (dx/2 by default), keeping the order, and renumbers the global ids.
template <int D>
void Simulation<D>::remove_outside_fluid() {
  const int n = static_cast<int>(p_.size());
  Kokkos::View<int*, MemSpace> keep("ondine::Fill::keep", n), index("ondine::Fill::index", n);
  const int nb = static_cast<int>(scene_.blocks.size());
  Kokkos::View<std::int64_t*, MemSpace> block_end("ondine::Fill::block_end", nb);
  Kokkos::View<double*, MemSpace> block_clearance("ondine::Fill::block_clearance", nb);
  {
    auto he = Kokkos::create_mirror_view(block_end);
    auto hc = Kokkos::create_mirror_view(block_clearance);
    std::int64_t end = 0;
    for (int b = 0; b < nb; ++b) {
      const FluidBlock& blk = scene_.blocks[b];
      std::int64_t cnt = 1;
      for (int k = 0; k < D; ++k) cnt *= std::llround((blk.box.max[k] - blk.box.min[k]) / scene_.dx);
      he(b) = end += cnt;  // the lattice order of fill()
      hc(b) = blk.wall_clearance * scene_.dx * (1 - 1e-9);  // a point exactly at the clearance is kept
    }
    Kokkos::deep_copy(block_end, he);
    Kokkos::deep_copy(block_clearance, hc);
  }
  Kokkos::parallel_for("ondine::Fill::fluid_region", Kokkos::RangePolicy<ExecSpace>(0, n),
                       FluidRegionFilter<D>{region_, block_end, block_clearance, p_.get(field::Position{}),
                                            p_.get(field::GlobalId{}), keep});
  int kept = 0;
  Kokkos::parallel_scan("ondine::Fill::scan", Kokkos::RangePolicy<ExecSpace>(0, n), KeepScan{keep, index}, kept);
  if (comm_.sum(static_cast<std::int64_t>(kept)) == 0)
    throw std::invalid_argument(scene_.source_file + ": no fluid particle lies inside the walls (check fluid_blocks and walls[].fluid_side)");
  Kokkos::View<int*, MemSpace> order("ondine::Fill::order", kept);
  Kokkos::parallel_for("ondine::Fill::gather", Kokkos::RangePolicy<ExecSpace>(0, n), KeepGather{keep, index, order});
  p_.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept));
  Kokkos::parallel_for("ondine::Fill::renumber", Kokkos::RangePolicy<ExecSpace>(0, kept),
                       Iota{p_.get(field::GlobalId{}), comm_.exclusive_scan(kept)});
}

// This rank's share of a checkpoint into the state fields.
template <int D>
void Simulation<D>::load_checkpoint(const CheckpointSlice& c) {
  auto put = [&](auto tag) {
    using V = field_view_t<decltype(tag), D>;
    const std::vector<double>& rows = c.fields.at(decltype(tag)::label);
    const int w = exchange::width_of<V>();
    exchange::Rows dev("ondine::Restart::rows", c.rows, w);
    Kokkos::deep_copy(dev, Kokkos::View<const double**, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(
                               rows.data(), c.rows, w));
    Kokkos::parallel_for("ondine::Restart::unpack", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(c.rows)),
                         exchange::UnpackRows<V>{p_.allocate(tag), dev, 0, 0});
  };
  put(field::Position{});
  put(field::Velocity{});
  put(field::Density{});
  put(field::Mass{});
  put(field::GlobalId{});
  if (apr_on_) {
    // level, role, mother flag and mother's id of each particle, as the run saved them
    put(field::AprBirthLevel{});
    put(field::AprLevel{});
    put(field::AprGuard{});
    put(field::AprMother{});
    put(field::AprParent{});
  }
}

template <int D>
std::map<std::string, std::pair<std::vector<double>, int>> Simulation<D>::state_rows() const {
  std::map<std::string, std::pair<std::vector<double>, int>> out;
  Kokkos::View<int*, MemSpace> index("ondine::Checkpoint::index", n_own_);
  Kokkos::parallel_for("ondine::Checkpoint::index", Kokkos::RangePolicy<ExecSpace>(0, n_own_), Iota32{index});
  auto take = [&](auto tag) {
    using V = field_view_t<decltype(tag), D>;
    const int w = exchange::width_of<V>();
    exchange::Rows dev("ondine::Checkpoint::rows", n_own_, w);
    exchange::PackRows<V, D> f{p_.get(tag), index, Kokkos::View<int*, MemSpace>(), dev, 0, {}};
    Kokkos::parallel_for("ondine::Checkpoint::pack", Kokkos::RangePolicy<ExecSpace>(0, n_own_), f);
    std::vector<double> rows(static_cast<std::size_t>(n_own_) * w);
    Kokkos::deep_copy(Kokkos::View<double**, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(rows.data(), n_own_, w), dev);
    out[decltype(tag)::label] = {std::move(rows), w};
  };
  take(field::Position{});
  take(field::Velocity{});
  take(field::Density{});
  take(field::Mass{});
  take(field::GlobalId{});
  if (apr_on_) {
    take(field::AprBirthLevel{});
    take(field::AprLevel{});
    take(field::AprGuard{});
    take(field::AprMother{});
    take(field::AprParent{});
  }
  return out;
}

template <int D>
CheckpointRefinement Simulation<D>::refinement_state() const {
  CheckpointRefinement c;
  if (!apr_on_) return c;
  apr_.save_state(c);
  c.guard_shifts = comm_.sum(apr_.guard_shifts());  // a global count (each rank counts its own)
  c.checksum = refinement_checksum();
  return c;
}

template <int D>
std::uint64_t Simulation<D>::refinement_checksum() const {
  if (!apr_on_) return 0;
  unsigned long long h = 0;
  Kokkos::parallel_reduce("ondine::AprStateHash", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          AprStateHash<D>{p_.get(field::GlobalId{}), p_.get(field::AprBirthLevel{}), p_.get(field::AprLevel{}),
                                          p_.get(field::AprGuard{}), p_.get(field::AprMother{}), p_.get(field::AprParent{})},
                          h);
  return comm_.sum_u64(static_cast<std::uint64_t>(h));
}

template <int D>
std::uint64_t Simulation<D>::state_checksum() const {
  unsigned long long h = 0;
  Kokkos::parallel_reduce("ondine::StateHash", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          StateHash<D>{p_.get(field::Position{}), p_.get(field::Velocity{}), p_.get(field::Density{}),
                                       p_.get(field::Mass{}), p_.get(field::GlobalId{})},
                          h);
  return comm_.sum_u64(static_cast<std::uint64_t>(h));
}

template <int D>
void Simulation<D>::update_walls(double t) {
  if (walls_.moving()) walls_.move_to(t);
  region_.seg = walls_.segments();
}

template <int D>
std::int64_t Simulation<D>::pair_count() const {
  // pairs within R, both ways, from the current list (skin pairs excluded)
  const auto x = p_.get(field::Position{});
  const auto list = list_;
  const auto box = box_;
  const double R2 = R_ * R_;
  std::int64_t total = 0;
  if (!list_valid_) return 0;
  if (apr_on_) return comm_.sum(static_cast<std::int64_t>(apr_.symmetric_list().total()));  // L. pairs within R + skin
  Kokkos::parallel_reduce("ondine::PairCount", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          KOKKOS_LAMBDA(const int i, std::int64_t& acc) {
                            const Vec<D> xi = load<D>(x, i);
                            for (int n = 0; n < list.num_neighbours(i); ++n)
                              if (norm2(box.delta(xi, load<D>(x, list.neighbour(i, n)))) < R2) ++acc;
                          },
                          total);
  return comm_.sum(total);
}

template <int D>
void Simulation<D>::ensure_neighbours() {
  const auto x = p_.get(field::Position{});
  if (list_valid_ && scene_.neighbour_skin > 0) {
    // Verlet criterion: rebuild once some particle (on any rank) moved more than skin/2.
    double d2max = 0;
    Kokkos::parallel_reduce("ondine::NeighbourList::displacement", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                            MaxDisplacement2<D>{box_, x, x_at_build_}, Kokkos::Max<double>(d2max));
    const double half_skin = 0.5 * skin_len_;
    if (comm_.max(d2max) < half_skin * half_skin) return;
  }
  rebuild_neighbours(true);
}

// Migration and halos (several ranks), cell list over owned + halo particles,
// list for the owned ones; then the balance check, which may rebalance once.
template <int D>
void Simulation<D>::rebuild_neighbours(bool may_rebalance) {
  if (apr_on_) {
    rebuild_level_lists(false, may_rebalance);  // in the middle of a step: roles are kept ...
    // ... and updated at the next step start. Without this, the step start measured the Verlet
    // displacement from this build and skipped the bookkeeping: in a fast flow the lists were
    // rebuilt at the stages, and the roles (and the passive guards' velocities) lagged for
    // tens of steps (dam break run-up: mother guards 2 dx_m above their zone; docs/apr.md, session 7)
    bookkeeping_due_ = true;
    return;
  }
  if (!comm_.serial()) {
    n_own_ = exchange_.migrate(p_, n_own_, orb_, box_, comm_);
    exchange_.build_halos(p_, n_own_, orb_, box_, comm_);
    halos_fresh_ = true;
  }
  const auto x = p_.get(field::Position{});
  cells_.build(local_grid_, x, static_cast<int>(p_.size()));
  list_.build(cells_, box_, x, n_own_, cutoff_);
  if (scene_.neighbour_skin > 0) {
    if (x_at_build_.extent(0) != x.extent(0))
      x_at_build_ = field_view_t<field::Position, D>("ondine::NeighbourList::x_at_build", x.extent(0));
    Kokkos::deep_copy(x_at_build_, x);
  }
  list_valid_ = true;
  ++builds_;
  if (!comm_.serial()) check_balance(static_cast<std::int64_t>(list_.total()), may_rebalance, [this] { rebuild_neighbours(false); });
}

// tau = min work / max work over the ranks (thesis 5.30), work = this rank's pair
// interactions (`pairs`) or particles. Below the threshold the domain is bisected again
// and `relist` rebuilds the lists; when cell-wide cuts cannot reach the threshold, only
// once the balance is clearly worse (0.05) than the last rebalance achieved.
template <int D>
template <class Relist>
void Simulation<D>::check_balance(std::int64_t pairs, bool may_rebalance, Relist&& relist) {
  std::vector<double> work;
  const std::int64_t mine = scene_.balance_by_pairs ? pairs : n_own_;
  for (std::int64_t w : comm_.gather_all(mine)) work.push_back(static_cast<double>(w));
  tau_ = balance_indicator(work);
  if (may_rebalance && tau_ < std::min(scene_.rebalance_threshold, achieved_tau_ - 0.05)) {
    const double before = tau_;
    decompose(scene_.balance_by_pairs);
    ++rebalances_;
    relist();
    achieved_tau_ = tau_;
    if (comm_.rank() == 0)
      std::fprintf(stderr, "ondine: step %lld: rebalanced, tau %.3f -> %.3f\n", static_cast<long long>(steps_), before, tau_);
  }
}

// ORB of the global cell grid (src/parallel/Decomposition.hpp), weighted by the
// pair interactions of each cell (from the current list) or, before the first
// list, by its particle count.
template <int D>
void Simulation<D>::decompose(bool by_pairs) {
  const int ncell = global_grid_.cells();
  Kokkos::View<double*, MemSpace> work("ondine::Decomposition::work", ncell);
  Kokkos::parallel_for("ondine::Decomposition::work", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                       CellWork<D>{global_grid_, box_, apr_on_ ? apr_.symmetric_list() : list_, p_.get(field::Position{}), work,
                                   by_pairs && list_valid_});
  // with refinement zones a guard's work is its interpolation sources (its Lx row)
  if (apr_on_ && by_pairs && list_valid_)
    Kokkos::parallel_for("ondine::Decomposition::guard_work", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                         CellWork<D>{global_grid_, box_, apr_.guard_list(), p_.get(field::Position{}), work, true});
  std::vector<double> host(ncell);
  Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(host.data(), ncell), work);
  comm_.sum_in_place(host);
  bool periodic[D];
  for (int k = 0; k < D; ++k) periodic[k] = box_.periodic[k];
  decomposition_ = Decomposition::bisect(D, global_grid_.n, periodic, host, comm_.size());
  orb_ = make_orb_lookup<D>(decomposition_, global_grid_);
  const CellBox& mine = decomposition_.box(comm_.rank());
  local_grid_ = local_cell_grid<D>(global_grid_, mine);
  local_box_ = box_;
  for (int k = 0; k < D; ++k) local_box_.periodic[k] = box_.periodic[k] && decomposition_.spans(comm_.rank(), k);
  list_valid_ = false;
}

template <int D>
void Simulation<D>::refresh_halos() {
  if (comm_.serial() || halos_fresh_) return;
  exchange_.refresh(p_, comm_, field::Position{}, field::Velocity{}, field::Density{});
  halos_fresh_ = true;
}

// Owned particles sorted by cell for memory locality; halos are dropped (the
// next list build brings them back).
template <int D>
void Simulation<D>::reorder_by_cell() {
  cells_.build(local_grid_, p_.get(field::Position{}), n_own_);
  const auto perm = Kokkos::subview(cells_.sorted, std::make_pair(0, n_own_));
  Kokkos::View<int*, MemSpace> order("ondine::Reorder::order", n_own_);
  Kokkos::deep_copy(order, perm);
  p_.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(n_own_));
  list_valid_ = false;
}

// Viscous flows along no-slip walls take the consistent Laplacian (kernels/ConsistentLaplacian.hpp).
template <int D>
bool Simulation<D>::consistent_laplacian() const {
  return !walls_.empty() && uses_consistent_laplacian(scene_);
}

// The equation of state of the NFM wall pressure (4.14), for the wall flux and the wall
// forces alike.
template <int D>
WallEos Simulation<D>::wall_eos() const {
  const double eos_gamma = scene_.eos == EosLaw::Tait ? scene_.tait_gamma : 1.0;
  return WallEos{scene_.rho0, scene_.c0, eos_gamma};
}

// What every flux evaluation reads, uniform (evaluate) or per level (evaluate_levels): the
// box, body force, state views and viscosity; with the consistent Laplacian, its weight
// array sized for n particles (grown with some slack).
template <int D>
FluxArgs<D> Simulation<D>::state_flux_args(int n) {
  FluxArgs<D> a;
  a.box = box_;
  for (int k = 0; k < D; ++k) a.body[k] = scene_.gravity[k] + scene_.body_force[k];
  a.x = p_.get(field::Position{});
  a.u = p_.get(field::Velocity{});
  a.rho = p_.get(field::Density{});
  a.P = p_.get(field::Pressure{});
  a.m = p_.get(field::Mass{});
  a.du = p_.get(field::Acceleration{});
  a.drho = p_.get(field::DensityRate{});
  // the lattice factor scales the plain Morris term; the consistent one has its own weights
  a.nu = scene_.viscous_term == ViscousTerm::Morris && !uses_consistent_laplacian(scene_) ? scene_.nu * morris_factor_ : scene_.nu;
  if (consistent_laplacian()) {
    if (static_cast<int>(laplacian_weights_.extent(0)) < n)
      laplacian_weights_ = LaplacianWeightView<D>("ondine::NFM::laplacian_weights", n + n / 8 + 16);
    a.laplacian_weights = laplacian_weights_;
  }
  return a;
}

template <int D>
void Simulation<D>::evaluate() {
  if (apr_on_) {
    evaluate_levels();
    return;
  }
  ensure_neighbours();
  refresh_halos();
  const int n = n_own_, n_all = static_cast<int>(p_.size());
  FluxArgs<D> a = state_flux_args(n);
  a.n = n;
  a.list = list_;
  a.R = R_;
  a.delta_coeff = scene_.delta_sph * scene_.c0 * R_;
  a.av_alpha_R_c0 = scene_.artificial_viscosity * R_ * scene_.c0;
  detail::with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, a.rho, a.P, n_all); });
  if (scene_.background_pressure) {
    // (2.105): P_min = max(0, -min_k P_k)
    double pmin = 0;
    const auto P = a.P;
    Kokkos::parallel_reduce("ondine::BackgroundPressure::min", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& mn) { if (P(i) < mn) mn = P(i); },
                            Kokkos::Min<double>(pmin));
    pmin = comm_.min(pmin);
    a.P_min = pmin < 0 ? -pmin : 0.0;
  }
  const bool walls = !walls_.empty();
  if (walls) {
    update_walls(stage_time_);
    ShepardGammaPass<D>{walls_.segments(), R_, box_, a.x, p_.get(field::ShepardGamma{})}.run(n_all);
  }
  // viscous flows along no-slip walls: the consistent Laplacian (kernels/ConsistentLaplacian.hpp)
  const bool morris_walls = consistent_laplacian();
  if (scene_.delta_sph > 0 || walls) {
    a.grad_rho = p_.get(field::DensityGradient{});
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      using K = decltype(W);
      if (morris_walls)
        DensityGradientPass<D, K, true>{list_, box_, W, R_ * R_, a.x, a.rho, a.m, a.grad_rho,
                                        {walls_.points(), walls_.cells(), 0.05 * R_, morris_factor_,
                                         p_.get(field::ShepardGamma{}), laplacian_weights_}}
            .run(n);
      else
        DensityGradientPass<D, K>{list_, box_, W, R_ * R_, a.x, a.rho, a.m, a.grad_rho}.run(n);
    });
    if (!comm_.serial()) exchange_.refresh(p_, comm_, field::DensityGradient{});
  }
  flux_(a);
  if (walls) {
    const WallEos eos = wall_eos();
    const auto gamma = p_.get(field::ShepardGamma{});
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      using K = decltype(W);
      const auto run = [&](auto pass) {
        pass.wall = walls_.points();
        pass.wall_cells = walls_.cells();
        pass.W = W;
        pass.R2 = R_ * R_;
        pass.body = a.body;
        pass.nu = scene_.nu;
        pass.eos = eos;
        pass.min_dn = 0.05 * R_;
        pass.box = box_;
        pass.P_min = a.P_min;
        pass.x = a.x;
        pass.u = a.u;
        pass.rho = a.rho;
        pass.P = a.P;
        pass.grad_rho = a.grad_rho;
        pass.gamma = gamma;
        pass.du = a.du;
        pass.drho = a.drho;
        pass.weights = laplacian_weights_;
        pass.list = a.list;
        pass.m = a.m;
        pass.clearance = 0.5 * scene_.dx;
        pass.velocity_muscl = scene_.wall_velocity_reconstruction;
        pass.run(n);
      };
      if (morris_walls)
        run(WallFluxPass<D, K, true, true>{});
      else if (scene_.viscous_term != ViscousTerm::None)
        run(WallFluxPass<D, K, true, false>{});
      else
        run(WallFluxPass<D, K, false, false>{});
    });
  }
  if (scene_.renormalised_continuity) {
    // replaces the plain divergence of (4.23)/(4.25) by the renormalised one (kernels/RenormalisedContinuity.hpp)
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      using K = decltype(W);
      if (walls)
        RenormalisedContinuity<D, K, true>{list_, box_, W, R_ * R_, walls_.points(), walls_.cells(), a.x, a.u, a.rho, a.m,
                                           p_.get(field::ShepardGamma{}), a.drho}
            .run(n);
      else
        RenormalisedContinuity<D, K, false>{list_, box_, W, R_ * R_, {}, {}, a.x, a.u, a.rho, a.m, {}, a.drho}.run(n);
    });
  }
}

// dt = min(CFL_a R / c_max (2.102), CFL_nu R^2 / nu (2.103), CFL_f sqrt(R / |a|_max) [V&I 11]).
template <int D>
double Simulation<D>::time_step() const {
  const int n = n_own_;
  const auto rho = p_.get(field::Density{});
  const auto du = p_.get(field::Acceleration{});
  double cmax = 0, a2max = 0;
  detail::with_eos<D>(scene_, [&](auto eos) {
    Kokkos::parallel_reduce("ondine::TimeStep::sound_speed", Kokkos::RangePolicy<ExecSpace>(0, n),
                            MaxSoundSpeed<D, decltype(eos)>{eos, rho}, Kokkos::Max<double>(cmax));
  });
  Kokkos::parallel_reduce("ondine::TimeStep::acceleration", Kokkos::RangePolicy<ExecSpace>(0, n),
                          MaxNorm2<D, std::decay_t<decltype(du)>>{du}, Kokkos::Max<double>(a2max));
  cmax = comm_.max(cmax);
  a2max = comm_.max(a2max);
  // one global step, bounded by the finest level that has SPH particles (with refinement zones)
  double R = R_;
  if (apr_on_) {
    std::int64_t finest = 0;  // on any rank
    for (int l = 0; l < apr_.levels(); ++l)
      if (apr_.active_end(l) > apr_.first(l)) finest = l;
    R = apr_.R(static_cast<int>(comm_.max(finest)));
  }
  double dt = scene_.cfl_acoustic * R / cmax;
  if (scene_.nu > 0) dt = std::min(dt, scene_.cfl_viscous * R * R / scene_.nu);
  if (a2max > 0) dt = std::min(dt, scene_.cfl_force * std::sqrt(R / std::sqrt(a2max)));
  if (!walls_.empty() && scene_.viscous_term != ViscousTerm::None && apr_on_) {
    for (int l = 0; l < apr_.levels(); ++l) {
      double kmax = 0;  // 0 on a rank without SPH particles of level l (it takes part in the all-reduce)
      const double Rl = apr_.R(l);
      with_kernel<D>(scene_.kernel, Rl, [&](auto W) {
        Kokkos::parallel_reduce("ondine::TimeStep::wall_viscous", Kokkos::RangePolicy<ExecSpace>(apr_.first(l), apr_.active_end(l)),
                                WallViscousStiffness<D, decltype(W)>{walls_.points(), wall_cells(l), W, Rl * Rl, scene_.nu,
                                                                     0.05 * Rl, box_, p_.get(field::Position{}),
                                                                     p_.get(field::ShepardGamma{})},
                                Kokkos::Max<double>(kmax));
      });
      kmax = comm_.max(kmax);
      if (kmax > 0) dt = std::min(dt, 1.0 / kmax);
    }
  } else if (!walls_.empty() && scene_.viscous_term != ViscousTerm::None) {
    double kmax = 0;
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      Kokkos::parallel_reduce("ondine::TimeStep::wall_viscous", Kokkos::RangePolicy<ExecSpace>(0, n),
                              WallViscousStiffness<D, decltype(W)>{walls_.points(), walls_.cells(), W, R_ * R_, scene_.nu,
                                                                   0.05 * R_, box_, p_.get(field::Position{}),
                                                                   p_.get(field::ShepardGamma{})},
                              Kokkos::Max<double>(kmax));
    });
    kmax = comm_.max(kmax);
    if (kmax > 0) dt = std::min(dt, 1.0 / kmax);
  }
  if (!std::isfinite(dt) || dt <= 0) throw std::runtime_error("time step is not finite (the state contains NaN)");
  return dt;
}

// The state, its derivatives and the integrator's stage storage (RK4 sums only with RK4).
template <int D>
RungeKuttaViews<D> Simulation<D>::stage_views() const {
  const bool rk4 = scene_.integrator == TimeIntegrator::RK4;
  return {p_.get(field::Position{}),
          p_.get(field::Velocity{}),
          p_.get(field::Density{}),
          p_.get(field::Acceleration{}),
          p_.get(field::DensityRate{}),
          p_.get(field::StagePosition{}),
          rk4 ? p_.get(field::StagePositionSum{}) : field_view_t<field::Position, D>(),
          p_.get(field::StageVelocity{}),
          rk4 ? p_.get(field::StageVelocitySum{}) : field_view_t<field::Velocity, D>(),
          p_.get(field::StageDensity{}),
          rk4 ? p_.get(field::StageDensitySum{}) : field_view_t<field::Density, D>()};
}

// One stage of an explicit Runge-Kutta step: y = y0 + c_dt k with k the current
// derivatives, and the weighted sum acc += w k used by the final RK4 update.
template <int D>
void Simulation<D>::stage_update(double c_dt, double w, bool first) {
  RungeKuttaStage<D>{local_box_, stage_views(), c_dt, w, w != 0.0, first}.run(n_own_);
  halos_fresh_ = false;
}

template <int D>
void Simulation<D>::allocate_stage_storage() {
  if (p_.has(field::StagePosition{})) return;
  p_.allocate(field::StagePosition{});
  p_.allocate(field::StageVelocity{});
  p_.allocate(field::StageDensity{});
  if (scene_.integrator == TimeIntegrator::RK4) {
    p_.allocate(field::StagePositionSum{});
    p_.allocate(field::StageVelocitySum{});
    p_.allocate(field::StageDensitySum{});
  }
}

template <int D>
double Simulation<D>::step(double t_stop) {
  output_saved_ = false;  // finish_output() after a step has nothing to put back
  if (scene_.reorder_interval > 0 && steps_ % scene_.reorder_interval == 0) reorder_by_cell();
  if (apr_on_) refinement_step_start();
  allocate_stage_storage();
  Kokkos::deep_copy(p_.get(field::StagePosition{}), p_.get(field::Position{}));
  Kokkos::deep_copy(p_.get(field::StageVelocity{}), p_.get(field::Velocity{}));
  Kokkos::deep_copy(p_.get(field::StageDensity{}), p_.get(field::Density{}));

  stage_time_ = t_;
  evaluate();  // k1 at y0, also the state the time step is computed from
  double dt = time_step();
  if (t_ + dt > t_stop) dt = std::max(t_stop - t_, 1e-300);
  else if (t_ + 1.5 * dt > t_stop) dt = 0.5 * (t_stop - t_);  // avoid a sliver step before t_stop

  if (scene_.integrator == TimeIntegrator::RK4) {
    // classical RK4: y1 = y0 + dt/6 (k1 + 2 k2 + 2 k3 + k4)
    stage_update(0.5 * dt, 1.0 / 6.0, true);
    stage_time_ = t_ + 0.5 * dt;
    evaluate();
    stage_update(0.5 * dt, 2.0 / 6.0, false);
    evaluate();
    stage_update(dt, 2.0 / 6.0, false);
    stage_time_ = t_ + dt;
    evaluate();
    // final: y = y0 + dt (acc + k4/6)
    RungeKutta4Final<D>{local_box_, stage_views(), dt}.run(n_own_);
    halos_fresh_ = false;
  } else {
    // explicit midpoint: y_1/2 = y0 + dt/2 k1, y1 = y0 + dt k(y_1/2)
    stage_update(0.5 * dt, 0.0, true);
    stage_time_ = t_ + 0.5 * dt;
    evaluate();
    stage_update(dt, 0.0, false);
  }
  if (scene_.shifting) {
    // (2.107)-(2.111) once per step, into the stage storage, then copied back
    ensure_neighbours();
    refresh_halos();
    const int n = n_own_;
    const auto x0_ = p_.get(field::StagePosition{});
    const auto u0_ = p_.get(field::StageVelocity{});
    const auto rho0_ = p_.get(field::StageDensity{});
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      const double max_shift = 0.02 * scene_.dx;  // per step (kernels/ShiftingPass.hpp)
      // local_box_: it wraps the shifted positions as the integrator does (shifting
      // with walls, whose periodic images need box_, is refused by the case file)
      if (walls_.empty())
        ShiftingPass<D, decltype(W), false>{list_, local_box_, W, R_ * R_, 0.5 * R_ * R_, W.value(scene_.dx), max_shift,
                                            p_.get(field::Position{}), p_.get(field::Velocity{}), p_.get(field::Density{}),
                                            p_.get(field::Mass{}), x0_, u0_, rho0_, walls_.points(), walls_.cells()}
            .run(n);
      else
        ShiftingPass<D, decltype(W), true>{list_, local_box_, W, R_ * R_, 0.5 * R_ * R_, W.value(scene_.dx), max_shift,
                                           p_.get(field::Position{}), p_.get(field::Velocity{}), p_.get(field::Density{}),
                                           p_.get(field::Mass{}), x0_, u0_, rho0_, walls_.points(), walls_.cells()}
            .run(n);
    });
    Kokkos::deep_copy(p_.get(field::Position{}), x0_);
    Kokkos::deep_copy(p_.get(field::Velocity{}), u0_);
    Kokkos::deep_copy(p_.get(field::Density{}), rho0_);
    halos_fresh_ = false;
  }
  if (!walls_.empty()) {
    // kernels/WallImpermeability.hpp: particles found behind a wall at the end of the step
    update_walls(t_ + dt);
    const long c = WallImpermeability<D>{walls_.segments(), walls_.wall_velocity(), dt, box_, p_.get(field::StagePosition{}),
                                         p_.get(field::Position{}), p_.get(field::Velocity{})}
                       .run(n_own_);
    if (c > 0) halos_fresh_ = false;
    wall_corrections_ += c;
  }
  check_state(dt);
  if (t_ < scene_.damping_time) {
    VelocityDamping<D>{p_.get(field::Velocity{}), std::exp(-dt / (0.1 * scene_.damping_time))}.run(n_own_);
    halos_fresh_ = false;
  }
  t_ += dt;
  ++steps_;
  stage_time_ = t_;
  return dt;
}

// Stops the run at the first step that produced a non-finite state or a density
// outside [0.5, 2] rho0, naming the step, time, particle and quantity; the state
// at the start of the step is put back so that the caller can write it.
template <int D>
void Simulation<D>::check_state(double dt) {
  int first = INT_MAX;
  Kokkos::parallel_reduce("ondine::StateCheck", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          FirstBadParticle<D>{p_.get(field::Position{}), p_.get(field::Velocity{}),
                                              p_.get(field::Density{}), 0.5 * scene_.rho0, 2.0 * scene_.rho0},
                          Kokkos::Min<int>(first));
  // the lowest rank with a bad particle names it
  const std::int64_t bad_rank = comm_.min(first == INT_MAX ? std::int64_t(comm_.size()) : std::int64_t(comm_.rank()));
  if (bad_rank == comm_.size()) return;
  if (first == INT_MAX) first = 0;
  // what went wrong, read from the host for that one particle
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::Position{}), first, Kokkos::ALL));
  auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::Velocity{}), first, Kokkos::ALL));
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::Density{}), first));
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::GlobalId{}), first));
  std::ostringstream m;
  m << "blow-up at step " << steps_ + 1 << ", t = " << t_ + dt << " s: particle " << id() << " (at";
  for (int k = 0; k < D; ++k) m << " " << x(k);
  m << ") has ";
  bool finite = std::isfinite(r());
  for (int k = 0; k < D; ++k) finite = finite && std::isfinite(x(k)) && std::isfinite(u(k));
  if (!finite) {
    m << "a non-finite state (density " << r() << ", velocity";
    for (int k = 0; k < D; ++k) m << " " << u(k);
    m << ")";
  } else {
    m << "density " << r() / scene_.rho0 << " rho0, outside [0.5, 2] rho0";
  }
  Kokkos::deep_copy(p_.get(field::Position{}), p_.get(field::StagePosition{}));
  Kokkos::deep_copy(p_.get(field::Velocity{}), p_.get(field::StageVelocity{}));
  Kokkos::deep_copy(p_.get(field::Density{}), p_.get(field::StageDensity{}));
  halos_fresh_ = false;
  throw BlowUp(comm_.broadcast(m.str(), static_cast<int>(bad_rank)));
}

template <int D>
Diagnostics Simulation<D>::diagnostics() const {
  const int n = n_own_;
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto m = p_.get(field::Mass{});
  Diagnostics d;
  Kokkos::parallel_reduce("ondine::Diagnostics::mass", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s += m(i); }, d.mass);
  for (int k = 0; k < D; ++k)
    Kokkos::parallel_reduce("ondine::Diagnostics::momentum", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& s) { s += m(i) * u(i, k); }, d.momentum[k]);
  Kokkos::parallel_reduce("ondine::Diagnostics::kinetic_energy", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s += 0.5 * m(i) * norm2(load<D>(u, i)); },
                          d.kinetic_energy);
  double v2 = 0;
  Kokkos::parallel_reduce("ondine::Diagnostics::max_speed", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) {
                            const double s = norm2(load<D>(u, i));
                            if (s > mx) mx = s;
                          },
                          Kokkos::Max<double>(v2));
  d.max_speed = std::sqrt(v2);
  Kokkos::parallel_reduce("ondine::Diagnostics::rho_min", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mn) { if (rho(i) < mn) mn = rho(i); },
                          Kokkos::Min<double>(d.rho_min));
  Kokkos::parallel_reduce("ondine::Diagnostics::rho_max", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) { if (rho(i) > mx) mx = rho(i); },
                          Kokkos::Max<double>(d.rho_max));
  if (apr_on_) {
    // with refinement zones the leaves carry the fluid: a mother's mass and
    // momentum are its daughters' (passive mothers and daughter guards overlap)
    apr::LeafSum<D> f{u, m, p_.get(field::AprMother{}), 0};
    d.mass = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::mass", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.mass);
    for (int k = 0; k < D; ++k) {
      f.what = 1 + k;
      d.momentum[k] = 0;
      Kokkos::parallel_reduce("ondine::Diagnostics::momentum", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.momentum[k]);
    }
    f.what = D + 1;
    d.kinetic_energy = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::kinetic_energy", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.kinetic_energy);
  }
  const auto box = box_;
  double hi[D];
  for (int k = 0; k < D; ++k) hi[k] = box.lo[k] + box.len[k];
  std::int64_t bad = 0;
  Kokkos::parallel_reduce("ondine::Diagnostics::outside_and_nan", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, std::int64_t& c) {
                            bool out = false, nan = !kmath::isfinite(rho(i));
                            for (int k = 0; k < D; ++k) {
                              nan = nan || !kmath::isfinite(x(i, k)) || !kmath::isfinite(u(i, k));
                              out = out || (!box.periodic[k] && (x(i, k) < box.lo[k] || x(i, k) > hi[k]));
                            }
                            c += (out ? 1 : 0) + (nan ? (std::int64_t(1) << 40) : 0);
                          },
                          bad);
  // over all ranks
  d.mass = comm_.sum(d.mass);
  for (int k = 0; k < D; ++k) d.momentum[k] = comm_.sum(d.momentum[k]);
  d.kinetic_energy = comm_.sum(d.kinetic_energy);
  d.max_speed = comm_.max(d.max_speed);
  d.rho_min = comm_.min(d.rho_min);
  d.rho_max = comm_.max(d.rho_max);
  bad = comm_.sum(bad);
  d.outside_domain = bad & ((std::int64_t(1) << 40) - 1);
  d.finite = (bad >> 40) == 0 && std::isfinite(d.kinetic_energy);
  return d;
}

// Shepard interpolation at each probe (thesis 2.40-2.41), by a reduction over all particles.
template <int D>
std::vector<ProbeSample> Simulation<D>::sample_probes() const {
  std::vector<Vec3> points;
  for (const Probe& pr : scene_.probes) points.push_back(pr.position);
  return sample_at(points);
}

template <int D>
std::vector<ProbeSample> Simulation<D>::sample_at(const std::vector<Vec3>& points) const {
  std::vector<ProbeSample> out;
  const int n = n_own_;
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto P = p_.get(field::Pressure{});
  const auto m = p_.get(field::Mass{});
  const auto box = box_;
  if (apr_on_) return sample_levels(points);
  for (const Vec3& point : points) {
    Vec<D> xp;
    for (int k = 0; k < D; ++k) xp[k] = point[k];
    ProbeSample s;
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      // one reduction per quantity: probes are sampled at output times only
      auto sum = [&](auto value) {
        double acc = 0;
        Kokkos::parallel_reduce("ondine::Probe", Kokkos::RangePolicy<ExecSpace>(0, n),
                                ProbeSum<D, decltype(W), decltype(value)>{box, W, xp, x, rho, m, value}, acc);
        return comm_.sum(acc);
      };
      using Scalar = probe_value::Scalar<std::decay_t<decltype(rho)>>;
      using Component = probe_value::Component<std::decay_t<decltype(u)>>;
      s.shepard = sum(probe_value::One{});
      if (s.shepard > 0) {
        s.pressure = sum(Scalar{P}) / s.shepard;
        s.density = sum(Scalar{rho}) / s.shepard;
        for (int k = 0; k < D; ++k) s.velocity[k] = sum(Component{u, k}) / s.shepard;
      }
    });
    out.push_back(s);
  }
  return out;
}

template <int D>
std::vector<double> Simulation<D>::wave_elevations() {
  std::vector<double> out;
  if (scene_.wave_gauges.empty()) return out;
  ensure_neighbours();  // the particle cell list is current
  refresh_halos();
  const double step = 0.25 * (apr_on_ ? apr_.dx(apr_.levels() - 1) : scene_.dx);  // a quarter of the finest spacing
  for (const WaveGauge& g : scene_.wave_gauges) {
    const int ns = static_cast<int>(std::floor((g.top - g.bottom) / step)) + 1;
    Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> pts("ondine::WaveGauge::points", ns);
    Kokkos::View<double*, MemSpace> sum("ondine::WaveGauge::sum", ns);
    auto hp = Kokkos::create_mirror_view(pts);
    std::vector<double> z(ns);
    for (int s = 0; s < ns; ++s) {  // the sample points of the line (not particles)
      z[s] = g.bottom + s * step;
      for (int k = 0; k < D - 1; ++k) hp(s, k) = g.position[k];
      hp(s, D - 1) = z[s];
    }
    Kokkos::deep_copy(pts, hp);
    if (apr_on_)  // SPH particles only, each with its level's radius (WaveGauge.hpp)
      with_kernel<D>(scene_.kernel, 1.0, [&](auto W1) {
        Kokkos::parallel_for("ondine::WaveGauge", Kokkos::RangePolicy<ExecSpace>(0, ns),
                             GaugeShepardSum<D, decltype(W1), true>{cells_, box_, W1, R_ * R_, n_own_, p_.get(field::Position{}),
                                                                    p_.get(field::Density{}), p_.get(field::Mass{}), pts, sum,
                                                                    apr_.zones(), p_.get(field::AprBirthLevel{}),
                                                                    p_.get(field::AprGuard{})});
      });
    else
      with_kernel<D>(scene_.kernel, R_, [&](auto W) {
        Kokkos::parallel_for("ondine::WaveGauge", Kokkos::RangePolicy<ExecSpace>(0, ns),
                             GaugeShepardSum<D, decltype(W)>{cells_, box_, W, R_ * R_, n_own_, p_.get(field::Position{}),
                                                             p_.get(field::Density{}), p_.get(field::Mass{}), pts, sum});
      });
    std::vector<double> shepard(ns);
    Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(shepard.data(), ns), sum);
    comm_.sum_in_place(shepard);
    out.push_back(gauge_level(z.data(), shepard.data(), ns));
  }
  return out;
}

template <int D>
std::vector<WallForce> Simulation<D>::wall_forces() {
  std::vector<WallForce> out;
  if (walls_.empty()) return out;
  ensure_neighbours();  // the particle cell list is current
  refresh_halos();
  const int nq = walls_.points().count;
  const double nu = scene_.viscous_term != ViscousTerm::None ? scene_.nu : 0.0;
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction("ondine::NFM::traction", nq, 2 * D);
  if (apr_on_)  // each SPH particle with its level's radius (WallForces.hpp)
    with_kernel<D>(scene_.kernel, 1.0, [&](auto W1) {
      Kokkos::parallel_for("ondine::NFM::wall_traction", Kokkos::RangePolicy<ExecSpace>(0, nq),
                           WallTraction<D, decltype(W1), true>{walls_.points(), cells_, W1, R_ * R_, nu, scene_.rho0,
                                                               wall_eos(), 0.05 * R_, box_, p_.get(field::Position{}),
                                                               p_.get(field::Velocity{}), p_.get(field::Density{}),
                                                               p_.get(field::Pressure{}), p_.get(field::Mass{}),
                                                               p_.get(field::DensityGradient{}), traction, apr_.zones(),
                                                               p_.get(field::AprBirthLevel{}), p_.get(field::AprGuard{}),
                                                               scene_.wall_velocity_reconstruction});
    });
  else
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      Kokkos::parallel_for("ondine::NFM::wall_traction", Kokkos::RangePolicy<ExecSpace>(0, nq),
                           WallTraction<D, decltype(W)>{walls_.points(), cells_, W, R_ * R_, nu, scene_.rho0,
                                                        wall_eos(), 0.05 * R_, box_, p_.get(field::Position{}),
                                                        p_.get(field::Velocity{}), p_.get(field::Density{}),
                                                        p_.get(field::Pressure{}), p_.get(field::Mass{}),
                                                        p_.get(field::DensityGradient{}), traction, {}, {}, {},
                                                        scene_.wall_velocity_reconstruction});
    });
  // several ranks: each wall point is counted by the rank that owns its cell (its
  // support is complete there: owned particles and halos)
  Kokkos::View<int*, MemSpace> counted("ondine::NFM::counted", nq);
  Kokkos::deep_copy(counted, 1);
  if (!comm_.serial()) {
    const auto orb = orb_;
    const auto wx = walls_.points().x;
    const auto box = box_;
    const int me = comm_.rank();
    Kokkos::parallel_for("ondine::NFM::wall_point_owner", Kokkos::RangePolicy<ExecSpace>(0, nq), KOKKOS_LAMBDA(const int q) {
      Vec<D> xq;
      for (int k = 0; k < D; ++k) xq[k] = box.wrap(wx(q, k), k);
      counted(q) = orb.owner(xq) == me ? 1 : 0;
    });
  }
  for (int w = 0; w < walls_.wall_count(); ++w) {
    WallForce f;
    f.name = walls_.names()[w];
    for (int c = 0; c < 2 * D; ++c) {
      double v = 0;
      Kokkos::parallel_reduce("ondine::NFM::wall_force", Kokkos::RangePolicy<ExecSpace>(0, nq),
                              WallTractionSum{traction, walls_.points().wall, counted, w, c}, v);
      (c < D ? f.pressure[c] : f.viscous[c - D]) = comm_.sum(v);
    }
    out.push_back(f);
  }
  return out;
}

template <int D>
std::int64_t Simulation<D>::wall_leaks(double clearance) const {
  if (walls_.empty()) return 0;
  long c = 0;
  Kokkos::parallel_reduce("ondine::NFM::leaks", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          WallLeakCount<D>{region_, clearance < 0 ? 0.1 * scene_.dx : clearance, p_.get(field::Position{})}, c);
  return comm_.sum(static_cast<std::int64_t>(c));
}

template <int D>
void Simulation<D>::prepare_output() {
  // several ranks: owned positions are wrapped into the periodic box only at
  // migration; migrate now so that snapshots hold wrapped positions
  if (!comm_.serial()) {
    if (apr_on_) relist_for_output();
    else rebuild_neighbours(false);
  }
  // the stored state's own pressure and Shepard factor (the flux passes left last-stage values)
  refresh_halos();
  if (apr_on_) {
    // a list rebuild here would have been the next step start's, with its bookkeeping: it still is
    const std::int64_t builds = builds_;
    ensure_neighbours();
    if (builds_ != builds) bookkeeping_due_ = true;
    // the guards' fields as the run has them, put back by finish_output()
    auto keep = [](auto& saved, const auto& v) {
      if (saved.extent(0) != v.extent(0)) saved = std::decay_t<decltype(saved)>("ondine::APR::saved_for_output", v.extent(0));
      Kokkos::deep_copy(saved, v);
    };
    keep(saved_u_, p_.get(field::Velocity{}));
    keep(saved_rho_, p_.get(field::Density{}));
    if (p_.has(field::DensityGradient{})) keep(saved_grad_rho_, p_.get(field::DensityGradient{}));
    apr_.save_wide_flags();
    output_saved_ = true;
    apr_.interpolate(p_, box_, true, walls_.segments());  // the guards of the stored state (5.24)
    refresh_guard_halos();
  }
  const int n = static_cast<int>(p_.size());
  detail::with_eos<D>(scene_, [&](auto eos) {
    update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), n);
  });
  if (!walls_.empty()) update_walls(t_);
  update_free_surface();
}

template <int D>
void Simulation<D>::finish_output() {
  if (!apr_on_ || !output_saved_) return;
  Kokkos::deep_copy(p_.get(field::Velocity{}), saved_u_);
  Kokkos::deep_copy(p_.get(field::Density{}), saved_rho_);
  if (p_.has(field::DensityGradient{})) Kokkos::deep_copy(p_.get(field::DensityGradient{}), saved_grad_rho_);
  apr_.restore_wide_flags();
  output_saved_ = false;
}

template <int D>
void Simulation<D>::update_free_surface() {
  if (apr_on_) {
    update_free_surface_levels();
    return;
  }
  if (!p_.has(field::FreeSurface{})) {
    if (!walls_.empty())
      ShepardGammaPass<D>{walls_.segments(), R_, box_, p_.get(field::Position{}), p_.get(field::ShepardGamma{})}.run(n_own_);
    return;
  }
  ensure_neighbours();
  refresh_halos();
  const int n = n_own_;
  if (!walls_.empty())
    ShepardGammaPass<D>{walls_.segments(), R_, box_, p_.get(field::Position{}), p_.get(field::ShepardGamma{})}
        .run(static_cast<int>(p_.size()));
  with_kernel<D>(scene_.kernel, R_, [&](auto W) {
    using K = decltype(W);
    if (walls_.empty())
      FreeSurfacePass<D, K, false>{list_, box_, W, R_, R_ * R_, walls_.points(), walls_.cells(), p_.get(field::Position{}),
                                   p_.get(field::Density{}), p_.get(field::Mass{}), field_view_t<field::ShepardGamma, D>(),
                                   p_.get(field::FreeSurface{})}
          .run(n);
    else
      FreeSurfacePass<D, K, true>{list_, box_, W, R_, R_ * R_, walls_.points(), walls_.cells(), p_.get(field::Position{}),
                                  p_.get(field::Density{}), p_.get(field::Mass{}), p_.get(field::ShepardGamma{}),
                                  p_.get(field::FreeSurface{})}
          .run(n);
  });
}

template <int D>
double Simulation<D>::front_position() const {
  double xmax = -1e300;
  Kokkos::parallel_reduce("ondine::Front", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          MaxComponent<D>{p_.get(field::Position{}), 0}, Kokkos::Max<double>(xmax));
  return comm_.max(xmax) + 0.5 * scene_.dx;
}

template <int D>
std::map<std::string, double> Simulation<D>::errors() const {
  std::map<std::string, double> e;
  const Diagnostics d = diagnostics();
  e["mass_drift"] = std::abs(d.mass - initial_.mass) / initial_.mass;
  bool all_periodic = true;
  for (int k = 0; k < D; ++k) all_periodic = all_periodic && scene_.periodic[k];
  if (all_periodic && walls_.empty() && scene_.damping_time == 0) {
    // With no walls, internal forces cancel pairwise: P(t) = P(0) + M (g + f) t exactly.
    double err2 = 0, scale2 = 0;
    for (int k = 0; k < D; ++k) {
      const double expect = initial_.momentum[k] + d.mass * (scene_.gravity[k] + scene_.body_force[k]) * t_;
      err2 += (d.momentum[k] - expect) * (d.momentum[k] - expect);
      scale2 += expect * expect;
    }
    const double scale = std::max(std::sqrt(scale2), d.mass * scene_.reference_velocity);
    e["momentum_balance_error"] = std::sqrt(err2) / scale;
  }
  bool taylor_green = all_periodic && D == 2;
  for (const FluidBlock& b : scene_.blocks) taylor_green = taylor_green && b.velocity_kind == InitialVelocity::TaylorGreen;
  if (taylor_green) {
    // Decaying vortex: u = -U e^{bt} cos kx sin ky, v = U e^{bt} sin kx cos ky, b = -2 nu k^2.
    const FluidBlock& b = scene_.blocks.front();
    const double k = 2.0 * M_PI / b.tg_wavelength;
    const double amp = b.tg_amplitude * std::exp(-2.0 * scene_.nu * k * k * t_);
    const int n = n_own_;
    const auto x = p_.get(field::Position{});
    const auto u = p_.get(field::Velocity{});
    double num = 0, den = 0, linf = 0;
    Kokkos::parallel_reduce("ondine::Error::taylor_green_l2", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& a) {
                              const double ue = -amp * kmath::cos(k * x(i, 0)) * kmath::sin(k * x(i, 1));
                              const double ve = amp * kmath::sin(k * x(i, 0)) * kmath::cos(k * x(i, 1));
                              a += (u(i, 0) - ue) * (u(i, 0) - ue) + (u(i, 1) - ve) * (u(i, 1) - ve);
                            },
                            num);
    Kokkos::parallel_reduce("ondine::Error::taylor_green_norm", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& a) {
                              const double ue = -amp * kmath::cos(k * x(i, 0)) * kmath::sin(k * x(i, 1));
                              const double ve = amp * kmath::sin(k * x(i, 0)) * kmath::cos(k * x(i, 1));
                              a += ue * ue + ve * ve;
                            },
                            den);
    Kokkos::parallel_reduce("ondine::Error::taylor_green_linf", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& mx) {
                              const double ue = -amp * kmath::cos(k * x(i, 0)) * kmath::sin(k * x(i, 1));
                              const double ve = amp * kmath::sin(k * x(i, 0)) * kmath::cos(k * x(i, 1));
                              const double err = kmath::sqrt((u(i, 0) - ue) * (u(i, 0) - ue) + (u(i, 1) - ve) * (u(i, 1) - ve));
                              if (err > mx) mx = err;
                            },
                            Kokkos::Max<double>(linf));
    e["velocity_l2"] = std::sqrt(comm_.sum(num) / comm_.sum(den));
    e["velocity_linf"] = comm_.max(linf) / amp;
    e["max_speed_decay_error"] = std::abs(d.max_speed - amp) / amp;
  }
  if (!walls_.empty()) {
    e["wall_leaks"] = static_cast<double>(wall_leaks());
    e["wall_crossings"] = static_cast<double>(wall_leaks(0.0));  // on the solid side of a wall only
    if (apr_on_) e["families_moved_off_walls"] = static_cast<double>(apr_.families_moved());
    if (apr_on_ && scene_.refinement_guard_shifting) e["guard_shifts"] = static_cast<double>(comm_.sum(apr_.guard_shifts()));
    e["wall_corrections"] = static_cast<double>(wall_corrections());
  }
  const Reference& ref = scene_.reference;
  const int n = n_own_;
  if (ref.kind == ReferenceKind::Poiseuille || ref.kind == ReferenceKind::Couette) {
    // start-up Poiseuille driven by the body force along x, or start-up Couette driven by the
    // upper wall (Morris et al. 1997), at the current time
    auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::Position{}));
    auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::Velocity{}));
    const double L = ref.length;
    // the analytic profile is evaluated on a fine table (a host loop over 1001 points, not
    // particles) and interpolated quadratically: exact for the steady parabola, O(h^3 u''') on
    // the transient. (A linear interpolation was off by up to h^2 |u''| / 8 = 1e-6 U_max, a bias
    // of 1e-5 relative near the walls that halved the near-wall error of a fine Poiseuille run.)
    const int m = 1000;
    std::vector<double> table(m + 1);
    for (int k = 0; k <= m; ++k) table[k] = reference::channel_startup(scene_, L * k / m, t_);
    Kokkos::View<double*, Kokkos::HostSpace> tab(table.data(), m + 1);
    double num = 0, den = 0, num_wall = 0, den_wall = 0;
    // with refinement zones: the SPH particles only (guards are interpolated copies), each with its radius
    Kokkos::View<int*, Kokkos::HostSpace> guard, birth;
    if (apr_on_) {
      guard = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::AprGuard{}));
      birth = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::AprBirthLevel{}));
    }
    // one pass on the host mirror: the error is a diagnostic at the end of a run
    for (int i = 0; i < n; ++i) {
      if (apr_on_ && guard(i)) continue;
      const double y = std::min(std::max(hx(i, 1) - ref.origin[1], 0.0), L);
      const double f = y / L * m;
      const int k = std::min(std::max(static_cast<int>(std::lround(f)), 1), m - 1);
      const double sk = f - k;
      const double ue = table[k] + 0.5 * sk * (table[k + 1] - table[k - 1]) +
                        0.5 * sk * sk * (table[k + 1] - 2.0 * table[k] + table[k - 1]);
      num += (hu(i, 0) - ue) * (hu(i, 0) - ue);
      den += ue * ue;
      // the particles whose support is cut by a wall (thesis Table 5.3's boundary error)
      const double Ri = apr_on_ ? apr_.R(birth(i)) : R_;
      if (y < Ri || y > L - Ri) {
        num_wall += (hu(i, 0) - ue) * (hu(i, 0) - ue);
        den_wall += ue * ue;
      }
    }
    e["velocity_l2"] = std::sqrt(comm_.sum(num) / comm_.sum(den));
    den_wall = comm_.sum(den_wall);
    if (den_wall > 0) e["velocity_l2_near_wall"] = std::sqrt(comm_.sum(num_wall) / den_wall);
  } else if (ref.kind == ReferenceKind::GhiaRe100 || ref.kind == ReferenceKind::GhiaRe1000) {
    // lid-driven cavity: RMS of (u - u_Ghia)/U on the vertical centreline and of (v - v_Ghia)/U on the
    // horizontal one, Shepard-interpolated at Ghia et al.'s points (the walls' own points excluded)
    const int column = ref.kind == ReferenceKind::GhiaRe100 ? 1 : 2;
    const auto slash = scene_.source_file.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : scene_.source_file.substr(0, slash);
    const double L = ref.length, U = scene_.reference_velocity;
    for (int line = 0; line < 2; ++line) {
      const auto table = reference::read_table(dir + (line == 0 ? "/reference/ghia1982_u_vertical_centreline.csv"
                                                                 : "/reference/ghia1982_v_horizontal_centreline.csv"));
      std::vector<Vec3> pts;
      std::vector<double> expect;
      for (const auto& row : table) {
        if (row[0] <= 0.0 || row[0] >= 1.0) continue;
        Vec3 pnt = ref.origin;
        pnt[line == 0 ? 1 : 0] += row[0] * L;  // along the line
        pnt[line == 0 ? 0 : 1] += 0.5 * L;     // at the centre
        pts.push_back(pnt);
        expect.push_back(row[column] * U);
      }
      const auto got = sample_at(pts);
      double sq = 0;
      for (std::size_t k = 0; k < pts.size(); ++k) {
        const double d = (got[k].velocity[line == 0 ? 0 : 1] - expect[k]) / U;
        sq += d * d;
      }
      e[line == 0 ? "centreline_u_rms" : "centreline_v_rms"] = std::sqrt(sq / pts.size());
    }
  } else if (ref.kind == ReferenceKind::Hydrostatic) {
    // P = rho0 |g| (H - z) for particles deeper than 3 dx; ratio of kinetic to potential energy
    auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::Position{}));
    auto hP = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::Pressure{}));
    auto hm = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.get(field::Mass{}));
    const double g = std::abs(scene_.gravity[1]), H = ref.length, z0 = ref.origin[1];
    double worst = 0, pe = 0;
    for (int i = 0; i < n; ++i) {
      const double z = hx(i, 1) - z0;
      pe += hm(i) * g * z;
      if (H - z < 3 * scene_.dx) continue;
      worst = std::max(worst, std::abs(hP(i) - scene_.rho0 * g * (H - z)));
    }
    worst = comm_.max(worst);
    pe = comm_.sum(pe);
    e["pressure_linf"] = worst / (scene_.rho0 * g * H);
    e["kinetic_over_potential"] = d.kinetic_energy / pe;
  }
  return e;
}

}  // namespace ondine

#include "solver/SimulationLevels.hpp"
