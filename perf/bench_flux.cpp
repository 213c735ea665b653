// Throughput of the solver core on the OpenMP backend: force evaluations and
// full time steps for a minimal and a full scheme, 2D and 3D, and the two
// neighbour strategies (list rebuilt every evaluation vs a Verlet skin).
// Prints one JSON object; medians over repetitions. Usage:
//   ondine_bench [--quick] [--out FILE]
#include <Kokkos_Core.hpp>
#include <mpi.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

using namespace ondine;
using Clock = std::chrono::steady_clock;

namespace {

std::string box_yaml(int D, int per_side, double R_over_dx, const std::string& scheme, double skin) {
  const double dx = 1.0 / per_side;
  const std::string lo = D == 2 ? "[0, 0]" : "[0, 0, 0]", hi = D == 2 ? "[1, 1]" : "[1, 1, 1]";
  const std::string per = D == 2 ? "[true, true]" : "[true, true, true]";
  return "dimension: " + std::to_string(D) + "\ndomain: {min: " + lo + ", max: " + hi + ", periodic: " + per +
         "}\nfluid: {rho0: 1000, sound_speed: 10" +
         (scheme.find("viscous_term") != std::string::npos ? ", viscosity: 1.0e-3" : "") + "}\ndiscretisation: {dx: " + std::to_string(dx) +
         ", R_over_dx: " + std::to_string(R_over_dx) + ", neighbour_skin: " + std::to_string(skin) +
         "}\nfluid_blocks: [{min: " + lo + ", max: " + hi + "}]\nscheme: " + scheme +
         "\ntime: {duration: 1, output_interval: 1}\n";
}

// Same initial disorder as shared/perf/pairbench.cpp: 5 % jitter, smooth velocity field.
template <int D>
void perturb(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Velocity{}));
  std::mt19937 g(1);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  const double dx = sim.scene().dx;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < D; ++k) hx(i, k) += d(g) * dx;
    hu(i, 0) = 0.1 * std::sin(6.28 * hx(i, 0));
    hu(i, 1) = -0.1 * std::cos(6.28 * hx(i, 1));
  }
  Kokkos::deep_copy(p.get(field::Position{}), hx);
  Kokkos::deep_copy(p.get(field::Velocity{}), hu);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <int D>
nlohmann::json measure(const std::string& name, int per_side, double R_over_dx, const std::string& scheme, int reps,
                       int evals, int steps) {
  // evaluations with a fixed list (a tiny skin: nothing moves, so nothing is rebuilt)
  Simulation<D> sim(parse_case(box_yaml(D, per_side, R_over_dx, scheme, 0.01), name + ".yaml"));
  perturb(sim);
  sim.evaluate();
  const double pairs = static_cast<double>(sim.pair_count());
  std::vector<double> t_eval;
  for (int r = 0; r < reps; ++r) {
    Kokkos::fence();
    const auto t0 = Clock::now();
    for (int e = 0; e < evals; ++e) sim.evaluate();
    Kokkos::fence();
    t_eval.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / evals);
  }
  const double n = static_cast<double>(sim.size());
  nlohmann::json j;
  j["case"] = name;
  j["dimension"] = D;
  j["particles"] = sim.size();
  j["R_over_dx"] = R_over_dx;
  j["scheme"] = scheme;
  j["neighbours_per_particle"] = pairs / n;
  j["evaluation_seconds_median"] = median(t_eval);
  j["pair_interactions_per_second"] = pairs / median(t_eval);
  j["particle_evaluations_per_second"] = n / median(t_eval);
  // full time steps (RK4 = 4 evaluations), two neighbour strategies
  for (double skin : {0.0, 0.3}) {
    Simulation<D> s2(parse_case(box_yaml(D, per_side, R_over_dx, scheme, skin), name + ".yaml"));
    perturb(s2);
    s2.step(1.0);
    std::vector<double> t_step;
    for (int r = 0; r < reps; ++r) {
      Kokkos::fence();
      const auto t0 = Clock::now();
      for (int s = 0; s < steps; ++s) s2.step(1.0);
      Kokkos::fence();
      t_step.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / steps);
    }
    const std::string key = skin == 0 ? "rebuild_every_evaluation" : "verlet_skin_0.3dx";
    j["steps"][key] = {{"step_seconds_median", median(t_step)},
                       {"particle_steps_per_second", n / median(t_step)},
                       {"neighbour_builds", s2.neighbour_builds()},
                       {"steps_taken", s2.steps()}};
  }
  std::fprintf(stderr, "%-28s N=%8.0f nb=%5.1f  eval %.4f s  %.3g pairs/s  %.3g particle-steps/s (skin 0.3dx)\n",
               name.c_str(), n, pairs / n, median(t_eval), pairs / median(t_eval),
               j["steps"]["verlet_skin_0.3dx"]["particle_steps_per_second"].get<double>());
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  Kokkos::initialize(argc, argv);
  {
    bool quick = false;
    std::string out;
    for (int a = 1; a < argc; ++a) {
      const std::string s = argv[a];
      if (s == "--quick") quick = true;
      else if (s == "--out" && a + 1 < argc) out = argv[++a];
    }
    const int reps = quick ? 3 : 5, evals = quick ? 3 : 10, steps = quick ? 2 : 5;
    const std::string minimal = "{time_integrator: rk4}";
    const std::string full = "{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.02, background_pressure: true}";
    const std::string pairbench = "{viscous_term: morris, delta_sph: 0.1}";
    const int s2 = quick ? 100 : 316, s3 = quick ? 22 : 46, spb = quick ? 100 : 300;
    nlohmann::json j;
    j["backend"] = Kokkos::DefaultExecutionSpace::name();
    j["threads"] = Kokkos::DefaultExecutionSpace().concurrency();
    j["runs"].push_back(measure<2>("minimal_2d", s2, 3.0, minimal, reps, evals, steps));
    j["runs"].push_back(measure<2>("full_2d", s2, 3.0, full, reps, evals, steps));
    j["runs"].push_back(measure<2>("pairbench_like_2d_R4dx", spb, 4.0, pairbench, reps, evals, steps));
    j["runs"].push_back(measure<3>("minimal_3d", s3, 3.0, minimal, reps, evals, steps));
    j["runs"].push_back(measure<3>("full_3d", s3, 3.0, full, reps, evals, steps));
    const auto& r = j["runs"];
    j["ratios"]["full_over_minimal_evaluation_time_2d"] =
        r[1]["evaluation_seconds_median"].get<double>() / r[0]["evaluation_seconds_median"].get<double>();
    j["ratios"]["full_over_minimal_evaluation_time_3d"] =
        r[4]["evaluation_seconds_median"].get<double>() / r[3]["evaluation_seconds_median"].get<double>();
    const std::string text = j.dump(2) + "\n";
    if (out.empty()) std::printf("%s", text.c_str());
    else std::ofstream(out) << text;
  }
  Kokkos::finalize();
  MPI_Finalize();
  return 0;
}
