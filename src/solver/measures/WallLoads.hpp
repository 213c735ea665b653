#pragma once
// The loads of the fluid on the walls, and the particles that leaked through them
// (solver/Measures.hpp).
#include <algorithm>
#include <cmath>

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

// The traction of the fluid at the given points (the walls' quadrature points, or a wall
// sensor's sample points)
// state_only: the MUSCL state's pressure P_f in place of P_p (kernels/WallForces.hpp)
template <int D>
WallTractions<D> tractions_at(Simulation<D>& sim, const WallPoints<D>& points, bool state_only = false) {
  const Scene& scene = sim.scene();
  StepState<D> state(sim);
  state.ensure_lists();  // the particle cell list is current
  state.domain().refresh_state_halos(state.particles());
  const int nq = points.count;
  const double nu = scene.viscous_term != ViscousTerm::None ? scene.nu : 0.0;
  WallTractions<D> t{Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace>("ondine::NFM::traction", nq, 2 * D),
                     Kokkos::View<int*, MemSpace>("ondine::NFM::counted", nq)};
  PassContext<D> c = sim.context(sim.levels().front());
  // the wall shear of a turbulence model reads u_* or nu_T of the halo copies too (the owner's,
  // from the last stage)
  if (c.wall_shear == WallShear::LogLaw) state.domain().refresh(state.particles(), field::FrictionVelocity{});
  if (c.wall_shear == WallShear::Eddy) state.domain().refresh(state.particles(), field::EddyViscosity{});
  // ... and the MUSCL state (4.30) the owners' density gradient (and velocity gradient): the
  // output's migration on several ranks made new halo copies, which carry neither
  ParticleSet<D>& p = state.particles();
  if (p.has(field::DensityGradient{})) state.domain().refresh(p, field::DensityGradient{});
  if (c.velocity_muscl) {
    state.domain().refresh(p, field::VelocityGradientX{}, field::VelocityGradientY{});
    if constexpr (D == 3) state.domain().refresh(p, field::VelocityGradientZ{});
  }
  c.R = sim.R();  // with zones each SPH particle with its level's radius (WallForces.hpp), R the coarsest
  c.nu = nu;
  c.wall = points;
  c.wall_state_only = state_only;
  sim.scheme().wall_traction(c, t.traction);
  const auto counted = t.counted;
  Kokkos::deep_copy(counted, 1);
  if (!sim.comm().serial()) {
    const auto orb = sim.domain().orb();
    const auto wx = points.x;
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
WallTractions<D> wall_tractions(Simulation<D>& sim) {
  return tractions_at(sim, sim.walls().points());
}

// A sample point of a wall sensor's face: position, normal, area weight, the sensor's index.
template <int D>
struct WallSensorSample {
  Vec<D> x, n;
  double s;
  int sensor;
};

// The sample points of the wall sensors (Scene::WallSensor): per sensor an m x m grid (m
// points along a segment in 2D) at the centres of equal pieces of its face, m = size / (dx/4)
// rounded up, between 1 and 8, each weighted by its piece's area (1 for a point sensor).
template <int D>
std::vector<WallSensorSample<D>> wall_sensor_samples(const Scene& scene) {
  std::vector<WallSensorSample<D>> pts;
  for (std::size_t k = 0; k < scene.wall_sensors.size(); ++k) {
    const WallSensor& w = scene.wall_sensors[k];
    Vec<D> c, n, t1 = Vec<D>::zero(), t2 = Vec<D>::zero();
    for (int a = 0; a < D; ++a) c[a] = w.position[a], n[a] = w.normal[a];
    if constexpr (D == 2) {
      t1[0] = -n[1], t1[1] = n[0];
    } else {
      const auto cross = [](const Vec<D>& a, const Vec<D>& b) {
        return Vec<D>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      };
      int least = 0;  // the axis least aligned with n
      for (int a = 1; a < 3; ++a)
        if (std::abs(n[a]) < std::abs(n[least])) least = a;
      Vec<D> e = Vec<D>::zero();
      e[least] = 1.0;
      const Vec<D> a1 = cross(n, e);
      t1 = (1.0 / std::sqrt(norm2(a1))) * a1;
      t2 = cross(n, t1);
    }
    const int m = w.size > 0 ? std::clamp(static_cast<int>(std::ceil(w.size / (0.25 * scene.dx))), 1, 8) : 1;
    const double piece = w.size > 0 ? w.size / m : 0.0, s = w.size > 0 ? std::pow(piece, D - 1) : 1.0;
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < (D == 3 ? m : 1); ++b) {
        const double u = (a + 0.5) * piece - 0.5 * w.size, v = D == 3 ? (b + 0.5) * piece - 0.5 * w.size : 0.0;
        pts.push_back({c + u * t1 + v * t2, n, s, static_cast<int>(k)});
      }
  }
  return pts;
}

// The samples as wall points for WallTraction: the wall velocity zero, no viscous part
template <int D>
WallPoints<D> wall_points_of(const std::vector<WallSensorSample<D>>& pts) {
  const int nq = static_cast<int>(pts.size());
  WallPoints<D> p;
  p.count = nq;
  p.x = decltype(p.x)("ondine::WallSensor::x", nq);
  p.n_out = decltype(p.n_out)("ondine::WallSensor::n_out", nq);
  p.u = decltype(p.u)("ondine::WallSensor::u", nq);
  p.s = decltype(p.s)("ondine::WallSensor::s", nq);
  p.wall = decltype(p.wall)("ondine::WallSensor::sensor", nq);
  p.no_slip = decltype(p.no_slip)("ondine::WallSensor::no_slip", nq);  // 0: the pressure only
  auto hx = Kokkos::create_mirror_view(p.x);
  auto hn = Kokkos::create_mirror_view(p.n_out);
  auto hs = Kokkos::create_mirror_view(p.s);
  auto hw = Kokkos::create_mirror_view(p.wall);
  for (int q = 0; q < nq; ++q) {
    for (int a = 0; a < D; ++a) hx(q, a) = pts[q].x[a], hn(q, a) = pts[q].n[a];
    hs(q) = pts[q].s;
    hw(q) = pts[q].sensor;
  }
  Kokkos::deep_copy(p.x, hx);
  Kokkos::deep_copy(p.n_out, hn);
  Kokkos::deep_copy(p.s, hs);
  Kokkos::deep_copy(p.wall, hw);
  return p;
}

// The pressure of each wall sensor: sum_q s_q <P_f>_q / sum_q s_q over its sample points, P_f
// the MUSCL state's pressure at the wall (4.30)-(4.32) without the impedance term rho c u_n of
// (4.14) (kernels/WallForces.hpp, state_only, writes s_q <P_f>_q n_out), summed over the ranks
// that count them.
// A point with no particle within R reads 0 (a dry sensor).
template <int D>
std::vector<double> wall_sensor_pressures(Simulation<D>& sim) {
  const std::vector<WallSensorSample<D>> pts = wall_sensor_samples<D>(sim.scene());
  const int ns = static_cast<int>(sim.scene().wall_sensors.size());
  std::vector<double> load(ns, 0.0), area(ns, 0.0);
  if (pts.empty()) return load;
  const WallTractions<D> t = tractions_at(sim, wall_points_of(pts), true);
  const auto ht = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), t.traction);
  const auto hc = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), t.counted);
  for (std::size_t q = 0; q < pts.size(); ++q) {  // the sensors' few sample points, not particles
    area[pts[q].sensor] += pts[q].s;
    if (hc(q))
      for (int k = 0; k < D; ++k) load[pts[q].sensor] += ht(q, k) * pts[q].n[k];
  }
  sim.comm().sum_in_place(load);
  for (int k = 0; k < ns; ++k) load[k] = area[k] > 0 ? load[k] / area[k] : 0.0;
  return load;
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
                          WallLeakCount<D>{fluid_region<D>(scene, walls, sim.domain().box()), clearance < 0 ? 0.1 * scene.dx : clearance,
                                           p.get(field::Position{}),
                                           clearance < 0 && p.has(field::AprBirthLevel{}) ? p.get(field::AprBirthLevel{})
                                                                                           : field_view_t<field::AprBirthLevel, D>()},
                          c);
  return sim.comm().sum(static_cast<std::int64_t>(c));
}

}  // namespace ondine
