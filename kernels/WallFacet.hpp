#pragma once
// One wall facet of the NFM walls: a segment [a, b] in 2D, a triangle (a, b, c) in 3D, with
// its unit normal n_in into the fluid (nfm.md §0). The geometry every facet user needs,
// written once for both dimensions: the Shepard factor's term (2D 4.55, 3D 4.80-4.82), the
// distance to the facet, whether a point's projection falls on it, and on which side of a
// closed wall a point lies.
#include "kernels/ShepardGamma2D.hpp"
#include "kernels/ShepardGamma3D.hpp"

namespace ondine {

template <int D>
struct Facet {
  Vec<D> a, b, c, n_in;  // c: the third vertex of a triangle (unused in 2D)
};

// The facet's term of sigma = sum over facets, gamma = shepard_gamma_from_sum(sigma).
template <int D>
KOKKOS_INLINE_FUNCTION double facet_gamma(const Vec<D>& x, const Facet<D>& f, double R) {
  if constexpr (D == 2) return shepard_gamma_segment(x, f.a, f.b, f.n_in, R);
  else return shepard_gamma_triangle(x, f.a, f.b, f.c, f.n_in, R);
}

// Barycentric coordinates (wa, wb, wc) of the projection of p on the facet's plane (3D), or
// (1 - t, t, 0) on the segment's line (2D).
template <int D>
KOKKOS_INLINE_FUNCTION void facet_barycentric(const Vec<D>& p, const Facet<D>& f, double w[3]) {
  if constexpr (D == 2) {
    const Vec<2> ab = f.b - f.a;
    const double t = dot(p - f.a, ab) / norm2(ab);
    w[0] = 1.0 - t;
    w[1] = t;
    w[2] = 0.0;
  } else {
    const Vec<3> e1 = f.b - f.a, e2 = f.c - f.a, ap = p - f.a;
    const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const double p1 = dot(ap, e1), p2 = dot(ap, e2);
    const double det = d11 * d22 - d12 * d12;
    w[1] = (d22 * p1 - d12 * p2) / det;
    w[2] = (d11 * p2 - d12 * p1) / det;
    w[0] = 1.0 - w[1] - w[2];
  }
}

// The projection of p on the facet's line or plane lies on the facet, within a relative tolerance.
template <int D>
KOKKOS_INLINE_FUNCTION bool facet_spans(const Vec<D>& p, const Facet<D>& f, double tol = 0.0) {
  double w[3];
  facet_barycentric<D>(p, f, w);
  return w[0] >= -tol && w[1] >= -tol && w[2] >= -tol;
}

// Signed distance of p to the facet's line or plane, > 0 on the fluid side.
template <int D>
KOKKOS_INLINE_FUNCTION double facet_signed_distance(const Vec<D>& p, const Facet<D>& f) {
  return dot(f.n_in, p - f.a);
}

// Squared distance from p to the closest point of the facet.
template <int D>
KOKKOS_INLINE_FUNCTION double facet_distance2(const Vec<D>& p, const Facet<D>& f) {
  const auto segment = [&](const Vec<D>& a, const Vec<D>& b) {
    const Vec<D> ab = b - a;
    double t = dot(p - a, ab) / norm2(ab);
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return norm2(p - (a + t * ab));
  };
  if constexpr (D == 2) {
    return segment(f.a, f.b);
  } else {
    if (facet_spans<D>(p, f)) {
      const double dn = facet_signed_distance<D>(p, f);
      return dn * dn;
    }
    const double ab = segment(f.a, f.b), bc = segment(f.b, f.c), ca = segment(f.c, f.a);
    return kmath::fmin(ab, kmath::fmin(bc, ca));
  }
}

// Solid angle of the triangle seen from p over 4 pi (Van Oosterom & Strackee 1983), signed
// positive when p is behind the triangle (on the side opposite to n_in). Summed over a closed
// surface it is the winding number: 0 outside, -1 inside a tank's surface (n_in inwards),
// +1 inside a body's (n_in outwards).
KOKKOS_INLINE_FUNCTION double triangle_winding(const Vec<3>& p, const Facet<3>& f) {
  const Vec<3> a = f.a - p, b = f.b - p, c = f.c - p;
  const double la = kmath::sqrt(norm2(a)), lb = kmath::sqrt(norm2(b)), lc = kmath::sqrt(norm2(c));
  double num = dot(a, shepard3d::cross(b, c));
  // the vertex order may be either way round n_in: the sign is taken from n_in
  const double orient = dot(shepard3d::cross(f.b - f.a, f.c - f.a), f.n_in) > 0 ? 1.0 : -1.0;
  const double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  constexpr double inv_2pi = 1.0 / (2.0 * 3.14159265358979323846);
  return orient * inv_2pi * kmath::atan2(num, den);
}

}  // namespace ondine
