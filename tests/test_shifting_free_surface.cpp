// Particle shifting (2.107)-(2.111) with a free surface and NFM walls: the particles on the
// free surface, or with a surface particle within R, keep only the tangential part of their
// shift (kernels/ShiftingPass.hpp). Without that, the concentration gradient of the truncated
// supports at the surface pushes the surface particles out of the water by up to 0.02 dx per
// step (the clamp), about 20 dx over 1000 steps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "reference/References.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"
#include "test_helpers.hpp"

using namespace ondine;

namespace {
const std::string src = ONDINE_SOURCE_DIR;

double highest(const Simulation<2>& sim) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Position{}));
  double y = -1e300;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) y = std::max(y, x(i, 1));
  return y;
}
}  // namespace

TEST_CASE("Shifting in a hydrostatic tank keeps the free surface in place and the pressure hydrostatic", "[shifting][nfm]") {
  // cases/hydrostatic_tank_2d.yaml: H = 0.5 m, 0.5 s damping, 2 s, at dx = 0.025 m (20 per depth)
  for (const std::string flux : {"delta_sph", "riemann"}) {
    std::vector<std::string> sets = {"scheme.shifting=true", "discretisation.dx=0.025"};
    if (flux == "riemann") sets.insert(sets.end(), {"scheme.flux=riemann", "scheme.delta_sph=0"});
    Simulation<2> sim(load_case(src + "/cases/hydrostatic_tank_2d.yaml", sets));
    const double top0 = highest(sim), dx = sim.scene().dx;
    while (sim.time() < 2.0 * (1 - 1e-12)) sim.step(2.0);
    const double top = highest(sim);
    const Diagnostics d = diagnostics(sim);
    INFO(flux << ": highest particle moved by " << (top - top0) / dx << " dx in " << sim.steps() << " steps; density "
              << d.rho_min << " .. " << d.rho_max);
    // the still surface settles by the weak compression of the column (rho g H / (rho0 c0^2) = 1 %
    // of H, 0.2 dx) and must not rise: a shift normal to the surface would lift it by several dx
    CHECK(std::abs(top - top0) < 0.5 * dx);
    CHECK(wall_leaks(sim, 0.0) == 0);
    // the hydrostatic pressure at the bottom probe (z = 0.05 m) within 3 % of rho g (H - z), the
    // bound of the unshifted tank in ondine validate
    const double p = sample_probes(sim).at(0).pressure;  // the bottom probe
    CHECK(std::abs(p - 1000 * 9.81 * 0.45) < 0.03 * 1000 * 9.81 * 0.5);
  }
}

TEST_CASE("Shifting leaves the dam-break front within the bounds of Martin & Moyce and close to the unshifted run", "[shifting][dam_break]") {
  const std::vector<std::string> base = {"discretisation.dx=0.002286"};
  auto shifted_sets = base;
  shifted_sets.push_back("scheme.shifting=true");
  Simulation<2> sim(load_case(src + "/cases/dam_break_2d.yaml", shifted_sets));
  const auto shifted = test::dam_break_front(sim);
  const auto plain = test::dam_break_front(base);
  const auto e = reference::martin_moyce_errors(shifted);
  const double d = reference::front_relative_difference(shifted, plain);
  INFO("front max relative error " << e.at("front_max_relative_error") << ", difference from the unshifted front " << d);
  CHECK(e.at("front_max_relative_error") < 0.20);
  CHECK(d < 0.03);
  CHECK(wall_leaks(sim, 0.0) == 0);
}

TEST_CASE("scheme.transport: lagrangian and shifting are read, ale with delta-SPH and a contradiction are refused", "[unit][case]") {
  CHECK(load_case(src + "/cases/dam_break_2d.yaml", {"scheme.transport=shifting"}).shifting);
  CHECK_FALSE(load_case(src + "/cases/taylor_green_2d.yaml", {"scheme.shifting=false", "scheme.transport=lagrangian"}).shifting);
  const auto refused = [](const std::vector<std::string>& sets, const std::string& what) {
    CHECK_THAT(test::case_refusal("taylor_green_2d.yaml", sets),
               Catch::Matchers::Contains("scheme.transport") && Catch::Matchers::Contains(what));
  };
  refused({"scheme.shifting=false", "scheme.transport=ale"}, "scheme.flux: riemann");
  refused({"scheme.transport=lagrangian"}, "disagrees with scheme.shifting");  // the case file says shifting: true
  refused({"scheme.transport=eulerian"}, "lagrangian");
}
