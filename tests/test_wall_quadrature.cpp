// The 3D NFM wall quadrature by clipping (thesis §4.4, method/nfm.md §11,
// geometry/TriangleQuadrature.hpp): weights summing to the area, exactness for linear
// integrands, points in the triangle, and the flat-wall accuracy test (4.91)-(4.92).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/TriangleQuadrature.hpp"
#include "kernels/SmoothingKernels.hpp"

using namespace ondine;

namespace {

using P3 = std::array<double, 3>;

struct Tri {
  std::string name;
  P3 a, b, c;
  double h;
};

P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double area_of(const Tri& t) {
  const P3 c = cross(sub(t.b, t.a), sub(t.c, t.a));
  return 0.5 * std::sqrt(dot(c, c));
}

// a rotation (about a skew axis) and a translation, so that the triangles are not in a
// coordinate plane
P3 place(double x, double y, double z, const P3& shift = {0.3, -1.7, 2.2}) {
  const double c1 = std::cos(0.7), s1 = std::sin(0.7), c2 = std::cos(-1.1), s2 = std::sin(-1.1);
  const double x1 = c1 * x - s1 * y, y1 = s1 * x + c1 * y;     // about z
  const double y2 = c2 * y1 - s2 * z, z2 = s2 * y1 + c2 * z;    // about x
  return {x1 + shift[0], y2 + shift[1], z2 + shift[2]};
}

std::vector<Tri> triangles() {
  const P3 far{1000.25, -730.5, 512.125};
  return {
      {"right, legs on the grid lines", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.1},
      {"right, right angle at v1 (edges on grid lines to round-off)", place(0, 0, 0), place(2, 0, 0), place(2, 1.5, 0),
       0.25},
      {"obtuse", place(0, 0, 0), place(1, 0, 0), place(2.3, 0.4, 0), 0.13},
      {"obtuse, v2 behind v0", place(0, 0, 0), place(1, 0, 0), place(-1.7, 0.6, 0), 0.11},
      {"thin sliver along e1", place(0, 0, 0), place(10, 0, 0), place(5, 1e-3, 0), 0.3},
      {"thin sliver, v0 -> v1 its short edge", place(0, 0, 0), place(1e-3, 0, 0), place(7, 3, 0), 0.2},
      {"large vs h", place(0, 0, 0), place(9.7, 0.3, 0), place(3.1, 8.9, 0), 0.07},
      {"smaller than h", place(0.4, 0.1, 0), place(0.41, 0.1, 0), place(0.403, 0.008, 0), 1.0},
      {"far from the origin", place(0, 0, 0, far), place(3, 0.2, 0, far), place(1.2, 2.5, 0, far), 0.17},
  };
}

// Neumaier's compensated sum: a plain sum of ~1e4 weights loses ~1e-13 by itself
struct Sum {
  double s = 0, c = 0;
  void add(double x) {
    const double t = s + x;
    c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
    s = t;
  }
  double value() const { return s + c; }
};

// Wendland C2 in 3D with R = 1 (the solver's kernel)
const WendlandC2<3> kW(1.0);

// (4.92): the integral of W over the plane at distance d from the particle, R = 1
double flat_wall_integral(double d) {
  return 0.75 * std::pow(1 - d, 5) * (2 + 10 * d + 16 * d * d);
}

}  // namespace

