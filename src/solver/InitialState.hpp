#pragma once
// The initial state of a run: the lattice fill of the fluid blocks, the points outside the
// walls' fluid region dropped, the walls' sides checked; or a checkpoint's rows.
#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/FluidRegion.hpp"
#include "io/Checkpoint.hpp"
#include "kernels/InitialFill.hpp"
#include "kernels/Permute.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/ParticleExchange.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"
#include "solver/CheckpointFields.hpp"
#include "solver/FillCutsBuild.hpp"
#include "solver/WallModel.hpp"

namespace ondine {

// Lattice fill of each block at (k + 1/2) dx, with its initial velocity and pressure.
template <int D>
void fill_lattice(ParticleSet<D>& p, const Scene& s, std::int64_t first, std::int64_t end) {
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  const auto rho = p.get(field::Density{});
  const auto m = p.get(field::Mass{});
  const auto id = p.get(field::GlobalId{});
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
// block's wall_clearance (dx/2 by default) (with walls: `region`), and those cut off by
// their block's half-spaces (beyond the cuts' margins: fill_cuts), keeping the order, and
// renumbers the global ids.
template <int D>
void remove_outside_fluid(ParticleSet<D>& p, const Scene& scene, const FluidRegion<D>* region, const Communicator& comm) {
  const int n = static_cast<int>(p.size());
  Kokkos::View<int*, MemSpace> keep("ondine::Fill::keep", n), index("ondine::Fill::index", n);
  const int nb = static_cast<int>(scene.blocks.size());
  Kokkos::View<std::int64_t*, MemSpace> block_end("ondine::Fill::block_end", nb);
  Kokkos::View<double*, MemSpace> block_clearance("ondine::Fill::block_clearance", nb);
  {
    auto he = Kokkos::create_mirror_view(block_end);
    auto hc = Kokkos::create_mirror_view(block_clearance);
    std::int64_t end = 0;
    for (int b = 0; b < nb; ++b) {
      const FluidBlock& blk = scene.blocks[b];
      std::int64_t cnt = 1;
      for (int k = 0; k < D; ++k) cnt *= std::llround((blk.box.max[k] - blk.box.min[k]) / scene.dx);
      he(b) = end += cnt;  // the lattice order of fill()
      hc(b) = blk.wall_clearance * scene.dx * (1 - 1e-9);  // a point exactly at the clearance is kept
    }
    Kokkos::deep_copy(block_end, he);
    Kokkos::deep_copy(block_clearance, hc);
  }
  const FillCuts<D> cuts = fill_cuts<D>(scene);
  Kokkos::parallel_for("ondine::Fill::fluid_region", Kokkos::RangePolicy<ExecSpace>(0, n),
                       FluidRegionFilter<D>{region ? *region : FluidRegion<D>{}, region != nullptr, block_end, block_clearance, cuts,
                                            p.get(field::Position{}), p.get(field::GlobalId{}), keep});
  int kept = 0;
  Kokkos::parallel_scan("ondine::Fill::scan", Kokkos::RangePolicy<ExecSpace>(0, n), KeepScan{keep, index}, kept);
  if (comm.sum(static_cast<std::int64_t>(kept)) == 0)
    throw std::invalid_argument(scene.source_file + (region ? ": no fluid particle lies inside the walls (check fluid_blocks and walls[].fluid_side)"
                                                            : ": no fluid particle is left by the fluid blocks' cuts (check fluid_blocks[].cut)"));
  Kokkos::View<int*, MemSpace> order("ondine::Fill::order", kept);
  Kokkos::parallel_for("ondine::Fill::gather", Kokkos::RangePolicy<ExecSpace>(0, n), KeepGather{keep, index, order});
  p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept));
  Kokkos::parallel_for("ondine::Fill::renumber", Kokkos::RangePolicy<ExecSpace>(0, kept),
                       Iota{p.get(field::GlobalId{}), comm.exclusive_scan(kept)});
}

// Refuses a fill whose fluid lies on the solid side of a wall (walls[i].fluid_side the
// wrong way round, or the points in the reverse order), which would start, blow up at the
// first step and leave snapshots behind: the particles within R of each wall are counted
// on either side of its facets (kernels/FluidRegion.hpp), and a wall with more fluid
// behind it than in front is named. A wall with fluid on both sides at equal counts (two
// tanks back to back) passes.
template <int D>
void check_wall_sides(const ParticleSet<D>& p, const Scene& scene, const WallModel<D>& walls, const PeriodicBox<D>& box, double R,
                      const Communicator& comm) {
  const int nw = static_cast<int>(scene.walls.size());
  Kokkos::View<long* [2], Kokkos::LayoutRight, MemSpace> count("ondine::NFM::wall_side_count", nw);
  Kokkos::parallel_for("ondine::NFM::wall_side_count", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p.size())),
                       WallSideCount<D>{walls.facets(), walls.facet_cells(), box, R, p.get(field::Position{}), count});
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), count);
  for (int w = 0; w < nw; ++w) {
    const std::int64_t front = comm.sum(static_cast<std::int64_t>(h(w, 0))), behind = comm.sum(static_cast<std::int64_t>(h(w, 1)));
    if (behind <= front) continue;
    const Wall& wall = scene.walls[static_cast<std::size_t>(w)];
    // open walls: left/right of the points (2D), front/back of the triangles' normals (3D)
    const char* open_side[2][2] = {{"right", "left"}, {"back", "front"}};
    const int in = wall.fluid_inside ? 1 : 0;
    const char* side = wall.closed ? (in ? "inside" : "outside") : open_side[D == 3][in];
    const char* other = wall.closed ? (in ? "outside" : "inside") : open_side[D == 3][1 - in];
    const char* how = wall.closed ? "" : (D == 2 ? " (walking along its points)" : " (of its triangles' normals)");
    throw std::invalid_argument(scene.source_file + ": walls[" + std::to_string(w) + "] ('" + wall.name + "'): " +
                                std::to_string(behind) + " fluid particles lie within R of it on its solid side and " +
                                std::to_string(front) + " on its fluid side; with fluid_side: " + side +
                                " the fluid must be on the " + side + " of the wall" + how + ": "
                                "expected fluid_side: " + other + ", or the fluid blocks on the other side");
  }
}

// This rank's share of a checkpoint into the state fields.
template <int D>
void load_checkpoint(ParticleSet<D>& p, const CheckpointSlice& c, bool refinement) {
  auto put = [&](auto tag) {
    using V = field_view_t<decltype(tag), D>;
    const auto found = c.fields.find(decltype(tag)::label);
    if (found == c.fields.end())
      throw CheckpointError(std::string("the checkpoint has no dataset '") + decltype(tag)::label +
                            "', which this case needs (k and epsilon: a checkpoint of a run without k-epsilon; "
                            "langevin_gradient_*: of a run without turbulence.langevin.mean_gradient: averaged)");
    const std::vector<double>& rows = found->second;
    const int w = exchange::width_of<V>();
    exchange::Rows dev("ondine::Restart::rows", c.rows, w);
    Kokkos::deep_copy(dev, Kokkos::View<const double**, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(
                               rows.data(), c.rows, w));
    Kokkos::parallel_for("ondine::Restart::unpack", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(c.rows)),
                         exchange::UnpackRows<V>{p.allocate(tag), dev, 0, 0});
  };
  for_each_checkpoint_field(p, refinement, put);
}

}  // namespace ondine
