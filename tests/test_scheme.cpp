// Weakly-compressible scheme: conservation laws, exactness of the renormalised
// gradient, and the time integrators against exact solutions.
#include <catch2/catch.hpp>

#include <cmath>

#include "observers/ErrorNorms.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using namespace ondine::test;

namespace {

// sum_i m_i du_i, and sum_i |m_i du_i| as its scale
template <int D>
std::pair<double, double> net_force(const Simulation<D>& sim) {
  const auto& p = sim.particles();
  const auto m = p.get(field::Mass{});
  const auto du = p.get(field::Acceleration{});
  double worst = 0, scale = 0;
  for (int k = 0; k < D; ++k) {
    double s = 0, a = 0;
    Kokkos::parallel_reduce(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i, double& acc) { acc += m(i) * du(i, k); }, s);
    Kokkos::parallel_reduce(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i, double& acc) { acc += (m(i) * du(i, k) < 0 ? -m(i) * du(i, k) : m(i) * du(i, k)); }, a);
    worst = std::max(worst, std::abs(s));
    scale += a;
  }
  return {worst, scale};
}

template <int D>
void check_conservation(const std::string& scheme, const std::string& extra = "") {
  const double L = D == 2 ? 0.5 : 0.25;
  const double dx = D == 2 ? 0.02 : 0.025;
  Simulation<D> sim(periodic_box(D, L, dx, scheme, ", viscosity: 1.0e-2", extra));
  disorder(sim, 0.2, 0.5, 0.01, 42);
  sim.evaluate();
  const auto [net, scale] = net_force(sim);
  INFO("scheme " << scheme << ": |sum m du| = " << net << ", sum |m du| = " << scale);
  REQUIRE(scale > 0);
  CHECK(net / scale < 1e-14);  // antisymmetric pair terms: round-off only

  const Diagnostics d0 = diagnostics(sim);
  for (int s = 0; s < 10; ++s) sim.step(1.0);
  const Diagnostics d1 = diagnostics(sim);
  CHECK(d1.mass == d0.mass);  // masses never change
  double p_scale = 0;
  for (int k = 0; k < D; ++k) p_scale += d0.mass * 0.5;  // sum m |u| bound: speeds up to 0.5
  for (int k = 0; k < D; ++k) CHECK(std::abs(d1.momentum[k] - d0.momentum[k]) / p_scale < 1e-13);
}

}  // namespace

TEST_CASE("Linear momentum is conserved to round-off in a periodic box (2D)", "[scheme][conservation]") {
  check_conservation<2>("{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.05}");
  check_conservation<2>("{viscous_term: monaghan_gingold, background_pressure: true}");
  check_conservation<2>("{viscous_term: morris, time_integrator: predictor_corrector}");
  check_conservation<2>("{flux: riemann, viscous_term: morris}");
  // the eddy viscosity nu_T,i differs from particle to particle: the Morris form stays antisymmetric
  check_conservation<2>("{viscous_term: morris, delta_sph: 0.1}", "turbulence: {model: smagorinsky, smagorinsky_constant: 1.0}\n");
  check_conservation<2>("{flux: riemann, riemann: {reconstruction: none}, viscous_term: monaghan_gingold, artificial_viscosity: 0.05}");
}

TEST_CASE("Linear momentum is conserved to round-off in a periodic box (3D)", "[scheme][conservation]") {
  check_conservation<3>("{viscous_term: monaghan_gingold, delta_sph: 0.1, artificial_viscosity: 0.05}");
  check_conservation<3>("{flux: riemann, viscous_term: monaghan_gingold}");
  check_conservation<3>("{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.05}",
                        "turbulence: {model: mixing_length, mixing_length: {length: 0.05}}\n");
}