TEST_CASE("Clipped wall quadrature: weights sum to the triangle's area", "[unit][nfm]") {
  for (const Tri& t : triangles()) {
    INFO(t.name);
    const auto pts = clip_quadrature(t.a, t.b, t.c, t.h);
    const double A = area_of(t);
    Sum total;
    double amin = A, amax = 0;
    for (const auto& q : pts) {
      total.add(q.area);
      amin = std::min(amin, q.area);
      amax = std::max(amax, q.area);
    }
    REQUIRE(!pts.empty());
    CHECK(std::abs(total.value() - A) <= 1e-13 * A);
    CHECK(amin >= 1e-14 * A);                  // slivers were merged away
    CHECK(amax <= t.h * t.h * (1 + 1e-12));    // one piece per square at most
  }
  // a triangle smaller than h: one point, its centroid, with its area
  const Tri& small = triangles()[7];
  const auto one = clip_quadrature(small.a, small.b, small.c, small.h);
  REQUIRE(one.size() == 1);
  for (int k = 0; k < 3; ++k) CHECK(one[0].x[k] == Approx((small.a[k] + small.b[k] + small.c[k]) / 3).epsilon(1e-12));
  // a triangle made of whole squares and halves: the right triangle of legs 1 on a 0.1 grid
  // has 45 whole squares and 10 half squares
  const auto right = clip_quadrature({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.1);
  CHECK(right.size() == 55);
}

TEST_CASE("Clipped wall quadrature: exact for linear integrands", "[unit][nfm]") {
  for (const Tri& t : triangles()) {
    INFO(t.name);
    const auto pts = clip_quadrature(t.a, t.b, t.c, t.h);
    const double A = area_of(t);
    const P3 g{0.37, -1.21, 0.83};  // f(x) = f0 + g . x
    for (double f0 : {0.0, 2.5, -40.0}) {
      auto f = [&](const P3& x) { return f0 + dot(g, x); };
      const P3 centroid{(t.a[0] + t.b[0] + t.c[0]) / 3, (t.a[1] + t.b[1] + t.c[1]) / 3,
                        (t.a[2] + t.b[2] + t.c[2]) / 3};
      const double exact = A * f(centroid);
      Sum total;
      for (const auto& q : pts) total.add(q.area * f(q.x));
      const double sum = total.value();
      // relative to the integral of |f| bounded by its largest vertex value (the integral
      // itself may be near zero where f changes sign on the triangle)
      const double scale = A * std::max({std::abs(f(t.a)), std::abs(f(t.b)), std::abs(f(t.c)), std::abs(exact / A)});
      INFO("f0 = " << f0 << ", sum " << sum << ", exact " << exact);
      CHECK(std::abs(sum - exact) <= 1e-12 * scale);
    }
  }
}

TEST_CASE("Clipped wall quadrature: every point lies in the triangle", "[unit][nfm]") {
  for (const Tri& t : triangles()) {
    INFO(t.name);
    const auto pts = clip_quadrature(t.a, t.b, t.c, t.h);
    const P3 e1 = sub(t.b, t.a), e2 = sub(t.c, t.a), nn = cross(e1, e2);
    const double n2 = dot(nn, nn), L = std::sqrt(std::max({dot(e1, e1), dot(e2, e2), dot(sub(t.c, t.b), sub(t.c, t.b))}));
    double worst_plane = 0, worst_bary = 0;
    for (const auto& q : pts) {
      const P3 r = sub(q.x, t.a);
      worst_plane = std::max(worst_plane, std::abs(dot(nn, r)) / std::sqrt(n2));
      // barycentric coordinates of the point
      const double l1 = dot(cross(r, e2), nn) / n2, l2 = dot(cross(e1, r), nn) / n2, l0 = 1 - l1 - l2;
      worst_bary = std::min({worst_bary, l0, l1, l2});
    }
    const double far = std::max(std::abs(t.a[0]), std::max(std::abs(t.a[1]), std::abs(t.a[2])));
    CHECK(worst_plane <= 1e-13 * (L + far));
    // a point may be outside by round-off only, measured in the triangle's size
    CHECK(worst_bary * std::sqrt(n2) / L >= -1e-12 * (1 + far / L));
  }
}

TEST_CASE("Clipped wall quadrature: degenerate input is refused", "[unit][nfm]") {
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, -0.1), std::invalid_argument);
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0.1), std::invalid_argument);  // collinear
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 0.1), std::invalid_argument);  // repeated
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {1, 0, 0}, {0, 1, std::nan("")}, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(clip_quadrature({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1e-6), std::invalid_argument);  // 5e11 squares
}

// (4.91)-(4.92): the integral of W over a flat wall, a square of side 4R (two triangles, each
// with its own grid: the second one's e1 runs along the diagonal), against the closed form,
// for a particle at distance d in front of it and at in-plane offsets that are not
// multiples of h. The support disc lies inside the square for every offset.
TEST_CASE("Clipped wall quadrature: flat-wall accuracy (4.91)-(4.92)", "[unit][nfm]") {
  const double R = 1.0;
  const P3 c00{-2 * R, -2 * R, 0}, c10{2 * R, -2 * R, 0}, c11{2 * R, 2 * R, 0}, c01{-2 * R, 2 * R, 0};
  const std::vector<double> ds{0.0, 0.1, 0.3, 0.5};
  const std::vector<std::array<double, 2>> offsets{{0.0, 0.0},     {0.1234, 0.0567}, {0.37, -0.61},
                                                    {-0.29, 0.83}, {0.05, 0.051},    {0.9, -0.77}};
  // the closed form against the thesis's reference values of R F (nfm.md §11)
  const std::vector<double> ref{1.5, 1.39946, 0.81178, 0.25781};
  for (std::size_t k = 0; k < ds.size(); ++k) CHECK(R * flat_wall_integral(ds[k]) == Approx(ref[k]).epsilon(1e-5));

  const std::vector<int> divisions{2, 3, 4, 5, 6, 8};
  double err_h4 = 0;
  std::cout << "\nNFM wall quadrature by clipping, flat wall, Wendland C2 3D: max relative error of "
               "sum s_q W over "
            << offsets.size() << " in-plane offsets\n  h     d=0.0      d=0.1      d=0.3      d=0.5      all\n";
  for (int m : divisions) {
    const double h = R / m;
    auto pts = clip_quadrature(c00, c10, c11, h);
    const auto second = clip_quadrature(c00, c11, c01, h);
    pts.insert(pts.end(), second.begin(), second.end());
    char line[160];
    int pos = std::snprintf(line, sizeof line, "  R/%d", m);
    double all = 0;
    for (double d : ds) {
      double worst = 0;
      for (const auto& o : offsets) {
        double sum = 0;
        for (const auto& q : pts) {
          const double dx = q.x[0] - o[0], dy = q.x[1] - o[1], dz = q.x[2] - d;
          sum += q.area * kW.value(std::sqrt(dx * dx + dy * dy + dz * dz));
        }
        worst = std::max(worst, std::abs(sum - flat_wall_integral(d)) / flat_wall_integral(d));
      }
      all = std::max(all, worst);
      pos += std::snprintf(line + pos, sizeof line - pos, "  %.3e", worst);
    }
    std::snprintf(line + pos, sizeof line - pos, "  %.3e", all);
    std::cout << line << "\n";
    if (m == 4) err_h4 = all;
  }
  std::cout << std::flush;
  // measured at h = R/4: 3.8e-3 (4.1e-3 over 400 random offsets); the error goes as h^2
  // (about 0.065 (h/R)^2), R/3: 9.7e-3, R/6: 1.1e-3, R/8: 4.4e-4
  CHECK(err_h4 < 5e-3);
}
