// scheme.pair_list: half (kernels/SymmetricFluxPass.hpp): each pair evaluated once, both
// particles updated. Checked against the full list's pass (the same rates to round-off), the
// conservation of momentum, a dam-break front, and the parser's refusals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "solver/Measures.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using Catch::Matchers::Contains;

namespace {

const std::string src = ONDINE_SOURCE_DIR;

// du/dt and drho/dt of every owned particle after one evaluation, on the host
template <int D>
std::pair<std::vector<double>, std::vector<double>> rates(Simulation<D>& sim) {
  sim.evaluate();
  const auto& p = sim.particles();
  auto du = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Acceleration{}));
  auto dr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::DensityRate{}));
  std::vector<double> a, r;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    for (int k = 0; k < D; ++k) a.push_back(du(i, k));
    r.push_back(dr(i));
  }
  return {a, r};
}

// max |a - b| over max |b|
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double d = 0, s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::max(d, std::abs(a[i] - b[i]));
    s = std::max(s, std::abs(b[i]));
  }
  REQUIRE(s > 0);
  return d / s;
}

// The same scene on the full and on the half list, the same disorder: the rates agree to round-off.
template <int D>
void check_same_rates(const Scene& full, const Scene& half, double amp, double speed) {
  Simulation<D> a(full), b(half);
  test::disorder(a, amp, speed, 0.01, 7);
  test::disorder(b, amp, speed, 0.01, 7);
  const auto [du_f, drho_f] = rates(a);
  const auto [du_h, drho_h] = rates(b);
  const double e_u = relative_difference(du_h, du_f), e_rho = relative_difference(drho_h, drho_f);
  INFO("du/dt " << e_u << ", drho/dt " << e_rho << " of the largest");
  CHECK(e_u < 1e-12);
  CHECK(e_rho < 1e-12);
}

template <int D>
void check_periodic(const std::string& scheme) {
  const double L = D == 2 ? 0.5 : 0.25, dx = D == 2 ? 0.02 : 0.025;
  const std::string half = scheme.substr(0, scheme.size() - 1) + ", pair_list: half}";
  INFO(D << "D " << scheme);
  check_same_rates<D>(test::periodic_box(D, L, dx, scheme, ", viscosity: 1.0e-2"),
                      test::periodic_box(D, L, dx, half, ", viscosity: 1.0e-2"), 0.2, 0.5);
}

}  // namespace

TEST_CASE("scheme.pair_list: half gives the full list's rates to round-off (periodic box)", "[unit][scheme]") {
  for (const std::string s : {"{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.05}",
                              "{viscous_term: morris, delta_sph: 0.1, background_pressure: true}", "{viscous_term: morris}"}) {
    check_periodic<2>(s);
    check_periodic<3>(s);
  }
}

TEST_CASE("scheme.pair_list: half gives the full list's rates to round-off next to NFM walls", "[unit][scheme]") {
  // the wall pass adds to and divides the pair sums by gamma: it must find the same sums
  const std::vector<std::string> dam = {"discretisation.dx=0.004572"};
  std::vector<std::string> dam_half = dam;
  dam_half.push_back("scheme.pair_list=half");
  check_same_rates<2>(load_case(src + "/cases/dam_break_2d.yaml", dam), load_case(src + "/cases/dam_break_2d.yaml", dam_half),
                      0.1, 0.3);
  const std::vector<std::string> t2 = {"discretisation.dx=0.08"};
  std::vector<std::string> t2_half = t2;
  t2_half.push_back("scheme.pair_list=half");
  check_same_rates<3>(load_case(src + "/cases/spheric_test2_3d.yaml", t2), load_case(src + "/cases/spheric_test2_3d.yaml", t2_half),
                      0.1, 0.3);
}

TEST_CASE("scheme.pair_list: half conserves linear momentum to round-off", "[scheme][conservation]") {
  for (int dim : {2, 3}) {
    const double L = dim == 2 ? 0.5 : 0.25, dx = dim == 2 ? 0.02 : 0.025;
    const Scene s = test::periodic_box(dim, L, dx, "{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.05, pair_list: half}",
                                       ", viscosity: 1.0e-2");
    auto run = [&](auto& sim) {
      test::disorder(sim, 0.2, 0.5, 0.01, 42);
      const Diagnostics d0 = diagnostics(sim);
      for (int n = 0; n < 10; ++n) sim.step(1.0);
      const Diagnostics d1 = diagnostics(sim);
      CHECK(d1.mass == d0.mass);
      for (int k = 0; k < dim; ++k) {
        INFO(dim << "D, momentum " << k << ": " << d0.momentum[k] << " -> " << d1.momentum[k]);
        CHECK(std::abs(d1.momentum[k] - d0.momentum[k]) / (dim * 0.5 * d0.mass) < 1e-13);  // speeds up to 0.5
      }
    };
    if (dim == 2) {
      Simulation<2> sim(s);
      run(sim);
    } else {
      Simulation<3> sim(s);
      run(sim);
    }
  }
}

TEST_CASE("scheme.pair_list: half leaves the dam-break front as full does", "[scheme]") {
  // a / 25 to T = 3.1: the two lists differ by the order of the sums only, so the fronts agree far
  // below a particle spacing (4 % of a)
  const auto half = test::dam_break_front({"discretisation.dx=0.002286", "scheme.pair_list=half"});
  const auto full = test::dam_break_front({"discretisation.dx=0.002286"});
  double d = 0;
  for (std::size_t k = 0; k < half.size(); ++k) d = std::max(d, std::abs(half[k].second - full[k].second));
  INFO("largest front difference " << d << " a");
  CHECK(d < 1e-3);
}

TEST_CASE("scheme.pair_list: a bad value is refused, and half falls back to full where the half-list pass is not built", "[unit][case]") {
  CHECK_THAT(test::case_refusal("dam_break_2d.yaml", {"scheme.pair_list=quarter"}),
             Contains("scheme.pair_list") && Contains("full") && Contains("half"));
  const auto half = [](const std::string& file, std::vector<std::string> sets) {
    sets.push_back("scheme.pair_list=half");
    return load_case(src + "/cases/" + file, sets).half_pair_list;
  };
  CHECK(half("dam_break_2d.yaml", {}));
  CHECK(half("spheric_test2_3d.yaml", {}));
  CHECK(half("taylor_green_2d.yaml", {}));                  // Morris viscosity, shifting
  CHECK_FALSE(half("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage"}));
  CHECK_FALSE(half("poiseuille_2d.yaml", {}));              // the consistent Laplacian next to no-slip walls
  CHECK_FALSE(half("dam_break_apr_2d.yaml", {}));           // refinement zones
  CHECK_FALSE(half("open_channel_2d.yaml", {}));            // open boundaries
  CHECK_FALSE(half("spheric_test2_3d.yaml", {"fluid.viscosity=1e-6", "scheme.viscous_term=morris", "scheme.artificial_viscosity=0",
                                             "turbulence.model=smagorinsky"}));  // the eddy viscosity's term
  CHECK_FALSE(load_case(src + "/cases/dam_break_2d.yaml", {"scheme.pair_list=full"}).half_pair_list);
}
