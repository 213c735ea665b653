#pragma once
// Analytical Shepard factor in 2D for Wendland C2 (Feldman; Leroy et al.;
// thesis 4.52-4.59): gamma_i = 1 + sum over wall segments of gamma_s,
//   gamma_s = sign(n_in . x_ia) / (12 pi) [ sign(t . x_bi) F(xi_b, d) - sign(t . x_ai) F(xi_a, d) ]   (4.55)
// with F(xi, d) of (4.56)-(4.58) = 84 d int_0^xi g_2(sqrt(d^2 + t^2)) dt, lengths in units of R,
// n_in the segment normal pointing into the fluid (nfm.md §0), and the wall limit (4.59)
// gamma_s = -(sign(t . x_bi) - sign(t . x_ai)) / 4 when the particle lies on the segment's line.
#include "kernels/Math.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

// (4.56)-(4.58); d > 0, |xi| <= sqrt(1 - d^2).
KOKKOS_INLINE_FUNCTION double shepard_F(double xi, double d) {
  const double d2 = d * d, d3 = d2 * d, d5 = d3 * d2, d7 = d5 * d2;
  const double s2 = xi * xi + d2, s = kmath::sqrt(s2);
  const double xi2 = xi * xi, xi3 = xi2 * xi, xi5 = xi3 * xi2;
  return (15.0 * d7 + 126.0 * d5) * kmath::asinh(xi / d) - 6.0 * kmath::atan(xi / d) + 8.0 * d * xi * s2 * s2 * s +
         (10.0 * d3 + 84.0 * d) * xi * s2 * s + (15.0 * d5 + 126.0 * d3) * xi * s - 42.0 * d * xi5 -
         (140.0 * d3 + 70.0 * d) * xi3 - (210.0 * d5 + 210.0 * d3 - 42.0 * d) * xi;
}

KOKKOS_INLINE_FUNCTION double sign_of(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

// Contribution gamma_s of segment [a, b] (inward unit normal n_in) to the Shepard
// factor of a particle at x, support radius R (thesis 4.55, algorithm of nfm.md §6).
KOKKOS_INLINE_FUNCTION double shepard_gamma_segment(const Vec<2>& x, const Vec<2>& a, const Vec<2>& b,
                                                    const Vec<2>& n_in, double R) {
  const Vec<2> ab = b - a;
  const double len = kmath::sqrt(norm2(ab));
  const Vec<2> t = (1.0 / len) * ab;
  const double dl = dot(n_in, x - a) / R;  // signed normal distance, > 0 in front
  const double d = dl < 0 ? -dl : dl;
  if (d >= 1.0) return 0.0;
  const double sb = sign_of(dot(t, b - x)), sa = sign_of(dot(t, a - x));
  // d_n -> 0 limit (4.59); also used below 1e-12 R where F's xi/d loses accuracy
  if (d < 1e-12) return -0.25 * (sb - sa);
  const double lim = kmath::sqrt(1.0 - d * d);
  const double ra2 = norm2(x - a) / (R * R) - d * d, rb2 = norm2(x - b) / (R * R) - d * d;
  const double xa = kmath::fmin(lim, kmath::sqrt(ra2 > 0 ? ra2 : 0.0));
  const double xb = kmath::fmin(lim, kmath::sqrt(rb2 > 0 ? rb2 : 0.0));
  constexpr double inv_12pi = 1.0 / (12.0 * 3.14159265358979323846);
  return sign_of(dl) * inv_12pi * (sb * shepard_F(xb, d) - sa * shepard_F(xa, d));
}

// gamma_i from sigma = sum over segments of gamma_s. The divergence theorem behind (4.46)-(4.50)
// gives gamma = 1 + sigma only where x_i lies in the fluid (the inner sphere of (4.49) is then
// inside the domain); on the solid side of a wall (a particle that has crossed it) the inner
// sphere is outside and gamma = sigma, which is then 1 + sigma - 1 with 1 + sigma in (1, 2].
// Since gamma <= 1 everywhere, 1 + sigma > 1 identifies the solid side; the margin 1e-9 keeps
// round-off of a fluid particle near distance R from a wall on the fluid side. Without this a
// particle just behind a wall got gamma = 1.5 (clipped to 1) instead of just under 1/2.
KOKKOS_INLINE_FUNCTION double shepard_gamma_from_sum(double sigma) {
  const double g = 1.0 + sigma;
  return g > 1.0 + 1e-9 ? g - 1.0 : g;
}

}  // namespace ondine