TEST_CASE("The renormalised density gradient is exact for a linear field", "[unit][scheme]") {
  // Open domain; particles farther than R from the block faces have a full support.
  const std::string y = R"(dimension: 2
domain: {min: [0, 0], max: [1, 1]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.04}
fluid_blocks: [{min: [0, 0], max: [1, 1]}]
scheme: {delta_sph: 0.1}
time: {duration: 1, output_interval: 1})";
  Simulation<2> sim(parse_case(y, "t.yaml"));
  disorder(sim, 0.25, 0.0, 0.0, 3);
  auto& p = sim.particles();
  const auto x = p.get(field::Position{});
  const auto rho = p.get(field::Density{});
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) { rho(i) = 1000 + 3.0 * x(i, 0) - 7.0 * x(i, 1); });
  sim.evaluate();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
  auto hg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::DensityGradient{}));
  const double R = sim.scene().R();
  int interior = 0;
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (hx(i, 0) < R || hx(i, 0) > 1 - R || hx(i, 1) < R || hx(i, 1) > 1 - R) continue;
    ++interior;
    worst = std::max({worst, std::abs(hg(i, 0) - 3.0), std::abs(hg(i, 1) + 7.0)});
  }
  CHECK(interior > 100);
  CHECK(worst < 1e-10);
}

TEST_CASE("A fluid block in free fall follows x = x0 + g t^2 / 2 (RK4 and midpoint)", "[scheme][integrator]") {
  for (const char* integ : {"rk4", "predictor_corrector"}) {
    Scene s = periodic_box(2, 0.4, 0.02, std::string("{time_integrator: ") + integ + "}", "",
                           "forces: {gravity: [0.0, -9.81]}\n");
    Simulation<2> sim(s);
    const Diagnostics d0 = diagnostics(sim);
    while (sim.time() < 0.05) sim.step(0.05);
    const Diagnostics d1 = diagnostics(sim);
    // internal forces cancel; the centre of mass velocity is g t
    CHECK(d1.momentum[1] / d1.mass == Approx(-9.81 * sim.time()).epsilon(1e-12));
    CHECK(std::abs(d1.momentum[0]) / d1.mass < 1e-12);
    CHECK(reference_errors(sim).at("momentum_balance_error") < 1e-12);
    CHECK(d1.mass == d0.mass);
  }
}

TEST_CASE("A still periodic box stays still for 1000 steps", "[scheme][still]") {
  Simulation<2> sim(periodic_box(2, 0.3, 0.02, "{viscous_term: morris, delta_sph: 0.1, time_integrator: predictor_corrector}",
                                 ", viscosity: 1.0e-3"));
  for (int s = 0; s < 1000; ++s) sim.step(1e9);
  CHECK(sim.steps() == 1000);
  CHECK(diagnostics(sim).max_speed < 1e-10);
}

TEST_CASE("A 3D periodic disordered flow decays without blowing up and conserves momentum", "[scheme][conservation]") {
  Simulation<3> sim(periodic_box(3, 0.25, 0.025, "{viscous_term: morris, delta_sph: 0.1}", ", viscosity: 1.0e-2"));
  disorder(sim, 0.1, 0.2, 0.0, 11);
  const Diagnostics d0 = diagnostics(sim);
  // kinetic energy trades with the compression energy of the weakly compressible
  // fluid step to step, so it is not monotone; it must never exceed its start
  // by more than that exchange and must fall overall.
  double ke_prev = d0.kinetic_energy, ke_max = 0;
  for (int s = 0; s < 40; ++s) {
    sim.step(1e9);
    const Diagnostics d = diagnostics(sim);
    REQUIRE(d.finite);
    ke_prev = d.kinetic_energy;
    ke_max = std::max(ke_max, ke_prev);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(d.momentum[k] - d0.momentum[k]) < 1e-12 * d0.mass * 0.2);
  }
  CHECK(ke_max < 1.05 * d0.kinetic_energy);
  CHECK(ke_prev < 0.5 * d0.kinetic_energy);
  CHECK(diagnostics(sim).rho_max < 1.01 * 1000);
}
