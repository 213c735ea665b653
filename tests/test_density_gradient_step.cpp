// scheme.density_gradient: step: the renormalised density gradient (2.42-2.44) computed at the
// first stage of a time step and held through its other stages (one gradient pass per RK4 step
// instead of four). The gradient feeds only delta-SPH's correction (2.63) and the MUSCL wall
// state (4.30), so holding it changes the flow by O(dt) in a correction term.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "reference/References.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using Catch::Matchers::Contains;

namespace {
const std::string src = ONDINE_SOURCE_DIR;

template <class View>
std::vector<double> host_copy(const View& v, int n) {
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
  std::vector<double> out;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) out.push_back(h(i, k));
  return out;
}

// the density gradient after one step of the 2D dam break at a / 25 (no reordering), and the
// gradient of the state the step starts from
std::pair<std::vector<double>, std::vector<double>> gradient_after_one_step(const std::string& mode) {
  Simulation<2> sim(load_case(src + "/cases/dam_break_2d.yaml", {"discretisation.dx=0.002286", "discretisation.reorder_interval=0",
                                                                  "scheme.density_gradient=" + mode}));
  const int n = static_cast<int>(sim.particles().size());
  sim.step(1.0);  // a first step, so that the state is not the initial lattice
  sim.evaluate();
  const auto at_start = host_copy(sim.particles().get(field::DensityGradient{}), n);
  sim.step(1.0);
  return {at_start, host_copy(sim.particles().get(field::DensityGradient{}), n)};
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}
}  // namespace

TEST_CASE("scheme.density_gradient: step keeps the first stage's gradient through the RK4 step", "[unit][scheme]") {
  // with step, the gradient left after the step is the one of the step's first stage, bit for
  // bit; with stage it is the fourth stage's, which differs
  const auto [start_step, after_step] = gradient_after_one_step("step");
  const auto [start_stage, after_stage] = gradient_after_one_step("stage");
  CHECK(after_step == start_step);
  double scale = 0;
  for (double g : start_stage) scale = std::max(scale, std::abs(g));
  const double moved = largest_difference(after_stage, start_stage);
  INFO("largest change of the gradient over the step with stage " << moved << " of " << scale);
  CHECK(moved > 1e-6 * scale);
}

TEST_CASE("scheme.density_gradient: step leaves the dam-break front as stage does", "[scheme]") {
  // a / 25 to T = 3.1 at the case's CFL: holding the gradient is an O(dt) change in delta-SPH's
  // correction, far below the front's own error (0.10 RMS against the experiment, a particle
  // spacing is 4 % of a). Measured: 8e-5 of a.
  const auto step = test::dam_break_front({"discretisation.dx=0.002286", "scheme.density_gradient=step"});
  const auto stage = test::dam_break_front({"discretisation.dx=0.002286", "scheme.density_gradient=stage"});
  double d = 0;
  for (std::size_t k = 0; k < step.size(); ++k) d = std::max(d, std::abs(step[k].second - stage[k].second));
  INFO("largest front difference " << d << " a");
  CHECK(d < 0.005);
}

TEST_CASE("scheme.density_gradient: a bad value, refinement zones and the consistent Laplacian are refused", "[unit][case]") {
  CHECK_THAT(test::case_refusal("dam_break_2d.yaml", {"scheme.density_gradient=sometimes"}),
             Contains("scheme.density_gradient") && Contains("stage") && Contains("step"));
  CHECK_THAT(test::case_refusal("dam_break_apr_2d.yaml", {"scheme.density_gradient=step"}),
             Contains("refinement") && Contains("density_gradient"));
  CHECK_THAT(test::case_refusal("poiseuille_2d.yaml", {"scheme.density_gradient=step"}),
             Contains("scheme.density_gradient") && Contains("consistent Laplacian"));
  CHECK_NOTHROW(load_case(src + "/cases/poiseuille_2d.yaml", {"scheme.density_gradient=step", "scheme.consistent_laplacian=false"}));
}
