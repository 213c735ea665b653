// Wave gauges (kernels/WaveGauge.hpp): the free-surface level where the Shepard
// sum along a vertical line falls through 1/2.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernels/WaveGauge.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

using namespace ondine;

TEST_CASE("The gauge level is where the sampled Shepard sum falls through 1/2", "[unit]") {
  // S(z) = 1 - z / 2 on [0, 1.5] crosses 1/2 at z = 1: linear between samples, exact
  double z[7], s[7];
  for (int k = 0; k < 7; ++k) {
    z[k] = 0.25 * k;
    s[k] = 1 - z[k] / 2;
  }
  CHECK(gauge_level(z, s, 7) == Approx(1.0).epsilon(1e-14));
  // a droplet above the surface does not count unless it fills half a support
  s[6] = 0.3;
  CHECK(gauge_level(z, s, 7) == Approx(1.0).epsilon(1e-14));
  s[6] = 0.3;
  s[5] = 0.7;  // a layer of fluid above a gap: the highest crossing is its surface
  CHECK(gauge_level(z, s, 7) == Approx(1.25 + 0.25 * 0.2 / 0.4).epsilon(1e-14));
  s[6] = 0.7;  // the line ends inside the fluid: its top
  CHECK(gauge_level(z, s, 7) == Approx(1.5).epsilon(1e-14));
}

// A tank with two still columns, 0.3 m and 0.6 m deep, a gauge over each.
const char* const two_columns = R"(
dimension: 2
domain: {min: [-0.05, -0.05], max: [1.05, 1.0]}
fluid: {rho0: 1000, sound_speed: 25}
discretisation: {dx: 0.02, R_over_dx: 3}
walls: [{name: tank, points: [[0, 0], [1, 0], [1, 0.9], [0, 0.9]], closed: true, fluid_side: inside, condition: slip}]
fluid_blocks: [{min: [0, 0], max: [0.5, 0.3], pressure: hydrostatic}, {min: [0.5, 0], max: [1, 0.6], pressure: hydrostatic}]
forces: {gravity: [0, -9.81]}
time: {duration: 1, output_interval: 1}
wave_gauges: [{name: low, position: [0.2], bottom: 0.05, top: 0.8}, {name: high, position: [0.8], bottom: 0.05, top: 0.8}]
)";

TEST_CASE("Wave gauges read the still-water levels of two columns", "[nfm]") {
  const double dx = 0.02;
  const Scene s = parse_case(two_columns, "gauges.yaml");
  Simulation<2> sim(s);
  const auto z = wave_elevations(sim);
  REQUIRE(z.size() == 2);
  // A half-filled support sums to 1/2 in the continuum; on the lattice the level is
  // within a small fraction of dx of the block top (measured: 0.004 dx).
  CHECK(std::abs(z[0] - 0.3) < 0.05 * dx);
  CHECK(std::abs(z[1] - 0.6) < 0.05 * dx);
}

// With a refinement zone around the low column's surface (its daughters on the fine
// lattice, dx_f = 0.01), the gauge reads the fine SPH particles at the fine radius:
// within 0.05 dx_f of the block top, as a uniform fine run. Summing mothers (guards
// inside the zone) and daughters together at the coarse radius, as the gauge did before,
// reads 0.3105 m: 1.05 dx_f high.
TEST_CASE("Wave gauges with refinement zones read the SPH particles of each level", "[nfm][apr]") {
  const double dx_f = 0.01;
  const Scene s = parse_case(std::string(two_columns) + "refinement: {zones: [{name: surface, min: [0.1, 0.2], max: [0.3, 0.4]}]}\n",
                             "gauges_apr.yaml");
  Simulation<2> sim(s);
  REQUIRE(sim.refinement().refined() > 0);
  const auto z = wave_elevations(sim);
  REQUIRE(z.size() == 2);
  std::printf("wave gauges with a zone: low %.6f m (block top 0.3), high %.6f m (0.6)\n", z[0], z[1]);
  CHECK(std::abs(z[0] - 0.3) < 0.05 * dx_f);
  CHECK(std::abs(z[1] - 0.6) < 0.05 * 0.02);
}

TEST_CASE("A wave gauge outside the domain or without gravity is refused", "[case]") {
  const std::string base = R"(
dimension: 2
domain: {min: [0, 0], max: [1, 1]}
fluid: {rho0: 1000, sound_speed: 25}
discretisation: {dx: 0.02}
fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]
time: {duration: 1, output_interval: 1}
)";
  CHECK_THROWS_WITH(parse_case(base + "forces: {gravity: [0, -9.81]}\nwave_gauges: [{name: g, position: [2.0], bottom: 0, top: 1}]\n", "g.yaml"),
                    Catch::Contains("wave_gauges[0].position") && Catch::Contains("outside the domain"));
  CHECK_THROWS_WITH(parse_case(base + "wave_gauges: [{name: g, position: [0.5], bottom: 0, top: 1}]\n", "g.yaml"),
                    Catch::Contains("need gravity"));
  CHECK_THROWS_WITH(parse_case(base + "forces: {gravity: [0, -9.81]}\nwave_gauges: [{name: g, position: [0.5], bottom: 1, top: 0}]\n", "g.yaml"),
                    Catch::Contains("top > bottom"));
}
