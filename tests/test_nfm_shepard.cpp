// Analytical Shepard factor of NFM walls in 2D (thesis 4.52-4.59) against the
// reference values of nfm.md §14, the closed-form flat-wall limit, and a
// brute-force integration of the kernel over the fluid side.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "kernels/ShepardGamma2D.hpp"
#include "kernels/SmoothingKernels.hpp"

using namespace ondine;

namespace {

struct Seg {
  Vec<2> a, b, n_in;
};

Vec<2> v2(double x, double y) { return Vec<2>{{x, y}}; }

double gamma_of(const std::vector<Seg>& segs, const Vec<2>& x, double R = 1.0) {
  double g = 1.0;
  for (const Seg& s : segs) g += shepard_gamma_segment(x, s.a, s.b, s.n_in, R);
  return g;
}

// Midpoint integration of W over the fluid region on a grid whose cell edges lie
// on the walls x = 0 and y = 0, so that every cell is wholly in or out of the
// fluid: the error is the midpoint rule's O(h^2) on the smooth kernel.
template <class Inside>
double brute_force(const Vec<2>& x, double R, Inside inside, int per_R = 1000) {
  const WendlandC2<2> W(R);
  const double h = R / per_R;
  const int a0 = static_cast<int>(std::floor((x[0] - R) / h)), a1 = static_cast<int>(std::ceil((x[0] + R) / h));
  const int b0 = static_cast<int>(std::floor((x[1] - R) / h)), b1 = static_cast<int>(std::ceil((x[1] + R) / h));
  double s = 0;
  for (int a = a0; a < a1; ++a)
    for (int b = b0; b < b1; ++b) {
      const double px = (a + 0.5) * h, py = (b + 0.5) * h;
      if (!inside(px, py)) continue;
      s += W.value(std::hypot(px - x[0], py - x[1])) * h * h;
    }
  return s;
}

// a long flat floor y = 0, fluid above, cut into several segments
std::vector<Seg> floor_segments(int pieces) {
  std::vector<Seg> s;
  const double x0 = -3, len = 6.0 / pieces;
  for (int k = 0; k < pieces; ++k) s.push_back({v2(x0 + k * len, 0), v2(x0 + (k + 1) * len, 0), v2(0, 1)});
  return s;
}

}  // namespace

TEST_CASE("F(xi, d) matches the reference values", "[unit][nfm]") {
  CHECK(shepard_F(0.5, 0.3) == Approx(-2.4582742587).epsilon(1e-9));
  CHECK(shepard_F(0.9, 0.1) == Approx(-6.6916884603).epsilon(1e-9));
  CHECK(shepard_F(-0.4, 0.5) == Approx(0.5097635338).epsilon(1e-9));
}

TEST_CASE("Shepard factor of a flat wall", "[unit][nfm]") {
  const auto wall = floor_segments(7);
  // far from the wall
  CHECK(gamma_of(wall, v2(0.1, 1.5)) == 1.0);
  // on the wall: 1/2, also exactly at a joint between two segments
  CHECK(gamma_of(wall, v2(0.3, 0.0)) == Approx(0.5).epsilon(1e-14));
  CHECK(gamma_of(wall, v2(-3 + 6.0 / 7, 0.0)) == Approx(0.5).epsilon(1e-14));
  // digest §14 reference values, and the closed form gamma(d) = 1 + F(sqrt(1-d^2), d)/(6 pi)
  const double d[] = {0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9};
  const double ref[] = {0.514851, 0.573815, 0.644995, 0.771168, 0.867849, 0.971491, 0.997765, 0.999993};
  for (int k = 0; k < 8; ++k) {
    const double g = gamma_of(wall, v2(0.123, d[k]));
    CHECK(g == Approx(ref[k]).margin(1e-6));
    CHECK(g == Approx(1 + shepard_F(std::sqrt(1 - d[k] * d[k]), d[k]) / (6 * M_PI)).epsilon(1e-10));
    // across a joint: continuous
    const double joint = -3 + 3 * 6.0 / 7;
    CHECK(gamma_of(wall, v2(joint - 1e-9, d[k])) == Approx(gamma_of(wall, v2(joint + 1e-9, d[k]))).epsilon(1e-7));
  }
  // the d -> 0 limit is continuous
  CHECK(gamma_of(wall, v2(0.2, 1e-9)) == Approx(0.5).margin(1e-7));
}

