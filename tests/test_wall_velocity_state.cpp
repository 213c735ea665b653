// The velocity's MUSCL state at an NFM wall point (thesis 4.30; kernels/WallVelocityState.hpp),
// scheme.wall_velocity_reconstruction: exact for a linear flow whatever the wall cuts off the
// support, and limited between the wall's and the particle's normal velocity.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/SmoothingKernels.hpp"
#include "kernels/WallVelocityState.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

using namespace ondine;

namespace {
// the stagnation-point flow u = (a x, -a y) above a floor y = 0 (divergence-free, u.n = 0 on it)
Vec<2> stagnation(const Vec<2>& x, double a) { return Vec<2>{{a * x[0], -a * x[1]}}; }
}  // namespace

TEST_CASE("Wall velocity state: the reconstructed normal velocity vanishes on the wall for a linear flow", "[unit][nfm]") {
  const double dx = 1.0, R = 3.0 * dx, a = 2.0;
  const WendlandC2<2> W(R);
  std::vector<Vec<2>> xs;  // lattice above the floor, first row at dx/2
  for (int i = -8; i <= 8; ++i)
    for (int j = 0; j < 8; ++j) xs.push_back(Vec<2>{{(i + 0.5) * dx, (j + 0.5) * dx}});
  const Vec<2> n_out{{0.0, -1.0}}, uq{{0.0, 0.0}};
  for (const double y : {0.5 * dx, 1.5 * dx, 2.5 * dx}) {  // rows whose supports the floor cuts
    const Vec<2> xi{{0.5 * dx, y}}, ui = stagnation(xi, a);
    VelocityGradientSum<2> S;
    for (const auto& xj : xs) {
      const Vec<2> xij = xi - xj;
      const double r = std::sqrt(norm2(xij));
      if (r <= 0.0 || r >= R) continue;
      S.add(dx * dx, xij, (W.derivative(r) / r) * xij, stagnation(xj, a) - ui);
    }
    const Mat<2> G = S.gradient();
    // renormalised: exact for a linear field on a one-sided support (2.42-2.44)
    CHECK(G.a[0][0] == Approx(a).margin(1e-12));
    CHECK(G.a[1][1] == Approx(-a).margin(1e-12));
    CHECK(std::abs(G.a[0][1]) < 1e-12);
    CHECK(std::abs(G.a[1][0]) < 1e-12);
    for (const double xw : {-1.0, 0.5, 2.0}) {  // wall points within R
      const Vec<2> xq{{xw, 0.0}};
      const double un_first_order = dot(ui - uq, n_out);  // a y: what the impedance read before
      CHECK(un_first_order == Approx(a * y));
      CHECK(std::abs(wall_normal_velocity<2>(G, xi - xq, ui, uq, n_out)) < 1e-12);
    }
  }
}

TEST_CASE("Wall velocity state: the limiter keeps the state between the wall's and the particle's", "[unit][nfm]") {
  const Vec<2> n{{0.0, -1.0}}, uq{{0.0, 0.0}}, xiq{{0.0, 1.0}};  // the particle 1 above the wall point
  Mat<2> G = Mat<2>::zero();
  // un_f = un_i + n . G (x_q - x_i) = un_i + G[1][1] with n = -e_y and x_q - x_i = -e_y
  const Vec<2> towards{{0.0, -1.0}};  // un_i = 1, into the wall
  G.a[1][1] = -0.25;
  CHECK(wall_normal_velocity<2>(G, xiq, towards, uq, n) == Approx(0.75));
  G.a[1][1] = -3.0;  // overshoot past the wall's value: not reversed
  CHECK(wall_normal_velocity<2>(G, xiq, towards, uq, n) == 0.0);
  G.a[1][1] = +0.5;  // larger than the particle's own: not enlarged
  CHECK(wall_normal_velocity<2>(G, xiq, towards, uq, n) == Approx(1.0));
  const Vec<2> away{{0.0, 1.0}};  // un_i = -1, away from the wall
  G.a[1][1] = 0.25;
  CHECK(wall_normal_velocity<2>(G, xiq, away, uq, n) == Approx(-0.75));
  G.a[1][1] = 3.0;
  CHECK(wall_normal_velocity<2>(G, xiq, away, uq, n) == 0.0);
  G.a[1][1] = -0.5;
  CHECK(wall_normal_velocity<2>(G, xiq, away, uq, n) == Approx(-1.0));
  // a moving wall: relative to u_q
  const Vec<2> uq_moving{{0.0, -1.0}};
  G.a[1][1] = -0.25;
  CHECK(wall_normal_velocity<2>(G, xiq, towards, uq_moving, n) == 0.0);
}

TEST_CASE("Wall velocity state: the density-gradient pass gathers the velocity gradient, exact for a linear flow next to 3D walls", "[unit][nfm]") {
  // the gradient that (4.30) reads comes from the density-gradient pass's own neighbour loop
  // (src/scene/Scene.hpp, uses_velocity_gradient); the tank's floor and walls cut the supports
  const std::string y = R"(dimension: 3
domain: {min: [-0.1, -0.1, -0.1], max: [0.7, 0.7, 0.7]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.05, R_over_dx: 2.5}
walls: [{name: tank, box: {min: [0, 0, 0], max: [0.6, 0.6, 0.6]}, fluid_side: inside, condition: slip}]
fluid_blocks: [{min: [0, 0, 0], max: [0.6, 0.6, 0.4]}]
scheme: {delta_sph: 0.1, density_gradient: step, wall_velocity_reconstruction: true}
time: {duration: 1, output_interval: 1})";
  Simulation<3> sim(parse_case(y, "t.yaml"));
  auto& p = sim.particles();
  REQUIRE(p.has(field::VelocityGradientX{}));
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  const double a = 0.3;  // the stagnation flow u = (a x, a y, -2 a z): divergence-free, u.n = 0 on the floor
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
    u(i, 0) = a * x(i, 0);
    u(i, 1) = a * x(i, 1);
    u(i, 2) = -2.0 * a * x(i, 2);
  });
  sim.evaluate();
  auto g0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::VelocityGradientX{}));
  auto g1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::VelocityGradientY{}));
  auto g2 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::VelocityGradientZ{}));
  const double exact[3][3] = {{a, 0, 0}, {0, a, 0}, {0, 0, -2 * a}};
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int b = 0; b < 3; ++b)
      worst = std::max({worst, std::abs(g0(i, b) - exact[0][b]), std::abs(g1(i, b) - exact[1][b]), std::abs(g2(i, b) - exact[2][b])});
  CHECK(p.size() > 1000);
  CHECK(worst < 1e-9);
}

TEST_CASE("Wall velocity state: without the option (and without Riemann-SPH) no velocity gradient is gathered", "[unit][nfm]") {
  const std::string y = R"(dimension: 2
domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.05}
walls: [{name: tank, points: [[0, 1], [0, 0], [1, 0], [1, 1]], closed: false, fluid_side: left, condition: slip}]
fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]
scheme: {delta_sph: 0.1}
time: {duration: 1, output_interval: 1})";
  Simulation<2> sim(parse_case(y, "t.yaml"));
  CHECK_FALSE(sim.particles().has(field::VelocityGradientX{}));
}
