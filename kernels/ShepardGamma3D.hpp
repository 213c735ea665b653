#pragma once
// Analytical Shepard factor in 3D for Wendland C2 (Violeau et al.; thesis 4.60-4.82, nfm.md §7):
// gamma_i = shepard_gamma_from_sum(sigma_i), sigma_i = sum over wall triangles tau of
//   gamma_tau = sign(dl) [ -w Gamma(d) + sum over edges s of tau of
//               sign(n_s . p_sk) ( sign(r_is2 . t_s) Phi(r_is2, r_ik, d) - sign(r_is1 . t_s) Phi(r_is1, r_ik, d) ) ]
// (4.80)-(4.82), lengths in units of R, with
//   dl = n_in . (x_i - v0) / R the signed particle-plane distance (> 0 on the fluid side), d = |dl|;
//   Gamma(d) = (1 - d)^6 (1 + 3d + 3d^2) / 2 the small circle around sigma (4.65), sigma the
//     projection of x_i on the plane, w its weight below;
//   Phi(r, a, d) the edge primitive (4.70)-(4.79), a = r_ik the particle-foot distance;
//   n_s the in-plane edge normal pointing out of the triangle, t_s the edge tangent and the
//     signed abscissae of the vertices along t_s measured from the foot kappa of sigma.
// Sign conventions (nfm.md §0, §7): n_in points into the fluid; sign(n_s . p_sk) = +1 when sigma
// is on the triangle's side of the edge's line; the factor sign(dl), not printed in (4.80), makes
// the term odd in the signed distance (the integrand d_n f(r) of int_tau W . n dS is), so that a
// particle behind the plane (exterior corners, a curved wall seen from its convex side) comes out
// right. The term jumps at dl = 0 (by the Gamma weight; shepard_gamma_from_sum compensates the
// jump of the sum when a particle crosses a wall), so every triangle of a plane must take the
// same side for a particle on it: for |dl| < 1e-12 the fluid side is taken (sign +1), whatever
// the round-off in dl of each triangle. A particle up to 1e-12 R behind a wall is thus evaluated
// as on the wall, which is continuous with its true value; gamma = 1/2 on a flat wall at d = 0.
//
// Orientation. The vertices may be listed in either order: the plane's normal is the geometric
// one, cross(v1 - v0, v2 - v0) normalised (about which the vertices are counter-clockwise, so
// t_s x normal is the outward edge normal of every edge), and n_in only picks the fluid side.
//
// Phi (4.73). Its two arcsines are written as atan2 of their exact numerator and denominator:
//   arcsin((dr + a^2) / (a (r + d))) = atan2(dr + a^2, q w),
//   arcsin((dr - a^2) / (a (r - d))) = atan2(d w^2 - q^2 r, q w (r + d)),
// with q = sqrt(a^2 - d^2) = p_sk (the in-plane distance sigma-kappa) and w = sqrt(r^2 - a^2) = xi
// (the abscissa along the edge), both taken from the geometry rather than from a and r. This is
// the arcsine with its argument clamped to [-1, 1] (its values at r = a are exactly +-pi/2, so
// Phi(a) = 0), without the loss of accuracy of the arcsine near +-1 (nfm.md quotes 1e-9 near
// r = a) and of a^2 - d^2 when p_sk << d; ln(sqrt(r^2 - a^2) + r) - ln a is log1p. No term
// divides by d, so d -> 0 needs no special case: Phi(r, a, 0) = 0 and Gamma(0) = 1/2.
// Phi is evaluated at min(r, 1) (phi = 0 beyond the support, (4.64)), and is 0 for r <= a or a >= 1.
//
// Singular positions of sigma (thesis §4.3.1.2). The thesis gives the Gamma term to a triangle
// holding sigma, split 1/2 on an edge and 1/N_s on a vertex between the triangles there, which
// needs the mesh's topology. Instead w is the angle fraction of the triangle at sigma, which needs
// none: w = 1 strictly inside, 1/2 on an edge, theta_k / (2 pi) on vertex k (theta_k the interior
// angle there), 0 outside; on a coplanar fan this equals the thesis's rule (both exact: the
// fractions of the triangles around sigma add up to 1). The edge whose line holds sigma gives no
// edge term: its two one-sided limits are opposite (+-Gamma/2 times the subtended angle over pi),
// their mean is 0, and the Gamma weight takes the jump. Unlike 1/N_s this is also exact on a
// fold or a curved wall (d > 0): a triangle's term, d int_tau f dA, is continuous in x, and the
// angle fraction with the edge left out is its value there (checked on an icosphere and a cube).
// Tolerance. An edge with p_sk < tol = 1e-9 d + 1e-12 (units of R) is taken to hold sigma and
// skipped, and then w = (1/2pi) sum over the edges not skipped of sign(n_s . p_sk) times the
// angle the edge subtends at sigma. On an edge or a vertex this is the angle fraction above; near
// them it is continuous, and because both triangles of a shared edge skip it or not alike, the
// weights of a coplanar fan add up to 1 at every position. Separate "within tol of one edge line"
// / "of two" tests do not: a few tol from a vertex a point can be within tol of two edge lines
// without being at the vertex (a fan's weights then added up to 3/2 1e-9 R from a vertex of the
// 10 x 10 grid of tests/test_nfm_shepard3d.cpp: gamma 0.25 low at d = 0). The skipped
// edge's neglected part is the regular part of its term, O(p_sk / d): hence tol relative to d
// (an absolute 1e-9 gives gamma = 1/2 instead of 1/4 on a face's plane 1e-10 from a 90 degree
// fold); the absolute 1e-12 absorbs round-off in the position of a particle set right above a
// vertex or an edge (without it, a particle within round-off of a shared vertex could be counted
// inside two triangles of the fan, or none). Each edge's p_sk, distance to the plane and vertex
// abscissae come from the perpendicular m from x to the edge's line, taken from the edge's vertex
// nearer to x: m is the same vector, bit for bit, in both triangles of the edge, and p_sk is
// accurate relative to |m| rather than to the size of the triangle. (Where the normals of
// coplanar neighbours differ by round-off, p_sk still differs between them by ~1e-16 d, which
// the near-singular edge terms turn into errors of ~1e-9 in gamma 1e-9 R from a vertex.)
// Limitation: a particle on a fold line of the wall (e.g. the edge of a box), or within ~1e-12 R
// of it, is seen by each face on its own edge (d and p_sk both ~0, the limit depends on their
// ratio) and gets the coplanar value: 1/2 on a 90 degree edge, 5/8 at a cube's corner, instead
// of 1/4 and 1/8. From 1e-10 R away from the line, in any direction, the value is right (1e-10).
#include "kernels/Math.hpp"
#include "kernels/ShepardGamma2D.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

