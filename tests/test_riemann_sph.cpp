// Riemann-SPH of Leduc et al. (thesis 2.90-2.101) with the acoustic solver (2.100) and MUSCL
// reconstruction with minmod (2.78)-(2.83): the pieces against their defining properties, the
// velocity gradient against a linear field, and the scheme against the dam-break experiment.
// (Momentum conservation to round-off: tests/test_scheme.cpp, with the other schemes.)
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "kernels/terms/RiemannLeduc.hpp"
#include "observers/ErrorNorms.hpp"
#include "reference/References.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using Catch::Matchers::Contains;

namespace {
const std::string src = ONDINE_SOURCE_DIR;
const std::vector<std::string> riemann = {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage",
                                          "scheme.cfl.acoustic=0.5"};
}  // namespace

TEST_CASE("MUSCL with minmod (2.83): exact on a linear field, no new extremum", "[unit][riemann]") {
  // a linear field phi = 2 + 3 s along the pair, particles at s = 0 and s = 1: slopes 3, midpoint 3.5
  CHECK(muscl_midpoint(2.0, 5.0, 0.5 * 3.0) == Approx(3.5).epsilon(1e-15));
  CHECK(muscl_midpoint(5.0, 2.0, -0.5 * 3.0) == Approx(3.5).epsilon(1e-15));
  CHECK(muscl_midpoint(4.0, 4.0, 7.0) == 4.0);  // no jump: the particle's value
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> U(-10.0, 10.0);
  for (int k = 0; k < 100000; ++k) {
    const double a = U(gen), b = U(gen), sa = U(gen), sb = U(gen);
    const double ha = muscl_midpoint(a, b, sa), hb = muscl_midpoint(b, a, sb);
    // each state between the pair's two values (to round-off: phi_i + (phi_j - phi_i) and phi_j
    // may differ in the last bit)
    const double eps = 1e-14 * 10.0;
    REQUIRE(std::min(a, b) - eps <= ha);
    REQUIRE(ha <= std::max(a, b) + eps);
    REQUIRE(std::min(a, b) - eps <= hb);
    REQUIRE(hb <= std::max(a, b) + eps);
  }
  // a jump (steep slopes on both sides): each state at most the other side's value
  CHECK(muscl_midpoint(0.0, 1.0, 5.0) == 1.0);
  CHECK(muscl_midpoint(1.0, 0.0, -5.0) == 0.0);
  // a slope against the jump (an extremum at i): first order
  CHECK(muscl_midpoint(0.0, 1.0, -0.2) == 0.0);
}

TEST_CASE("The acoustic Riemann solver (2.100): identical states, mirror symmetry, the impedance relation", "[unit][riemann]") {
  const double Z = 1000.0 * 15.0;
  // identical states: the state itself
  const AcousticRiemann same = acoustic_riemann(Z, 0.3, 2000.0, Z, 0.3, 2000.0);
  CHECK(same.u == Approx(0.3).epsilon(1e-15));
  CHECK(same.P == Approx(2000.0).epsilon(1e-15));
  // mirror: swapping the sides and the axis flips u_E and keeps P_E
  const AcousticRiemann a = acoustic_riemann(1.1 * Z, 0.7, 3000.0, 0.9 * Z, -0.2, 1000.0);
  const AcousticRiemann b = acoustic_riemann(0.9 * Z, 0.2, 1000.0, 1.1 * Z, -0.7, 3000.0);
  CHECK(b.u == Approx(-a.u).epsilon(1e-14));
  CHECK(b.P == Approx(a.P).epsilon(1e-14));
  // two streams meeting at +-U in a fluid at rest pressure: P_E = P + Z U (the acoustic
  // impedance relation of a linear wave), u_E = 0
  const AcousticRiemann c = acoustic_riemann(Z, 0.1, 500.0, Z, -0.1, 500.0);
  CHECK(c.u == Approx(0.0).margin(1e-15));
  CHECK(c.P == Approx(500.0 + Z * 0.1).epsilon(1e-14));
  // a pressure jump at rest: u_E = (P_L - P_R) / (2 Z), P_E the mean
  const AcousticRiemann d = acoustic_riemann(Z, 0.0, 1500.0, Z, 0.0, 500.0);
  CHECK(d.u == Approx(1000.0 / (2 * Z)).epsilon(1e-14));
  CHECK(d.P == Approx(1000.0).epsilon(1e-14));
}

TEST_CASE("The low-dissipation pressure: its dissipation vanishes for a separating pair and is capped at c", "[unit][riemann]") {
  const double rho = 1000, c = 15, P = 700;
  // separating (U_L < U_R): P_E is the impedance-weighted mean, no dissipation
  CHECK(low_dissipation_riemann(rho, c, -0.2, P, rho, c, 0.2, P, 3.0).P == Approx(P).epsilon(1e-15));
  // closing slowly: (1/2) rho eta dU^2
  const double dU = 0.1;
  CHECK(low_dissipation_riemann(rho, c, dU / 2, P, rho, c, -dU / 2, P, 3.0).P == Approx(P + 0.5 * rho * 3.0 * dU * dU).epsilon(1e-14));
  // closing fast (eta dU > c): the acoustic value of (2.100), P + rho c dU / 2
  CHECK(low_dissipation_riemann(rho, c, 5.0, P, rho, c, -5.0, P, 3.0).P ==
        Approx(acoustic_riemann(rho * c, 5.0, P, rho * c, -5.0, P).P).epsilon(1e-14));
  // u_E is (2.100)'s
  CHECK(low_dissipation_riemann(rho, c, 0.3, 900, 1.01 * rho, c, -0.1, 400, 3.0).u ==
        Approx(acoustic_riemann(rho * c, 0.3, 900, 1.01 * rho * c, -0.1, 400).u).epsilon(1e-15));
}

