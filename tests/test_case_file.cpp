// Case-file parsing: a good file, and each kind of bad input with the message
// that names the file, the line and the key.
#include <catch2/catch.hpp>

#include <filesystem>

#include "scene/CaseFile.hpp"
#include "scene/FluxSchemes.hpp"

using namespace ondine;
using Catch::Matchers::Contains;

namespace {

const std::string good = R"(name: box
dimension: 2
domain:
  min: [0.0, 0.0]
  max: [1.0, 1.0]
  periodic: [true, true]
fluid:
  rho0: 1000.0
  sound_speed: auto
  mach: 0.1
  viscosity: 1.0e-3
discretisation:
  dx: 0.02
  kernel: wendland_c2
  R_over_dx: 3.0
fluid_blocks:
  - min: [0.0, 0.0]
    max: [1.0, 0.5]
    velocity: [0.5, 0.0]
forces:
  gravity: [0.0, -9.81]
scheme:
  viscous_term: morris
  delta_sph: 0.1
time:
  duration: 0.5
  output_interval: 0.1
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  REQUIRE(p != std::string::npos);
  return s.replace(p, from.size(), to);
}

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_case(text, "cases/box.yaml", sets);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("A good case file parses into the scene it describes", "[unit][case]") {
  const Scene s = parse_case(good, "cases/box.yaml");
  CHECK(s.name == "box");
  CHECK(s.dimension == 2);
  CHECK(s.periodic[0]);
  CHECK(s.dx == 0.02);
  CHECK(s.R() == Approx(0.06));
  CHECK(s.viscous_term == ViscousTerm::Morris);
  CHECK(s.delta_sph == 0.1);
  CHECK(s.blocks.size() == 1);
  CHECK(count_particles(s) == 50 * 25);
  // auto sound speed: u_ref = max(|u0|, sqrt(2 g H)) with H the block height, c0 = u_ref / Ma
  CHECK(s.c0 == Approx(std::sqrt(2 * 9.81 * 0.5) / 0.1));
}

TEST_CASE("Command-line overrides change a key, and a bad override is named", "[unit][case]") {
  const Scene s = parse_case(good, "cases/box.yaml", {"discretisation.dx=0.01", "fluid_blocks.0.velocity=[0, 1]"});
  CHECK(s.dx == 0.01);
  CHECK(s.blocks[0].velocity[1] == 1.0);
  CHECK_THAT(error_of(good, {"discretisation.dx=-1"}), Contains("--set discretisation.dx") && Contains("positive"));
  CHECK_THAT(error_of(good, {"nonsense"}), Contains("expected key=value"));
  CHECK_THAT(error_of(good, {"fluid.colour=blue"}), Contains("fluid.colour") && Contains("unknown key"));
  // a key an override made above the one it sets (no line in the file): the override is named
  CHECK_THAT(error_of(good, {"nothere.key=1"}), Contains("--set nothere.key: key 'nothere'") && Contains("unknown key") &&
                                                    !Contains("cases/box.yaml"));
  CHECK_THAT(error_of(good, {"fluid.extra.depth=1"}), Contains("--set fluid.extra.depth: key 'fluid.extra'") && Contains("unknown key"));
}

