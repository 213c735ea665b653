#pragma once
#include <random>
#include <string>

#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

namespace ondine::test {

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

}  // namespace ondine::test
