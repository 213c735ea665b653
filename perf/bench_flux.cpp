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
#include <map>
#include <sstream>
#include <random>
#include <string>
#include <vector>

#include "app/KernelProfile.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

using namespace ondine;
using Clock = std::chrono::steady_clock;

namespace {

// Bytes held by Views other than the neighbour list, from Kokkos' allocation
// callbacks; the time in neighbour-search kernels comes from the kernel profile
// of `ondine run --profile` (src/app/KernelProfile.hpp).
struct Instrument {
  static inline std::map<const void*, std::pair<std::string, uint64_t>> live;
  static void alloc(const Kokkos::Tools::SpaceHandle, const char* label, const void* ptr, const uint64_t size) {
    live[ptr] = {label, size};
  }
  static void dealloc(const Kokkos::Tools::SpaceHandle, const char*, const void* ptr, const uint64_t) { live.erase(ptr); }
  static double bytes_excluding_neighbour_list() {
    double b = 0;
    for (const auto& [ptr, v] : live)
      if (v.first.find("NeighbourList") == std::string::npos) b += static_cast<double>(v.second);
    return b;
  }
  static double search_seconds() { return kernel_seconds({"ondine::CellList", "ondine::NeighbourList"}); }
  static void install() {
    install_kernel_profile();
    namespace KT = Kokkos::Tools::Experimental;
    KT::set_allocate_data_callback(alloc);
    KT::set_deallocate_data_callback(dealloc);
  }
};

std::string box_yaml(int D, int per_side, double R_over_dx, const std::string& scheme, double skin) {
  std::ostringstream dx;
  dx.precision(17);
  dx << 1.0 / per_side;
  const std::string lo = D == 2 ? "[0, 0]" : "[0, 0, 0]", hi = D == 2 ? "[1, 1]" : "[1, 1, 1]";
  const std::string per = D == 2 ? "[true, true]" : "[true, true, true]";
  return "dimension: " + std::to_string(D) + "\ndomain: {min: " + lo + ", max: " + hi + ", periodic: " + per +
         "}\nfluid: {rho0: 1000, sound_speed: 10" +
         (scheme.find("viscous_term") != std::string::npos ? ", viscosity: 1.0e-3" : "") + "}\ndiscretisation: {dx: " + dx.str() +
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
  nlohmann::json j;
  j["case"] = name;
  j["dimension"] = D;
  j["R_over_dx"] = R_over_dx;
  j["scheme"] = scheme;
  j["backend"] = Kokkos::DefaultExecutionSpace::name();
  j["threads"] = Kokkos::DefaultExecutionSpace().concurrency();
  double n = 0, pairs = 0;
  {
    // force evaluations on a fixed list (a tiny skin: nothing moves, nothing is rebuilt)
    Simulation<D> sim(parse_case(box_yaml(D, per_side, R_over_dx, scheme, 0.01), name + ".yaml"));
    perturb(sim);
    sim.evaluate();
    n = static_cast<double>(sim.size());
    pairs = static_cast<double>(pair_count(sim));
    std::vector<double> t_eval;
    for (int r = 0; r < reps; ++r) {
      Kokkos::fence();
      const auto t0 = Clock::now();
      for (int e = 0; e < evals; ++e) sim.evaluate();
      Kokkos::fence();
      t_eval.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / evals);
    }
    j["particles"] = sim.size();
    j["neighbours_per_particle"] = pairs / n;
    j["evaluation_seconds_median"] = median(t_eval);
    j["pair_interactions_per_second"] = pairs / median(t_eval);
  }
  // full time steps (RK4: 4 evaluations per step) with the two neighbour strategies
  for (double skin : {0.0, 0.3}) {
    Instrument::live.clear();
    Simulation<D> s2(parse_case(box_yaml(D, per_side, R_over_dx, scheme, skin), name + ".yaml"));
    perturb(s2);
    s2.step(1.0);
    const double bytes = Instrument::bytes_excluding_neighbour_list() / n;
    std::vector<double> t_step, f_search;
    double wall = 0;
    for (int r = 0; r < reps; ++r) {
      Kokkos::fence();
      reset_kernel_profile();
      const auto t0 = Clock::now();
      for (int st = 0; st < steps; ++st) s2.step(1.0);
      Kokkos::fence();
      const double t = std::chrono::duration<double>(Clock::now() - t0).count();
      wall += t;
      t_step.push_back(t / steps);
      f_search.push_back(Instrument::search_seconds() / t);
    }
    const std::string key = skin == 0 ? "rebuild_every_evaluation" : "verlet_skin_0.3dx";
    j["strategies"][key] = {{"steps", steps * reps},
                            {"wall_seconds", wall},
                            {"step_seconds_median", median(t_step)},
                            {"particle_steps_per_second", n / median(t_step)},
                            {"neighbour_search_fraction_median", median(f_search)},
                            {"neighbour_builds", s2.domain().builds()},
                            {"bytes_per_particle", bytes}};
  }
  // headline figures: the default strategy (Verlet skin 0.3 dx)
  const auto& d = j["strategies"]["verlet_skin_0.3dx"];
  j["steps"] = d["steps"];
  j["wall_seconds"] = d["wall_seconds"];
  j["particle_steps_per_second"] = d["particle_steps_per_second"];
  j["bytes_per_particle"] = d["bytes_per_particle"];
  j["neighbour_search_fraction"] = d["neighbour_search_fraction_median"];
  std::fprintf(stderr, "%-24s N=%8.0f nb=%5.1f  eval %.4f s  %.3g pairs/s  %.3g particle-steps/s  %.0f B/particle  search %.0f%% (rebuild-every-eval: %.3g p-steps/s, search %.0f%%)\n",
               name.c_str(), n, pairs / n, j["evaluation_seconds_median"].get<double>(),
               j["pair_interactions_per_second"].get<double>(), d["particle_steps_per_second"].get<double>(),
               d["bytes_per_particle"].get<double>(), 100 * d["neighbour_search_fraction_median"].get<double>(),
               j["strategies"]["rebuild_every_evaluation"]["particle_steps_per_second"].get<double>(),
               100 * j["strategies"]["rebuild_every_evaluation"]["neighbour_search_fraction_median"].get<double>());
  std::printf("%s\n", j.dump().c_str());
  std::fflush(stdout);
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
    Instrument::install();
    const int reps = quick ? 2 : 3, evals = quick ? 3 : 5, steps = quick ? 2 : 3;
    const std::string minimal = "{time_integrator: rk4}";
    const std::string full = "{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.02, background_pressure: true}";
    const std::string pairbench = "{viscous_term: morris, delta_sph: 0.1}";
    nlohmann::json all;
    all["backend"] = Kokkos::DefaultExecutionSpace::name();
    all["threads"] = Kokkos::DefaultExecutionSpace().concurrency();
    auto& runs = all["runs"];
    // the yardstick configuration of shared/perf/pairbench.cpp: R = 4 dx, delta-SPH + Morris, 300^2
    runs.push_back(measure<2>("pairbench_like_2d", quick ? 100 : 300, 4.0, pairbench, reps, evals, steps));
    const std::vector<int> sides2 = quick ? std::vector<int>{100} : std::vector<int>{100, 316, 1000};
    const std::vector<int> sides3 = quick ? std::vector<int>{22} : std::vector<int>{22, 46, 79};
    for (int s2 : sides2) {
      runs.push_back(measure<2>("minimal_2d", s2, 3.0, minimal, reps, evals, steps));
      runs.push_back(measure<2>("full_2d", s2, 3.0, full, reps, evals, steps));
    }
    for (int s3 : sides3) {
      runs.push_back(measure<3>("minimal_3d", s3, 3.0, minimal, reps, evals, steps));
      runs.push_back(measure<3>("full_3d", s3, 3.0, full, reps, evals, steps));
    }
    // minimal against full at the same size (the last pair of each dimension)
    auto ratio = [&](int D) {
      double tmin = 0, tfull = 0;
      for (const auto& r : runs) {
        if (r["dimension"] != D) continue;
        if (r["case"].get<std::string>().rfind("minimal", 0) == 0) tmin = r["evaluation_seconds_median"];
        if (r["case"].get<std::string>().rfind("full", 0) == 0) tfull = r["evaluation_seconds_median"];
      }
      return tfull / tmin;
    };
    all["ratios"]["full_over_minimal_evaluation_time_2d"] = ratio(2);
    all["ratios"]["full_over_minimal_evaluation_time_3d"] = ratio(3);
    if (!out.empty()) std::ofstream(out) << all.dump(2) << "\n";
  }
  Kokkos::finalize();
  MPI_Finalize();
  return 0;
}