TEST_CASE("Bad case files get a message naming file, line and key", "[unit][case]") {
  SECTION("couette reference without its wall velocity, or a velocity on another reference") {
    const std::string couette = good + "reference: {type: couette, length: 1.0}\n";
    CHECK_THAT(error_of(couette), Contains("cases/box.yaml:") && Contains("reference.velocity") && Contains("missing"));
    CHECK(error_of(good + "reference: {type: couette, length: 1.0, velocity: 1.0}\n").empty());
    CHECK_THAT(error_of(good + "reference: {type: couette, length: 1.0, velocity: fast}\n"),
               Contains("reference.velocity") && Contains("speed along x"));
    CHECK_THAT(error_of(good + "reference: {type: poiseuille, length: 1.0, velocity: 1.0}\n"),
               Contains("reference.velocity") && Contains("only a couette"));
  }
  SECTION("open_channel reference: its inlet speed, and a section whose pressure stations lie in the domain") {
    CHECK(error_of(good + "reference: {type: open_channel, length: 0.4, origin: [0.7, 0.0], velocity: 1.0}\n").empty());
    CHECK_THAT(error_of(good + "reference: {type: open_channel, length: 0.4, origin: [0.7, 0.0]}\n"),
               Contains("reference.velocity") && Contains("missing"));
    // 0.7 - 1.5 x 0.6 < 0: the upstream pressure station would lie outside the domain
    CHECK_THAT(error_of(good + "reference: {type: open_channel, length: 0.6, origin: [0.7, 0.0], velocity: 1.0}\n"),
               Contains("cases/box.yaml:") && Contains("reference.origin") && Contains("inside the domain"));
    CHECK_THAT(error_of(good + "reference: {type: open_channel, length: 0.4, velocity: 1.0}\n"), Contains("reference.origin"));
  }
  SECTION("unknown key") {
    const auto m = error_of(replace(good, "  mach: 0.1", "  mach: 0.1\n  rho_zero: 3"));
    CHECK_THAT(m, Contains("cases/box.yaml:11:") && Contains("fluid.rho_zero") && Contains("unknown key"));
  }
  SECTION("wrong type") {
    const auto m = error_of(replace(good, "rho0: 1000.0", "rho0: heavy"));
    CHECK_THAT(m, Contains("cases/box.yaml:8:") && Contains("fluid.rho0") && Contains("'heavy'"));
    const auto m2 = error_of(replace(good, "max: [1.0, 1.0]", "max: [1.0, 1.0, 1.0]"));
    CHECK_THAT(m2, Contains("cases/box.yaml:5:") && Contains("domain.max") && Contains("2 numbers"));
  }
  SECTION("missing required key") {
    const auto m = error_of(replace(good, "  duration: 0.5\n", ""));
    CHECK_THAT(m, Contains("cases/box.yaml:") && Contains("time.duration") && Contains("missing"));
  }
  SECTION("wall clearance outside (0, 0.5] dx") {
    for (const char* v : {"0", "-0.1", "0.6", "near"}) {
      const auto m = error_of(replace(good, "    velocity: [0.5, 0.0]", std::string("    velocity: [0.5, 0.0]\n    wall_clearance: ") + v));
      INFO(v);
      CHECK_THAT(m, Contains("cases/box.yaml:") && Contains("fluid_blocks[0].wall_clearance") && Contains("dx"));
    }
    CHECK_THAT(error_of(replace(good, "    velocity: [0.5, 0.0]", "    velocity: [0.5, 0.0]\n    wall_clearance: 0.6")), Contains("(0, 0.5]"));
    CHECK(error_of(replace(good, "    velocity: [0.5, 0.0]", "    velocity: [0.5, 0.0]\n    wall_clearance: 0.01")).empty());
  }
  SECTION("block cuts") {
    const std::string v = "    velocity: [0.5, 0.0]";
    CHECK(error_of(replace(good, v, v + "\n    cut: [{point: [0.5, 0.0], normal: [-1.0, 1.0]}]")).empty());
    CHECK_THAT(error_of(replace(good, v, v + "\n    cut: [{point: [0.5, 0.0], normal: [0.0, 0.0]}]")),
               Contains("cases/box.yaml:") && Contains("fluid_blocks[0].cut[0].normal") && Contains("non-zero"));
    CHECK_THAT(error_of(replace(good, v, v + "\n    cut: [{point: [0.5, 0.0]}]")), Contains("fluid_blocks[0].cut[0]") && Contains("normal"));
    CHECK_THAT(error_of(replace(good, v, v + "\n    cut: []")), Contains("fluid_blocks[0].cut") && Contains("1 to 8"));
    CHECK_THAT(error_of(replace(good, v, v + "\n    cut: [{point: [0.5, 0.0], normal: [1, 0], side: up}]")),
               Contains("fluid_blocks[0].cut[0].side") && Contains("unknown key"));
  }
  SECTION("negative spacing") {
    const auto m = error_of(replace(good, "dx: 0.02", "dx: -0.02"));
    CHECK_THAT(m, Contains("cases/box.yaml:13:") && Contains("discretisation.dx") && Contains("positive"));
  }
  SECTION("empty fluid region") {
    const auto m = error_of(replace(good, "max: [1.0, 0.5]", "max: [1.0, 0.005]"));
    CHECK_THAT(m, Contains("cases/box.yaml:18:") && Contains("fluid_blocks[0].max") && Contains("empty fluid region"));
    const auto m2 = error_of(replace(good, "fluid_blocks:\n  - min: [0.0, 0.0]\n    max: [1.0, 0.5]\n    velocity: [0.5, 0.0]", "fluid_blocks: []"));
    CHECK_THAT(m2, Contains("fluid_blocks") && Contains("non-empty"));
  }
  SECTION("box outside the domain") {
    const auto m = error_of(replace(good, "max: [1.0, 0.5]", "max: [1.5, 0.5]"));
    CHECK_THAT(m, Contains("cases/box.yaml:18:") && Contains("fluid_blocks[0].max") && Contains("outside the domain"));
  }
  SECTION("a particle count that cannot fit in memory") {
    const auto m = error_of(replace(good, "dx: 0.02", "dx: 1.0e-7"));
    CHECK_THAT(m, Contains("cases/box.yaml:13:") && Contains("discretisation.dx") && Contains("GiB"));
  }
  SECTION("a bad choice among options") {
    const auto m = error_of(replace(good, "kernel: wendland_c2", "kernel: gaussian"));
    CHECK_THAT(m, Contains("cases/box.yaml:14:") && Contains("discretisation.kernel") && Contains("wendland_c2 | quartic_spline | cubic_spline"));
  }
  SECTION("inconsistent physics") {
    const auto m = error_of(replace(good, "viscous_term: morris", "viscous_term: none"));
    CHECK_THAT(m, Contains("fluid.viscosity") && Contains("viscous_term"));
  }
  SECTION("wall sensors: walls needed, a normal, a face size, fixed walls, unique names") {
    const std::string bounded = replace(good, "periodic: [true, true]", "periodic: [false, false]");
    const std::string walls = bounded + "walls:\n  - {name: floor, points: [[0.0, 0.0], [1.0, 0.0]], fluid_side: left}\n";
    const std::string ok = "wall_sensors:\n  - {name: S1, position: [0.5, 0.0], normal: [0, -1], size: 0.01}\n";
    CHECK(error_of(walls + ok).empty());
    CHECK_THAT(error_of(bounded + ok), Contains("cases/box.yaml:") && Contains("wall_sensors") && Contains("no walls"));
    CHECK_THAT(error_of(walls + "wall_sensors:\n  - {name: S1, position: [0.5, 0.0], normal: [0, 0]}\n"),
               Contains("wall_sensors[0].normal") && Contains("non-zero"));
    CHECK_THAT(error_of(walls + "wall_sensors:\n  - {name: S1, position: [0.5, 0.0]}\n"), Contains("wall_sensors[0].normal") && Contains("missing"));
    CHECK_THAT(error_of(walls + "wall_sensors:\n  - {name: S1, position: [0.5, 0.0], normal: [0, -1], size: -1}\n"),
               Contains("wall_sensors[0].size"));
    CHECK_THAT(error_of(walls + "wall_sensors:\n  - {name: S1, position: [0.5, 2.0], normal: [0, -1]}\n"),
               Contains("wall_sensors[0].position") && Contains("outside the domain"));
    CHECK_THAT(error_of(walls + ok + "  - {name: S1, position: [0.4, 0.0], normal: [0, -1]}\n"),
               Contains("wall_sensors[1].name") && Contains("duplicate"));
    const std::string moving =
        bounded + "walls:\n  - {name: floor, points: [[0.0, 0.0], [1.0, 0.0]], fluid_side: left, motion: {type: oscillation, amplitude: [0.02, 0.0], period: 1.0}}\n";
    REQUIRE(error_of(moving).empty());
    CHECK_THAT(error_of(moving + ok), Contains("wall_sensors") && Contains("move"));
  }
  SECTION("the wall quadrature's spacing in metres or in dx, not both") {
    CHECK(error_of(replace(good, "  R_over_dx: 3.0", "  R_over_dx: 3.0\n  wall_quadrature_spacing_dx: 0.8")).empty());
    CHECK_THAT(error_of(replace(good, "  R_over_dx: 3.0", "  R_over_dx: 3.0\n  wall_quadrature_spacing_dx: 0")),
               Contains("cases/box.yaml:") && Contains("discretisation.wall_quadrature_spacing_dx") && Contains("positive"));
    CHECK_THAT(error_of(replace(good, "  R_over_dx: 3.0", "  R_over_dx: 3.0\n  wall_quadrature_spacing: 0.01\n  wall_quadrature_spacing_dx: 0.8")),
               Contains("cases/box.yaml:") && Contains("discretisation.wall_quadrature_spacing_dx") && Contains("not both"));
  }
  SECTION("not YAML at all") {
    const auto m = error_of("dimension: [2\n");
    CHECK_THAT(m, Contains("cases/box.yaml:") && Contains("not valid YAML"));
  }
}

