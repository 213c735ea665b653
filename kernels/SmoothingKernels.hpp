#pragma once
// Smoothing kernels W(r, R) with R the support radius (thesis convention).
// Each kernel gives W(r) and dW/dr; the gradient w.r.t. x_i is dW/dr * x_ij / r_ij
// (points from i towards j since dW/dr < 0, operators-and-schemes §0).
#include <Kokkos_Core.hpp>

namespace ondine {

namespace detail {
constexpr double pi = 3.14159265358979323846;
}

// Wendland C2, thesis (2.7)-(2.8): W = C/vol(P) (1-q)^4 (1+4q), C = 7 (2D), 14 (3D).
template <int D>
struct WendlandC2 {
  static constexpr const char* name = "wendland_c2";
  double R, inv_R, sigma;  // sigma = normalisation / R^D
  WendlandC2() = default;
  explicit WendlandC2(double R_)
      : R(R_), inv_R(1.0 / R_),
        sigma(D == 2 ? 7.0 / (detail::pi * R_ * R_) : 21.0 / (2.0 * detail::pi * R_ * R_ * R_)) {}

  KOKKOS_INLINE_FUNCTION double value(double r) const {
    if (r >= R) return 0.0;
    const double q = r * inv_R;
    const double a = 1.0 - q;
    return sigma * a * a * a * a * (1.0 + 4.0 * q);
  }
  KOKKOS_INLINE_FUNCTION double derivative(double r) const {
    if (r >= R) return 0.0;
    const double q = r * inv_R;
    const double a = 1.0 - q;
    return -20.0 * sigma * inv_R * q * a * a * a;
  }
};

// Quartic (M5) spline of Violeau & Issa [V&I 2], smoothing length h = R / 2.5;
// exact normalisations 96/(1199 pi h^2) in 2D and 1/(20 pi h^3) in 3D (digest §1.2).
template <int D>
struct QuarticSpline {
  static constexpr const char* name = "quartic_spline";
  double inv_h, sigma_over_h_inv;
  double sigma;
  QuarticSpline() = default;
  explicit QuarticSpline(double R) {
    const double h = R / 2.5;
    inv_h = 1.0 / h;
    sigma = D == 2 ? 96.0 / (1199.0 * detail::pi * h * h) : 1.0 / (20.0 * detail::pi * h * h * h);
    sigma_over_h_inv = sigma * inv_h;
  }
  KOKKOS_INLINE_FUNCTION double value(double r) const {
    const double q = r * inv_h;
    if (q >= 2.5) return 0.0;
    const double a = 2.5 - q, b = 1.5 - q, c = 0.5 - q;
    double t = a * a * a * a;
    if (q < 1.5) t -= 5.0 * b * b * b * b;
    if (q < 0.5) t += 10.0 * c * c * c * c;
    return sigma * t;
  }
  KOKKOS_INLINE_FUNCTION double derivative(double r) const {
    const double q = r * inv_h;
    if (q >= 2.5) return 0.0;
    const double a = 2.5 - q, b = 1.5 - q, c = 0.5 - q;
    double t = -4.0 * a * a * a;
    if (q < 1.5) t += 20.0 * b * b * b;
    if (q < 0.5) t -= 40.0 * c * c * c;
    return sigma_over_h_inv * t;
  }
};

// Cubic spline of the course chapter, support radius R (= the course's h):
// 40/(7 pi R^2) in 2D, 8/(pi R^3) in 3D (digest §1.3).
template <int D>
struct CubicSpline {
  static constexpr const char* name = "cubic_spline";
  double R, inv_R, sigma;
  CubicSpline() = default;
  explicit CubicSpline(double R_)
      : R(R_), inv_R(1.0 / R_),
        sigma(D == 2 ? 40.0 / (7.0 * detail::pi * R_ * R_) : 8.0 / (detail::pi * R_ * R_ * R_)) {}
  KOKKOS_INLINE_FUNCTION double value(double r) const {
    if (r >= R) return 0.0;
    const double q = r * inv_R;
    if (q <= 0.5) return sigma * (6.0 * (q * q * q - q * q) + 1.0);
    const double a = 1.0 - q;
    return sigma * 2.0 * a * a * a;
  }
  KOKKOS_INLINE_FUNCTION double derivative(double r) const {
    if (r >= R) return 0.0;
    const double q = r * inv_R;
    if (q <= 0.5) return sigma * inv_R * 6.0 * (3.0 * q * q - 2.0 * q);
    const double a = 1.0 - q;
    return -sigma * inv_R * 6.0 * a * a;
  }
};

}  // namespace ondine
