// Smoothing kernels: unit integral, W(R) = 0, derivative = finite difference of W.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernels/SmoothingKernels.hpp"

using namespace ondine;

namespace {

// Integral of W over its support by composite Simpson in r (radial symmetry):
// 2 pi r W(r) dr in 2D, 4 pi r^2 W(r) dr in 3D.
template <int D, class K>
double integral(const K& W, double R) {
  const int n = 20000;
  const double h = R / n;
  double s = 0;
  for (int k = 0; k <= n; ++k) {
    const double r = k * h;
    const double shell = D == 2 ? 2 * M_PI * r : 4 * M_PI * r * r;
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    s += w * shell * W.value(r);
  }
  return s * h / 3;
}

template <int D, class K>
void check_kernel() {
  for (double R : {0.013, 1.0, 3.7}) {
    const K W(R);
    CHECK(integral<D>(W, R) == Approx(1.0).epsilon(1e-6));
    CHECK(W.value(R) == 0.0);
    CHECK(W.value(1.01 * R) == 0.0);
    CHECK(W.derivative(R) == Approx(0.0).margin(1e-12 / std::pow(R, D + 1)));
    CHECK(W.value(0.0) > 0.0);
    // derivative against a central finite difference, away from the branch points
    for (double q : {0.05, 0.17, 0.33, 0.41, 0.55, 0.66, 0.78, 0.93}) {
      const double r = q * R, e = 1e-6 * R;
      const double fd = (W.value(r + e) - W.value(r - e)) / (2 * e);
      CHECK(W.derivative(r) == Approx(fd).epsilon(1e-6).margin(1e-9 * W.value(0) / R));
      CHECK(W.derivative(r) <= 0.0);
    }
  }
}

}  // namespace

TEST_CASE("Wendland C2 is normalised, vanishes at R and has the right derivative", "[unit][kernel]") {
  check_kernel<2, WendlandC2<2>>();
  check_kernel<3, WendlandC2<3>>();
  // thesis (2.8): W(0) = 7/(pi R^2) in 2D and 21/(2 pi R^3) in 3D
  CHECK(WendlandC2<2>(2.0).value(0) == Approx(7 / (M_PI * 4)));
  CHECK(WendlandC2<3>(2.0).value(0) == Approx(21 / (2 * M_PI * 8)));
}

TEST_CASE("Quartic spline of V&I is normalised with the exact constant", "[unit][kernel]") {
  check_kernel<2, QuarticSpline<2>>();
  check_kernel<3, QuarticSpline<3>>();
}

TEST_CASE("Cubic spline of the course chapter is normalised", "[unit][kernel]") {
  check_kernel<2, CubicSpline<2>>();
  check_kernel<3, CubicSpline<3>>();
}
