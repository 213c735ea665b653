#pragma once
// Simulation<D>: the set-up of a run (the lattice fill, the fluid region of the walls, a
// checkpoint's state) and the state rows and checksums a checkpoint carries. Included by
// SimulationImpl.hpp only.
#include <cmath>
#include <stdexcept>

#include "kernels/InitialFill.hpp"
#include "kernels/StateHash.hpp"
#include "scene/CaseFile.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/SchemePasses.hpp"
#include "solver/StepState.hpp"
#include "solver/hooks/StepHooks.hpp"

namespace ondine {

template <int D>
Simulation<D>::Simulation(const Scene& scene, const CheckpointSlice* restart) : scene_(scene) {
  if (scene.dimension != D) throw std::logic_error("Simulation<D>: scene dimension mismatch");
  R_ = scene.R();
  scheme_ = make_scheme<D>(scene);
  // with refinement zones the skin and the wall quadrature follow the finest spacing
  apr_on_ = !scene.refinement_zones.empty();
  const double dx_finest = scene.dx / std::ldexp(1.0, scene.max_refinement_level());
  skin_len_ = scene.neighbour_skin * (apr_on_ ? dx_finest : scene.dx);
  if (apr_on_) {
    if (restart && !restart->header.refinement.present)
      throw std::logic_error("Simulation<D>: a checkpoint without the APR state for a scene with refinement zones");
  }
  // the wall quadrature's spacing; with zones in 2D every level's walls at the finest level's
  // dx / 4 (3D: each level at its own spacing, build_level_walls)
  wall_spacing_ = wall_quadrature_spacing<D>(scene, apr_on_ && D == 2 ? dx_finest : scene.dx);
  domain_ = Domain<D>(scene_, R_ + skin_len_, skin_len_);
  // this rank's share of the lattice or of the checkpoint; migrate() then sends
  // every particle to the owner of its cell
  const std::int64_t lattice = count_particles(scene);
  lattice_first_ = lattice * comm().rank() / comm().size();
  const std::int64_t lattice_end = lattice * (comm().rank() + 1) / comm().size();
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
  // the density gradient feeds delta-SPH, the MUSCL wall state (4.30) and Riemann-SPH's MUSCL (2.78)
  if (uses_density_gradient(scene)) p_.allocate(field::DensityGradient{});
  if (uses_velocity_gradient(scene)) {
    p_.allocate(field::VelocityGradientX{});
    p_.allocate(field::VelocityGradientY{});
    if constexpr (D == 3) p_.allocate(field::VelocityGradientZ{});
  }
  if (walls) p_.allocate(field::ShepardGamma{});
  if (scene.flux == FluxScheme::Riemann && scene.riemann_variant == RiemannVariant::Vila) p_.allocate(field::MassRate{});
  bool free_surface_possible = false;
  for (int k = 0; k < D; ++k) free_surface_possible = free_surface_possible || !scene.periodic[k];
  if (free_surface_possible) p_.allocate(field::FreeSurface{});
  if (walls) {
    walls_ = WallModel<D>(scene_, domain_.box(), R_, wall_spacing_);
    if (apr_on_) build_level_walls();
    build_fluid_region();
  }
  hooks_ = make_step_hooks<D>(scene_, restart);
  for (auto& h : hooks_) h->allocate(p_);
  if (restart) {
    load_checkpoint(*restart);
  } else {
    fill(lattice_first_, lattice_end);
    if (walls) remove_outside_fluid();
    if (walls) check_wall_sides();
  }
  n_own_ = static_cast<int>(p_.size());
  if (!comm().serial()) {
    // first decomposition: weighted by the particles in each cell
    decompose(false);
    n_own_ = domain_.migrate(p_, n_own_);
  }
  // the hooks' set-up (the open boundaries' roles, before the refinement sorts the particles)
  StepState<D> state(*this);
  for (auto& h : hooks_) h->start(state, restart);
  if (apr_on_ && restart) {
    // the APR fields came with the checkpoint (load_checkpoint); the zones, counters and
    // level ranges as saved (on several ranks after the first migration: each rank sorts
    // the particles it owns by their stored level and role). The first step starts with
    // the bookkeeping that the saved run would have done after writing the checkpoint.
    apr_ = AdaptiveRefinement<D>(scene_, domain_.box(), skin_len_);
    apr_.restore(p_, n_own_, restart->header.refinement);
    apr_.count_guard_shifts(comm().rank() == 0 ? restart->header.refinement.guard_shifts : 0);
    domain_.invalidate_lists();
    bookkeeping_due_ = true;
  } else if (apr_on_) {
    // every particle starts as a coarse SPH particle; one bookkeeping pass per
    // level creates the daughters of each nested level in turn (on several ranks,
    // after the first decomposition: each rank refines the particles it owns)
    apr_ = AdaptiveRefinement<D>(scene_, domain_.box(), skin_len_);
    // ids from the fill's count on (the open boundaries may have dropped particles since)
    const std::int64_t hook_ids = hooks_next_id();
    apr_.initialise(p_, hook_ids >= 0 ? hook_ids : comm().sum(static_cast<std::int64_t>(n_own_)));
    for (int l = 1; l < apr_.levels(); ++l) refinement_bookkeeping();
  }
  with_eos<D>(scene_, [&](auto eos) {
    update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), n_own_);
  });
  initial_ = diagnostics();
  if (!restart)
    for (auto& h : hooks_) h->started(initial_);
  if (restart) {
    t_ = restart->header.time;
    steps_ = restart->header.step;
    stage_time_ = t_;
    initial_.mass = restart->header.initial_mass;
    for (int k = 0; k < 3; ++k) initial_.momentum[k] = restart->header.initial_momentum[k];
    if (walls_.moving()) update_walls(t_);
  }
}

