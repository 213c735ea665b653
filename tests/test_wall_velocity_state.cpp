// The velocity's MUSCL state at an NFM wall point (thesis 4.30; kernels/WallVelocityState.hpp),
// scheme.wall_velocity_reconstruction: exact for a linear flow whatever the wall cuts off the
// support, and limited between the wall's and the particle's normal velocity.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "kernels/SmoothingKernels.hpp"
#include "kernels/WallVelocityState.hpp"

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
