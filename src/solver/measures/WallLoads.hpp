#pragma once
// The loads of the fluid on the walls, and the particles that leaked through them
// (solver/Measures.hpp).
#include "kernels/FluidRegion.hpp"
#include "kernels/WallForces.hpp"
#include "solver/FluidRegionBuild.hpp"
#include "solver/StepState.hpp"

namespace ondine {

// The traction of every wall point (kernels/WallForces.hpp: pressure force, viscous force, s_q
// included) and whether this rank counts the point: on several ranks the rank that owns its
// cell (its support is complete there: owned particles and halos)
template <int D>
struct WallTractions {
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction;
  Kokkos::View<int*, MemSpace> counted;
};

template <int D>
WallTractions<D> wall_tractions(Simulation<D>& sim) {
  const Scene& scene = sim.scene();
  const WallModel<D>& walls = sim.walls();
  StepState<D> state(sim);
  state.ensure_lists();  // the particle cell list is current
  state.domain().refresh_state_halos(state.particles());
  const int nq = walls.points().count;
  const double nu = scene.viscous_term != ViscousTerm::None ? scene.nu : 0.0;
  WallTractions<D> t{Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace>("ondine::NFM::traction", nq, 2 * D),
                     Kokkos::View<int*, MemSpace>("ondine::NFM::counted", nq)};
  PassContext<D> c = sim.context(sim.levels().front());
  c.R = sim.R();  // with zones each SPH particle with its level's radius (WallForces.hpp), R the coarsest
  c.nu = nu;
  sim.scheme().wall_traction(c, t.traction);
  const auto counted = t.counted;
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
  return t;
}

template <int D>
std::vector<WallForce> wall_forces(Simulation<D>& sim) {
  const Scene& scene = sim.scene();
  const WallModel<D>& walls = sim.walls();
  std::vector<WallForce> out;
  if (walls.empty()) return out;
  const int nq = walls.points().count;
  const WallTractions<D> t = wall_tractions(sim);
  const auto traction = t.traction;
  const auto counted = t.counted;
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

// Each wall point's load (solver/Measures.hpp): the counting rank's values, summed over the ranks.
// P_p is the pressure force over s along n_out (WallTraction writes s <P_p> n_out).
template <int D>
WallLoadField wall_load_field(Simulation<D>& sim) {
  WallLoadField f;
  const WallModel<D>& walls = sim.walls();
  if (walls.empty()) return f;
  const int nq = walls.points().count;
  const WallTractions<D> t = wall_tractions(sim);
  Kokkos::View<double* [12], Kokkos::LayoutRight, MemSpace> packed("ondine::NFM::wall_load_field", nq);
  const auto traction = t.traction;
  const auto counted = t.counted;
  const WallPoints<D> wp = walls.points();
  Kokkos::parallel_for("ondine::NFM::wall_load_field", Kokkos::RangePolicy<ExecSpace>(0, nq), KOKKOS_LAMBDA(const int q) {
    const double s = wp.s(q), on = counted(q) && s > 0 ? 1.0 : 0.0, inv_s = s > 0 ? 1.0 / s : 0.0;
    double Pn = 0.0;
    for (int k = 0; k < 3; ++k) {
      packed(q, k) = k < D ? on * wp.x(q, k) : 0.0;
      packed(q, 3 + k) = k < D ? on * wp.n_out(q, k) : 0.0;
      packed(q, 7 + k) = k < D ? on * (traction(q, k) + traction(q, D + k)) * inv_s : 0.0;
      if (k < D) Pn += traction(q, k) * wp.n_out(q, k);
    }
    packed(q, 6) = on * Pn * inv_s;
    packed(q, 10) = on * s;
    packed(q, 11) = on * wp.wall(q);
  });
  std::vector<double> h(12 * static_cast<std::size_t>(nq));
  Kokkos::deep_copy(Kokkos::View<double* [12], Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(h.data(), nq), packed);
  sim.comm().sum_in_place(h);
  for (int q = 0; q < nq; ++q) {
    const double* r = &h[12 * static_cast<std::size_t>(q)];
    for (int k = 0; k < 3; ++k) {
      f.position.push_back(r[k]);
      f.normal.push_back(r[3 + k]);
      f.traction.push_back(r[7 + k]);
    }
    f.pressure.push_back(r[6]);
    f.area.push_back(r[10]);
    f.wall.push_back(r[11]);
  }
  return f;
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