// The fluid region of the walls (kernels/FluidRegion.hpp): the facets, and the closed
// walls as facet ranges with the side the fluid is on (a host loop over walls).
template <int D>
void Simulation<D>::build_fluid_region() {
  region_.facets = walls_.facets();
  region_.cells = walls_.facet_cells();
  region_.box = domain_.box();
  region_.behind = scene_.dx;
  std::vector<int> first, count, inside;
  int s0 = 0;
  for (const Wall& w : scene_.walls) {
    const int ns = static_cast<int>(D == 3 ? w.mesh.triangles.size() : (w.closed ? w.points.size() : w.points.size() - 1));
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

// Refuses a fill whose fluid lies on the solid side of a wall (walls[i].fluid_side the
// wrong way round, or the points in the reverse order), which would start, blow up at the
// first step and leave snapshots behind: the particles within R of each wall are counted
// on either side of its facets (kernels/FluidRegion.hpp), and a wall with more fluid
// behind it than in front is named. A wall with fluid on both sides at equal counts (two
// tanks back to back) passes.
template <int D>
void Simulation<D>::check_wall_sides() {
  const int nw = static_cast<int>(scene_.walls.size());
  Kokkos::View<long* [2], Kokkos::LayoutRight, MemSpace> count("ondine::NFM::wall_side_count", nw);
  Kokkos::parallel_for("ondine::NFM::wall_side_count", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p_.size())),
                       WallSideCount<D>{walls_.facets(), walls_.facet_cells(), domain_.box(), R_, p_.get(field::Position{}), count});
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), count);
  for (int w = 0; w < nw; ++w) {
    const std::int64_t front = comm().sum(static_cast<std::int64_t>(h(w, 0))), behind = comm().sum(static_cast<std::int64_t>(h(w, 1)));
    if (behind <= front) continue;
    const Wall& wall = scene_.walls[static_cast<std::size_t>(w)];
    // open walls: left/right of the points (2D), front/back of the triangles' normals (3D)
    const char* open_side[2][2] = {{"right", "left"}, {"back", "front"}};
    const int in = wall.fluid_inside ? 1 : 0;
    const char* side = wall.closed ? (in ? "inside" : "outside") : open_side[D == 3][in];
    const char* other = wall.closed ? (in ? "outside" : "inside") : open_side[D == 3][1 - in];
    const char* how = wall.closed ? "" : (D == 2 ? " (walking along its points)" : " (of its triangles' normals)");
    throw std::invalid_argument(scene_.source_file + ": walls[" + std::to_string(w) + "] ('" + wall.name + "'): " +
                                std::to_string(behind) + " fluid particles lie within R of it on its solid side and " +
                                std::to_string(front) + " on its fluid side; with fluid_side: " + side +
                                " the fluid must be on the " + side + " of the wall" + how + ": "
                                "expected fluid_side: " + other + ", or the fluid blocks on the other side");
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
  if (comm().sum(static_cast<std::int64_t>(kept)) == 0)
    throw std::invalid_argument(scene_.source_file + ": no fluid particle lies inside the walls (check fluid_blocks and walls[].fluid_side)");
  Kokkos::View<int*, MemSpace> order("ondine::Fill::order", kept);
  Kokkos::parallel_for("ondine::Fill::gather", Kokkos::RangePolicy<ExecSpace>(0, n), KeepGather{keep, index, order});
  p_.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept));
  Kokkos::parallel_for("ondine::Fill::renumber", Kokkos::RangePolicy<ExecSpace>(0, kept),
                       Iota{p_.get(field::GlobalId{}), comm().exclusive_scan(kept)});
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
  for_each_checkpoint_field(put);
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
  for_each_checkpoint_field(take);
  return out;
}

template <int D>
CheckpointRefinement Simulation<D>::refinement_state() const {
  CheckpointRefinement c;
  if (!apr_on_) return c;
  apr_.save_state(c);
  c.guard_shifts = comm().sum(apr_.guard_shifts());  // a global count (each rank counts its own)
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
  return comm().sum_u64(static_cast<std::uint64_t>(h));
}

template <int D>
std::uint64_t Simulation<D>::state_checksum() const {
  unsigned long long h = 0;
  Kokkos::parallel_reduce("ondine::StateHash", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          StateHash<D>{p_.get(field::Position{}), p_.get(field::Velocity{}), p_.get(field::Density{}),
                                       p_.get(field::Mass{}), p_.get(field::GlobalId{})},
                          h);
  return comm().sum_u64(static_cast<std::uint64_t>(h));
}

template <int D>
std::int64_t Simulation<D>::hooks_next_id() const {
  for (const auto& h : hooks_)
    if (h->next_id() >= 0) return h->next_id();
  return -1;
}

template <int D>
std::int64_t Simulation<D>::next_id() const {
  if (apr_on_) return apr_.next_id();
  const std::int64_t ids = hooks_next_id();
  return ids >= 0 ? ids : 0;
}

}  // namespace ondine