TEST_CASE("Shepard factor in interior and exterior 90 degree corners", "[unit][nfm]") {
  // interior corner, fluid in x > 0, y > 0: floor from (4, 0) to (0, 0), wall from (0, 0) to (0, 4)
  const std::vector<Seg> inner = {{v2(4, 0), v2(0, 0), v2(0, 1)}, {v2(0, 0), v2(0, 4), v2(1, 0)}};
  CHECK(gamma_of(inner, v2(0.3, 0.4)) == Approx(0.808760).margin(1e-6));
  CHECK(gamma_of(inner, v2(0.1, 0.7)) == Approx(0.643459).margin(1e-6));
  CHECK(gamma_of(inner, v2(0.5, 0.05)) == Approx(0.557254).margin(1e-6));
  // at the corner (the limit d -> 0 depends on the direction there, so approach it)
  CHECK(gamma_of(inner, v2(1e-7, 1e-7)) == Approx(0.25).margin(1e-6));
  // exterior corner, solid in x < 0, y < 0: fluid on the outside of the quadrant
  const std::vector<Seg> outer = {{v2(-4, 0), v2(0, 0), v2(0, 1)}, {v2(0, 0), v2(0, -4), v2(1, 0)}};
  CHECK(gamma_of(outer, v2(0.2, -0.3)) == Approx(0.800606).margin(1e-6));
  CHECK(gamma_of(outer, v2(-0.3, 0.25)) == Approx(0.845844).margin(1e-6));
  CHECK(gamma_of(outer, v2(0.05, 0.05)) == Approx(0.818329).margin(1e-6));
  // against brute-force integration of W over the fluid, off the reference points
  const double R = 0.7;
  auto in_inner = [](double x, double y) { return x > 0 && y > 0; };
  auto in_outer = [](double x, double y) { return x > 0 || y > 0; };
  for (const Vec<2>& p : {v2(0.11, 0.23), v2(0.4, 0.02), v2(0.6, 0.6)}) {
    CHECK(gamma_of(inner, p, R) == Approx(brute_force(p, R, in_inner)).margin(1e-6));
  }
  for (const Vec<2>& p : {v2(0.11, -0.23), v2(-0.4, 0.02), v2(0.05, 0.01)}) {
    CHECK(gamma_of(outer, p, R) == Approx(brute_force(p, R, in_outer)).margin(1e-6));
  }
}

TEST_CASE("Shepard factor on the solid side of a wall (a particle that crossed it)", "[unit][nfm]") {
  // gamma = integral of W over the fluid; the boundary sum counts the inner sphere of (4.49) only
  // for points in the fluid, so behind a wall gamma = sum of gamma_s (shepard_gamma_from_sum)
  auto gamma_any = [](const std::vector<Seg>& segs, const Vec<2>& x, double R) {
    double s = 0;
    for (const Seg& g : segs) s += shepard_gamma_segment(x, g.a, g.b, g.n_in, R);
    return shepard_gamma_from_sum(s);
  };
  const double R = 0.7;
  const auto wall = floor_segments(7);
  // just behind the wall: just under 1/2 (continuous across the wall), decreasing with depth
  CHECK(gamma_any(wall, v2(0.123, -1e-9), 1.0) == Approx(0.5).margin(1e-7));
  CHECK(gamma_any(wall, v2(0.123, -0.1), 1.0) == Approx(1.0 - 0.644995).margin(1e-6));
  for (const Vec<2>& p : {v2(0.11, -0.05), v2(0.3, -0.3), v2(-0.2, -0.6)})
    CHECK(gamma_any(wall, p, R) == Approx(brute_force(p, R, [](double, double y) { return y > 0; })).margin(1e-6));
  // the fluid side is unchanged, including near distance R where 1 + sum rounds about 1
  CHECK(gamma_any(wall, v2(0.123, 0.3), 1.0) == Approx(0.867849).margin(1e-6));
  CHECK(gamma_any(wall, v2(0.123, 1.0 - 1e-12), 1.0) == Approx(1.0).margin(1e-12));
  // interior corner (fluid in x > 0, y > 0), points that crossed the side wall or the corner
  const std::vector<Seg> inner = {{v2(4, 0), v2(0, 0), v2(0, 1)}, {v2(0, 0), v2(0, 4), v2(1, 0)}};
  auto in_inner = [](double x, double y) { return x > 0 && y > 0; };
  for (const Vec<2>& p : {v2(-0.02, 0.3), v2(-0.05, 0.01), v2(-0.01, -0.02)})
    CHECK(gamma_any(inner, p, R) == Approx(brute_force(p, R, in_inner)).margin(1e-6));
  // exterior corner (solid quadrant x < 0, y < 0): points inside the solid
  const std::vector<Seg> outer = {{v2(-4, 0), v2(0, 0), v2(0, 1)}, {v2(0, 0), v2(0, -4), v2(1, 0)}};
  auto in_outer = [](double x, double y) { return x > 0 || y > 0; };
  for (const Vec<2>& p : {v2(-0.05, -0.02), v2(-0.3, -0.1)})
    CHECK(gamma_any(outer, p, R) == Approx(brute_force(p, R, in_outer)).margin(1e-6));
}

