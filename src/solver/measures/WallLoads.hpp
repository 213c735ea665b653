#pragma once
// The loads of the fluid on the walls, and the particles that leaked through them
// (solver/Measures.hpp).
#include "kernels/FluidRegion.hpp"
#include "kernels/WallForces.hpp"
#include "solver/FluidRegionBuild.hpp"
#include "solver/StepState.hpp"

namespace ondine {

template <int D>
std::vector<WallForce> wall_forces(Simulation<D>& sim) {
  const Scene& scene = sim.scene();
  const WallModel<D>& walls = sim.walls();
  std::vector<WallForce> out;
  if (walls.empty()) return out;
  StepState<D> state(sim);
  state.ensure_lists();  // the particle cell list is current
  state.domain().refresh_state_halos(state.particles());
  const int nq = walls.points().count;
  const double nu = scene.viscous_term != ViscousTerm::None ? scene.nu : 0.0;
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction("ondine::NFM::traction", nq, 2 * D);
  PassContext<D> c = sim.context(sim.levels().front());
  c.R = sim.R();  // with zones each SPH particle with its level's radius (WallForces.hpp), R the coarsest
  c.nu = nu;
  sim.scheme().wall_traction(c, traction);
  // several ranks: each wall point is counted by the rank that owns its cell (its
  // support is complete there: owned particles and halos)
  Kokkos::View<int*, MemSpace> counted("ondine::NFM::counted", nq);
  Kokkos::deep_copy(counted, 1);
  if (!sim.comm().serial()) {
    const auto orb = sim.domain().orb();
    const auto wx = walls.points().x;
    const auto box = sim.domain().box();
    const int me = sim.comm().rank();
    Kokkos::parallel_for("ondine::NFM::wall_point_owner", Kokkos::RangePolicy<ExecSpace>(0, nq), KOKKOS_LAMBDA(const int q) {
      Vec<D> xq;
      for (int k = 0; k < D; ++k) xq[k] = box.wrap(wx(q, k), k);
      counted(q) = orb.owner(xq) == me ? 1 : 0;
    });
  }
  for (int w = 0; w < walls.wall_count(); ++w) {
    WallForce f;
    f.name = walls.names()[w];
    for (int c = 0; c < 2 * D; ++c) {
      double v = 0;
      Kokkos::parallel_reduce("ondine::NFM::wall_force", Kokkos::RangePolicy<ExecSpace>(0, nq),
                              WallTractionSum{traction, walls.points().wall, counted, w, c}, v);
      (c < D ? f.pressure[c] : f.viscous[c - D]) = sim.comm().sum(v);
    }
    const Vec3& centre = scene.walls[static_cast<std::size_t>(w)].moment_centre;
    for (int k = D == 2 ? 2 : 0; k < 3; ++k) {
      double v = 0;
      Kokkos::parallel_reduce("ondine::NFM::wall_moment", Kokkos::RangePolicy<ExecSpace>(0, nq),
                              WallMomentSum<D>{traction, walls.points().x, walls.points().wall, counted, w, k,
                                               {centre[0], centre[1], centre[2]}},
                              v);
      f.moment[k] = sim.comm().sum(v);
    }
    out.push_back(f);
  }
  return out;
}

template <int D>
std::int64_t wall_leaks(const Simulation<D>& sim, double clearance) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  const Scene& scene = sim.scene();
  const WallModel<D>& walls = sim.walls();
  if (walls.empty()) return 0;
  long c = 0;
  Kokkos::parallel_reduce("ondine::NFM::leaks", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                          WallLeakCount<D>{fluid_region<D>(scene, walls, sim.domain().box()), clearance < 0 ? 0.1 * scene.dx : clearance, p.get(field::Position{})}, c);
  return sim.comm().sum(static_cast<std::int64_t>(c));
}

}  // namespace ondine
