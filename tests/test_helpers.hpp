#pragma once
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "scene/CaseError.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

namespace ondine::test {

// The message with which the parser refuses cases/<file> with these --set overrides, or
// "accepted" where it takes them.
inline std::string case_refusal(const std::string& file, const std::vector<std::string>& sets) {
  try {
    load_case(std::string(ONDINE_SOURCE_DIR) + "/cases/" + file, sets);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "accepted";
}

// A periodic box of fluid, dimension D, side L, spacing dx, with the scheme given as YAML.
inline Scene periodic_box(int D, double L, double dx, const std::string& scheme, const std::string& fluid_extra = "",
                          const std::string& forces = "") {
  const std::string v = D == 2 ? "[%, %]" : "[%, %, %]";
  auto vec = [&](double a) {
    std::string s = v;
    for (std::size_t p; (p = s.find('%')) != std::string::npos;) s.replace(p, 1, std::to_string(a));
    return s;
  };
  const std::string per = D == 2 ? "[true, true]" : "[true, true, true]";
  std::string y = "dimension: " + std::to_string(D) + "\ndomain: {min: " + vec(0) + ", max: " + vec(L) +
                  ", periodic: " + per + "}\nfluid: {rho0: 1000, sound_speed: 10" + fluid_extra +
                  "}\ndiscretisation: {dx: " + std::to_string(dx) + "}\nfluid_blocks: [{min: " + vec(0) +
                  ", max: " + vec(L) + "}]\nscheme: " + scheme + "\n" + forces + "time: {duration: 1, output_interval: 1}\n";
  return parse_case(y, "test.yaml");
}

// Jitters positions by up to `amp` dx and gives random velocities and densities.
template <int D>
void disorder(Simulation<D>& sim, double amp, double speed, double rho_jitter, unsigned seed) {
  auto& p = sim.particles();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Velocity{}));
  auto hr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Density{}));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> s(-1, 1);
  const double dx = sim.scene().dx;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      hx(i, k) += amp * dx * s(rng);
      hu(i, k) = speed * s(rng);
    }
    hr(i) *= 1.0 + rho_jitter * s(rng);
  }
  Kokkos::deep_copy(p.get(field::Position{}), hx);
  Kokkos::deep_copy(p.get(field::Velocity{}), hu);
  Kokkos::deep_copy(p.get(field::Density{}), hr);
}

// The particles' fields a refinement test reads, copied to the host.
template <int D>
struct AprHostState {
  Kokkos::View<double* [D], Kokkos::LayoutLeft, Kokkos::HostSpace> x, u;
  Kokkos::View<double*, Kokkos::HostSpace> rho, P, m;
  Kokkos::View<int*, Kokkos::HostSpace> guard, birth, mother;
  Kokkos::View<std::int64_t*, Kokkos::HostSpace> parent;
};

template <int D>
AprHostState<D> apr_host_state(const Simulation<D>& sim) {
  const auto& p = sim.particles();
  auto host = [](const auto& v) { return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v); };
  AprHostState<D> h;
  h.x = host(p.get(field::Position{}));
  h.u = host(p.get(field::Velocity{}));
  h.rho = host(p.get(field::Density{}));
  h.P = host(p.get(field::Pressure{}));
  h.m = host(p.get(field::Mass{}));
  h.guard = host(p.get(field::AprGuard{}));
  h.birth = host(p.get(field::AprBirthLevel{}));
  h.mother = host(p.get(field::AprMother{}));
  h.parent = host(p.get(field::AprParent{}));
  return h;
}

// The surge front (T, Z) = (t sqrt(2 g / a), x_front / a) of the Martin & Moyce dam break
// (cases/dam_break_2d.yaml, a = 0.05715 m), sampled every 5 ms to t = 0.17 s (T = 3.1); the
// simulation is left at t = 0.17 s.
inline std::vector<std::pair<double, double>> dam_break_front(Simulation<2>& sim) {
  const double a = 0.05715, g = 9.81;
  std::vector<std::pair<double, double>> front;
  for (int k = 0; k <= 34; ++k) {
    const double t = 0.005 * k;
    while (sim.time() < t * (1 - 1e-12)) sim.step(t);
    front.emplace_back(t * std::sqrt(2 * g / a), front_position(sim) / a);
  }
  return front;
}

// The same with the given --set overrides of cases/dam_break_2d.yaml.
inline std::vector<std::pair<double, double>> dam_break_front(const std::vector<std::string>& sets) {
  Simulation<2> sim(load_case(std::string(ONDINE_SOURCE_DIR) + "/cases/dam_break_2d.yaml", sets));
  return dam_break_front(sim);
}

}  // namespace ondine::test