namespace shepard3d {

KOKKOS_INLINE_FUNCTION Vec<3> cross(const Vec<3>& u, const Vec<3>& v) {
  return Vec<3>{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
}

// Phi (4.73)-(4.79) from r <= 1, a = sqrt(d^2 + q^2), d >= 0, q = p_sk > 0 and w = sqrt(r^2 - a^2) >= 0.
KOKKOS_INLINE_FUNCTION double Phi_qw(double r, double a, double d, double q, double w) {
  if (!(w > 0.0) || !(q > 0.0)) return 0.0;
  constexpr double inv_64pi = 1.0 / (64.0 * 3.14159265358979323846);
  const double a2 = a * a, a4 = a2 * a2, a6 = a4 * a2;
  const double d2 = d * d, d4 = d2 * d2, d6 = d4 * d2;
  const double r2 = r * r, r3 = r2 * r, r4 = r2 * r2, r5 = r4 * r;
  // P1 (4.74); ln(sqrt(r^2 - a^2) + r) - ln(a) = log1p((w + r - a) / a), r - a = w^2 / (r + a)
  const double P1 = (15.0 * a6 + 18.0 * d2 * a4 + 168.0 * a4 + 24.0 * d4 * a2 + 224.0 * d2 * a2 + 48.0 * d6 + 448.0 * d4) * d * q;
  const double L = kmath::log1p((w + w * w / (r + a)) / a);
  // P2 (4.75) and P3 (4.76), each minus its value at r = a (arcsine +pi/2 and -pi/2):
  // arcsin(.) - pi/2 = -atan2(q w, dr + a^2); arcsin(.) + pi/2 = atan2(q w (r + d), q^2 r - d w^2)
  const double dp = d + 1.0, dm = d - 1.0;
  const double dp2 = dp * dp, dm2 = dm * dm;
  const double c2 = 8.0 * dp2 * dp2 * dp2 * (3.0 * d2 - 3.0 * d + 1.0);
  const double c3 = 8.0 * dm2 * dm2 * dm2 * (3.0 * d2 + 3.0 * d + 1.0);
  const double B2 = -kmath::atan2(q * w, d * r + a2);
  const double B3 = kmath::atan2(q * w * (r + d), q * q * r - d * w * w);
  // P4 + P5 + P6 (4.77)-(4.79), times d sqrt(a^2 - d^2) sqrt(r^2 - a^2) (zero at r = a)
  const double P4 = 12.0 * d2 * r3 - 80.0 * d2 * r2 + 18.0 * d2 * a2 * r + 224.0 * d2 * r + 24.0 * d4 * r;
  const double P5 = -128.0 * a4 - 160.0 * d2 * a2 - 224.0 * a2 - 240.0 * d4 - 336.0 * d2 + 112.0;
  const double P6 = 8.0 * r5 - 48.0 * r4 + 112.0 * r3 - 112.0 * r2 + 10.0 * a2 * r3 - 64.0 * a2 * r2 + 168.0 * a2 * r + 15.0 * a4 * r;
  return inv_64pi * (P1 * L + c2 * B2 + c3 * B3 + (P4 + P5 + P6) * d * q * w);
}

}  // namespace shepard3d

// Edge primitive Phi(r, a = r_ik, d = d_n) of (4.70)-(4.79), lengths in units of R, d <= a:
// int_a^min(r,1) d sqrt(a^2 - d^2) / (4 pi) (1 - s)^6 (1 + 3s + 3s^2) / ((s^2 - d^2) sqrt(s^2 - a^2)) ds.
KOKKOS_INLINE_FUNCTION double shepard_Phi(double r, double a, double d) {
  if (d < 0.0) d = -d;
  if (r > 1.0) r = 1.0;
  if (a >= 1.0 || r <= a) return 0.0;
  const double q2 = (a - d) * (a + d);
  if (!(q2 > 0.0)) return 0.0;
  return shepard3d::Phi_qw(r, a, d, kmath::sqrt(q2), kmath::sqrt((r - a) * (r + a)));
}

// Gamma (4.82), the term of a full circle around sigma: the kernel mass beyond a plane at
// distance d (1/2 at d = 0), so that gamma = 1 - Gamma(d) on a flat wall.
KOKKOS_INLINE_FUNCTION double shepard_Gamma(double d) {
  const double e = 1.0 - d, e2 = e * e;
  return 0.5 * e2 * e2 * e2 * (1.0 + 3.0 * d + 3.0 * d * d);
}

// Contribution gamma_tau of triangle (v0, v1, v2) to sigma = sum over triangles, gamma =
// shepard_gamma_from_sum(sigma), for a particle at x, support radius R; n_in: the triangle's
// normal into the fluid (only its side is used). Algorithm of nfm.md §7 with the weights above.
KOKKOS_INLINE_FUNCTION double shepard_gamma_triangle(const Vec<3>& x, const Vec<3>& v0, const Vec<3>& v1,
                                                     const Vec<3>& v2, const Vec<3>& n_in, double R) {
  constexpr double two_pi = 2.0 * 3.14159265358979323846;
  const Vec<3> nc = shepard3d::cross(v1 - v0, v2 - v0);  // the vertices are counter-clockwise about nc
  const double nc_len = kmath::sqrt(norm2(nc));
  if (!(nc_len > 0.0)) return 0.0;  // degenerate triangle
  const Vec<3> n = (1.0 / nc_len) * nc;
  const double side = dot(n, n_in) < 0.0 ? -1.0 : 1.0;   // n_in = side * n
  const double dl = side * dot(n, x - v0) / R;            // signed distance, > 0 in front
  const double d = dl < 0.0 ? -dl : dl;
  if (d >= 1.0) return 0.0;
  // pass 1, per edge s1 -> s2, from m = the perpendicular from x to the edge's line (taken from
  // the vertex nearer to x; the same vector, bit for bit, in the triangle across the edge):
  // h = signed in-plane distance of sigma to the line (> 0 outside, p_sk = |h|), de = the
  // distance to the plane seen from the edge (d up to round-off), xi1 < xi2 = the abscissae of
  // s1, s2 from kappa; the edge is skipped (taken to hold sigma) when p_sk < 1e-9 de + 1e-12
  const Vec<3>* const v[3] = {&v0, &v1, &v2};
  double h[3], de[3], xi1[3], xi2[3];
  bool skip[3], skipped = false, inside = true;
  for (int k = 0; k < 3; ++k) {
    const Vec<3> p1 = *v[k] - x, p2 = *v[(k + 1) % 3] - x;
    const Vec<3> e = p2 - p1;
    const Vec<3> t = (1.0 / kmath::sqrt(norm2(e))) * e;
    const Vec<3> nu = shepard3d::cross(t, n);  // in-plane, out of the triangle
    const Vec<3> pn = norm2(p1) < norm2(p2) ? p1 : p2;
    const Vec<3> m = pn - dot(pn, t) * t;
    h[k] = -dot(nu, m) / R;
    const double dm = dot(n, m) / R;
    de[k] = dm < 0.0 ? -dm : dm;
    xi1[k] = dot(t, p1) / R;
    xi2[k] = dot(t, p2) / R;
    const double q = h[k] < 0.0 ? -h[k] : h[k];
    skip[k] = q < 1e-9 * de[k] + 1e-12;
    if (skip[k]) skipped = true;
    else if (h[k] > 0.0) inside = false;
  }
  // pass 2: the edge terms of (4.81) and, with an edge skipped, the angle fraction w
  double edges = 0.0, angle = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (skip[k]) continue;
    const double q = h[k] < 0.0 ? -h[k] : h[k];  // p_sk
    const double sgn = h[k] < 0.0 ? 1.0 : -1.0;  // sign(n_s . p_sk)
    if (skipped) angle += sgn * kmath::atan2(q * (xi2[k] - xi1[k]), q * q + xi1[k] * xi2[k]);
    const double dk = de[k];
    const double a2 = dk * dk + q * q;
    if (a2 >= 1.0) continue;  // the edge's line misses the support
    const double a = kmath::sqrt(a2);
    const double w_clip = kmath::sqrt((1.0 - a) * (1.0 + a));  // abscissa where r = 1
    if (xi1[k] >= w_clip || xi2[k] <= -w_clip) continue;       // the edge misses the support
    double term = 0.0;
    const double xis[2] = {xi2[k], xi1[k]};
    for (int j = 0; j < 2; ++j) {
      const double xi = xis[j];
      const double w = xi < 0.0 ? -xi : xi;
      if (w == 0.0) continue;  // Phi(a) = 0
      const double phi = w >= w_clip ? shepard3d::Phi_qw(1.0, a, dk, q, w_clip)
                                     : shepard3d::Phi_qw(kmath::sqrt(a2 + w * w), a, dk, q, w);
      term += (j == 0 ? 1.0 : -1.0) * (xi < 0.0 ? -1.0 : 1.0) * phi;
    }
    edges += sgn * term;
  }
  const double w = skipped ? angle / two_pi : (inside ? 1.0 : 0.0);
  const double sign_dl = dl < -1e-12 ? -1.0 : 1.0;  // the fluid side within 1e-12 of the plane
  return sign_dl * (edges - w * shepard_Gamma(d));
}

}  // namespace ondine
