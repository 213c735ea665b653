#pragma once
// Probes, wave gauges and the dam-break front (solver/Measures.hpp).
#include <cmath>

#include "kernels/ProbeSum.hpp"
#include "kernels/TimeStep.hpp"
#include "kernels/WaveGauge.hpp"
#include "solver/StepState.hpp"

namespace ondine {

template <int D>
std::vector<ProbeSample> sample_probes(const Simulation<D>& sim) {
  std::vector<Vec3> points;
  for (const Probe& pr : sim.scene().probes) points.push_back(pr.position);
  return sample_at(sim, points);
}

// Shepard interpolation at each point (thesis 2.40-2.41), by reductions over the owned
// particles: sum_j w_j W(x - x_j) f_j / sum_j w_j W(x - x_j); with refinement zones over
// the SPH particles only, each with its level's radius (apr::ProbeSum). One reduction per
// quantity: probes are sampled at output times only.
template <int D>
std::vector<ProbeSample> sample_at(const Simulation<D>& sim, const std::vector<Vec3>& points) {
  std::vector<ProbeSample> out;
  PassContext<D> c = sim.context(sim.levels().front());
  c.end = static_cast<int>(sim.size());  // every owned particle; with zones, guards are skipped inside
  c.R = sim.R();
  for (const Vec3& point : points) {
    Vec<D> xp;
    for (int k = 0; k < D; ++k) xp[k] = point[k];
    // what = 0: the Shepard sum, 1: pressure, 2: density, 3 + k: velocity k
    const auto sum = [&](int what) { return sim.comm().sum(sim.scheme().probe_sum(c, xp, what)); };
    ProbeSample s;
    s.shepard = sum(0);
    if (s.shepard > 0) {
      s.pressure = sum(1) / s.shepard;
      s.density = sum(2) / s.shepard;
      for (int k = 0; k < D; ++k) s.velocity[k] = sum(3 + k) / s.shepard;
    }
    out.push_back(s);
  }
  return out;
}

template <int D>
std::vector<double> wave_elevations(Simulation<D>& sim) {
  std::vector<double> out;
  const Scene& scene = sim.scene();
  if (scene.wave_gauges.empty()) return out;
  StepState<D> state(sim);
  state.ensure_lists();  // the particle cell list is current
  state.domain().refresh_state_halos(state.particles());
  const double step = 0.25 * (sim.refinement_on() ? sim.refinement().dx(sim.refinement().levels() - 1) : scene.dx);  // a quarter of the finest spacing
  PassContext<D> c = sim.context(sim.levels().front());
  c.end = static_cast<int>(sim.size());
  c.R = sim.R();  // with zones the coarsest radius: the cell list's reach
  for (const WaveGauge& g : scene.wave_gauges) {
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
    // with zones: SPH particles only, each with its level's radius (WaveGauge.hpp)
    sim.scheme().gauge_sums(c, pts, sum);
    std::vector<double> shepard(ns);
    Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(shepard.data(), ns), sum);
    sim.comm().sum_in_place(shepard);
    out.push_back(gauge_level(z.data(), shepard.data(), ns));
  }
  return out;
}

template <int D>
double front_position(const Simulation<D>& sim) {
  double xmax = -1e300;
  Kokkos::parallel_reduce("ondine::Front", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(sim.size())),
                          MaxComponent<D>{sim.particles().get(field::Position{}), 0}, Kokkos::Max<double>(xmax));
  return sim.comm().max(xmax) + 0.5 * sim.scene().dx;
}

}  // namespace ondine