TEST_CASE("Numerical Shepard (4.51) with many points converges to the analytical value", "[unit][nfm]") {
  // gamma = 1 - sum_j s_j f(|x_i - x_j|/R) (x_i - x_j).n_out with f = (7/pi) g_2 / R^2 (nfm.md §4-5)
  auto g2 = [](double r) { return 0.5 - 2.5 * r * r + 4 * r * r * r - 2.5 * std::pow(r, 4) + 4.0 / 7 * std::pow(r, 5) - 1 / (14 * r * r); };
  const double R = 1.0, d = 0.05;
  const double exact = gamma_of(floor_segments(3), v2(0.0, d), R);
  double prev_err = 1;
  for (int m : {20, 80, 320, 1280}) {
    // wall points on y = 0 for |x| < R, n_out = (0, -1)
    double g = 1.0;
    const double s = 2 * R / m;
    for (int q = 0; q < m; ++q) {
      const double xq = -R + (q + 0.5) * s;
      const double r = std::hypot(xq, d) / R;
      if (r >= 1) continue;
      const double f = 7 / M_PI * g2(r) / (R * R);
      g -= s * f * (d * -1.0);  // (x_i - x_j).n_out = d * (-1)
    }
    const double err = std::abs(g - exact);
    INFO("m = " << m << ": |numerical - analytical| = " << err);
    CHECK((err < prev_err || err < 1e-12));
    prev_err = err;
  }
  CHECK(prev_err < 1e-6);
}

namespace {

// the five-pointed star of cases/star_body_2d.yaml: tips at 0.15 m, notches at r_i
// (area 0.03 m^2), vertices counter-clockwise from the top tip, fluid outside
std::vector<Vec<2>> star_vertices() {
  const double Ro = 0.15, Ri = 0.03 / (5 * Ro * std::sin(M_PI / 5));
  std::vector<Vec<2>> v;
  for (int k = 0; k < 10; ++k) {
    const double a = M_PI / 2 + k * M_PI / 5, r = k % 2 == 0 ? Ro : Ri;
    v.push_back(v2(0.5 + r * std::cos(a), 0.5 + r * std::sin(a)));
  }
  return v;
}

// segments of a counter-clockwise polygon with the fluid outside: n_in = the outward normal
std::vector<Seg> outside_of(const std::vector<Vec<2>>& v) {
  std::vector<Seg> s;
  for (size_t k = 0; k < v.size(); ++k) {
    const Vec<2> a = v[k], b = v[(k + 1) % v.size()], t = b - a;
    const double l = std::sqrt(norm2(t));
    s.push_back({a, b, v2(t[1] / l, -t[0] / l)});
  }
  return s;
}

// even-odd rule
bool in_polygon(const std::vector<Vec<2>>& v, double x, double y) {
  bool in = false;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i][1] > y) != (v[j][1] > y) && x < (v[j][0] - v[i][0]) * (y - v[i][1]) / (v[j][1] - v[i][1]) + v[i][0]) in = !in;
  }
  return in;
}

}  // namespace

TEST_CASE("Shepard factor near the star's acute tips, reflex notches and thin arms", "[unit][nfm]") {
  // thesis 4.6.1's star (Fig. 4.24): 46-degree tips, 118-degree fluid wedges at the notches, arms
  // narrower than the support (0.08 m at the base, 2 R at R/dx = 4, dx = 0.01): a support that
  // crosses an arm holds fluid on both sides, and a point in the notch sees the two faces and
  // the arms behind them. The brute-force cells are counted by their centre (even-odd rule): the
  // error is random across the polygon's edges, about 1e-5 at 800 cells per R.
  const auto v = star_vertices();
  const auto segs = outside_of(v);
  const double R = 0.04;
  auto fluid = [&](double x, double y) { return !in_polygon(v, x, y); };
  auto gamma_any = [&](const Vec<2>& x) {
    double s = 0;
    for (const Seg& g : segs) s += shepard_gamma_segment(x, g.a, g.b, g.n_in, R);
    return shepard_gamma_from_sum(s);
  };
  const Vec<2> tip = v[0], notch = v[5], tip2 = v[2];
  const Vec<2> mid_arm = 0.5 * (tip + v[1]);  // middle of a face of the top arm, arm width about R there
  const Vec<2> n_face = segs[0].n_in;
  std::vector<Vec<2>> points = {
      tip + v2(0, 0.005),             // just beyond the top tip
      tip + v2(0.006, -0.01),         // beside the tip, both faces within R
      tip + v2(0, -0.02),             // inside the tip (a particle that crossed)
      notch + v2(0, -0.004),          // in the bottom notch's wedge
      notch + v2(0.003, -0.02),       // below it, the two lower arms within R
      mid_arm + 0.01 * n_face,        // 0.01 m off the face of a thin arm: the far face within R
      mid_arm + 0.002 * n_face,       // nearly on it
      tip2 + v2(-0.01, 0.0),          // beyond a side tip
  };
  for (const Vec<2>& p : points) {
    const double g = gamma_any(p), ref = brute_force(p, R, fluid, 800);
    INFO("point (" << p[0] << ", " << p[1] << "): analytical " << g << ", brute force " << ref);
    CHECK(g == Approx(ref).margin(2e-4));
  }
  // and the star's area from the same integrals: gamma = 1 far away
  CHECK(gamma_any(v2(0.5, 0.9)) == 1.0);
}