TEST_CASE("A key written twice in a mapping is refused with its line", "[case]") {
  const std::string y = R"(dimension: 2
domain: {min: [0, 0], max: [1, 1]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation:
  dx: 0.02
  dx: 0.01
fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]
time: {duration: 1, output_interval: 1}
)";
  CHECK_THROWS_WITH(ondine::parse_case(y, "dup.yaml"), Catch::Contains("dup.yaml:6:3: key 'discretisation.dx': written twice"));
}

TEST_CASE("A wall reaching beyond a periodic face is refused", "[case]") {
  const std::string y = R"(dimension: 2
domain: {min: [0, -0.1], max: [0.4, 1.1], periodic: [true, false]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.04}
walls: [{name: bottom, points: [[-0.1, 0], [0.4, 0]], fluid_side: left}]
fluid_blocks: [{min: [0, 0], max: [0.4, 1]}]
time: {duration: 1, output_interval: 1}
)";
  CHECK_THROWS_WITH(ondine::parse_case(y, "wall.yaml"), Catch::Contains("key 'walls[0].points': a wall must lie within the domain along the periodic axis x"));
}

TEST_CASE("A 2D wall that meets itself is refused, naming the segments", "[case]") {
  const std::string y = R"(dimension: 2
domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.04}
walls: [{name: tank, points: POINTS, closed: CLOSED, fluid_side: SIDE}]
fluid_blocks: [{min: [0, 0], max: [0.4, 0.4]}]
time: {duration: 1, output_interval: 1}
)";
  auto error = [&](const std::string& points, bool closed) {
    try {
      parse_case(replace(replace(replace(y, "POINTS", points), "CLOSED", closed ? "true" : "false"), "SIDE", closed ? "inside" : "left"), "w.yaml");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // a bow tie: its first and third segments cross
  CHECK_THAT(error("[[0, 0], [1, 1], [1, 0], [0, 1]]", true), Contains("w.yaml:5:") && Contains("key 'walls[0].points': segments 0 and 2 (0-based) meet"));
  // a vertex on a segment that is not its neighbour
  CHECK_THAT(error("[[0, 0], [1, 0], [1, 1], [0.5, 0], [0, 0.5]]", true), Contains("segments 0 and 2 (0-based) meet"));
  // an open and a closed wall folding back onto themselves
  CHECK_THAT(error("[[0, 0.5], [1, 0.5], [0.5, 0.5]]", false), Contains("segments 0 and 1 fold back onto each other at point 1"));
  CHECK_THAT(error("[[0, 0], [1, 0], [0.5, 0], [0.5, 1]]", true), Contains("segments 0 and 1 fold back onto each other at point 1"));
  // simple polylines pass: a square, an L, an open floor with a wall
  CHECK(error("[[0, 0], [1, 0], [1, 1], [0, 1]]", true).empty());
  CHECK(error("[[0, 0], [1, 0], [1, 0.5], [0.5, 0.5], [0.5, 1], [0, 1]]", true).empty());
  CHECK(error("[[0, 1], [0, 0], [1, 0]]", false).empty());
}

TEST_CASE("Every shipped case file selects a built flux scheme, and another is refused naming its keys", "[unit][case]") {
  namespace fs = std::filesystem;
  int n = 0;
  for (const auto& e : fs::directory_iterator(std::string(ONDINE_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".yaml") continue;
    INFO(e.path().string());
    const Scene s = load_case(e.path().string());
    CHECK(flux_scheme_index(flux_key(s)) >= 0);
    ++n;
  }
  CHECK(n >= 20);
  // Riemann-SPH first order with the plain Morris term and the background pressure: not a row of the table
  const std::vector<std::string> sets = {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.riemann.reconstruction=none",
                                         "scheme.background_pressure=true"};
  CHECK_THROWS_WITH(load_case(std::string(ONDINE_SOURCE_DIR) + "/cases/poiseuille_2d.yaml", sets),
                    Contains("selects a flux scheme that is not built (scheme.flux: riemann") &&
                        Contains("scheme.riemann.reconstruction: none") && Contains("scheme.background_pressure: true") &&
                        Contains("the built ones are:"));
}