TEST_CASE("Riemann-SPH Taylor-Green (25 x 25, Re = 100): the low-dissipation pressure keeps the vortex", "[riemann][case]") {
  // velocity L2 error at t = 0.5 s against the analytic decay; ondine validate's bound is 0.05
  // (delta-SPH with shifting: 0.018). The acoustic pressure of (2.100) damps the vortex through
  // rho c (U_L - U_R) / 2 at every pair (measured 0.14 with MUSCL).
  auto velocity_l2 = [](const std::string& dissipation) {
    Simulation<2> sim(load_case(src + "/cases/taylor_green_2d.yaml", {"discretisation.dx=0.04", "scheme.flux=riemann", "scheme.delta_sph=0",
                                                                      "scheme.riemann.dissipation=" + dissipation}));
    while (sim.time() < 0.5 * (1 - 1e-12)) sim.step(0.5);
    return reference_errors(sim).at("velocity_l2");
  };
  const double low = velocity_l2("low"), acoustic = velocity_l2("acoustic");
  INFO("velocity L2: low " << low << ", acoustic " << acoustic);
  CHECK(low < 0.05);
  CHECK(acoustic > 0.1);
}

TEST_CASE("The renormalised velocity gradient of the MUSCL reconstruction is exact for a linear field", "[unit][riemann]") {
  const std::string y = R"(dimension: 2
domain: {min: [0, 0], max: [1, 1]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.04}
fluid_blocks: [{min: [0, 0], max: [1, 1]}]
scheme: {flux: riemann}
time: {duration: 1, output_interval: 1})";
  Simulation<2> sim(parse_case(y, "t.yaml"));
  test::disorder(sim, 0.25, 0.0, 0.0, 3);
  auto& p = sim.particles();
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
    u(i, 0) = 0.5 + 2.0 * x(i, 0) - 3.0 * x(i, 1);
    u(i, 1) = -1.0 + 4.0 * x(i, 0) + 5.0 * x(i, 1);
  });
  sim.evaluate();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
  auto g0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::VelocityGradientX{}));
  auto g1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::VelocityGradientY{}));
  int checked = 0;
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // every particle, the block's edges included: the renormalisation makes the operator exact
    // for linear fields whatever the support (M_i is singular nowhere here)
    ++checked;
    worst = std::max({worst, std::abs(g0(i, 0) - 2.0), std::abs(g0(i, 1) + 3.0), std::abs(g1(i, 0) - 4.0), std::abs(g1(i, 1) - 5.0)});
  }
  CHECK(checked > 500);
  CHECK(worst < 1e-9);
}

TEST_CASE("Riemann-SPH dam break (a/25): the surge front against Martin & Moyce, no leak", "[riemann][case][dam_break]") {
  // the same bounds as the delta-SPH case (tests/test_nfm_cases.cpp): 20 % for T <= 3, speed 10 %
  Simulation<2> sim(load_case(src + "/cases/dam_break_2d.yaml", [] {
    auto s = riemann;
    s.push_back("discretisation.dx=0.002286");
    return s;
  }()));
  const auto front = test::dam_break_front(sim);
  const auto e = reference::martin_moyce_errors(front);
  INFO("front max relative error " << e.at("front_max_relative_error") << ", speed error " << e.at("front_speed_relative_error"));
  CHECK(e.at("front_max_relative_error") < 0.20);
  CHECK(e.at("front_speed_relative_error") < 0.10);
  CHECK(wall_leaks(sim, 0.0) == 0);
}

TEST_CASE("scheme.flux: riemann refuses delta-SPH, the renormalised continuity, a held gradient and refinement zones", "[unit][case]") {
  const auto refused = [](const std::string& file, const std::vector<std::string>& sets, const std::string& key) {
    CHECK_THAT(test::case_refusal(file, sets), Contains(key));
  };
  refused("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.density_gradient=stage"}, "scheme.delta_sph");
  refused("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0"}, "scheme.density_gradient");
  refused("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage",
                                "scheme.renormalised_continuity=true"},
          "scheme.renormalised_continuity");
  refused("dam_break_apr_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0"}, "refinement");
  refused("dam_break_2d.yaml", {"scheme.flux=upwind"}, "scheme.flux");
  refused("dam_break_2d.yaml", {"scheme.riemann.reconstruction=muscl"}, "scheme.riemann");
  refused("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage", "scheme.riemann.limiter=superbee"},
          "scheme.riemann.limiter");
  refused("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage", "scheme.riemann.dissipation=none"},
          "scheme.riemann.dissipation");
  // first order holds no gradient, so the held gradient is accepted there
  CHECK_NOTHROW(load_case(src + "/cases/dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.riemann.reconstruction=none"}));
}
