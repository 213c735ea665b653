#include "geometry/TriangleQuadrature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ondine {

namespace {

using V2 = std::array<double, 2>;
using V3 = std::array<double, 3>;

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double cross2(const V2& a, const V2& b) { return a[0] * b[1] - a[1] * b[0]; }

// Up to 4 + 3 vertices in exact arithmetic; each Sutherland-Hodgman pass at most doubles the
// count whatever the rounding, so 4 -> 8 -> 16 -> 32 bounds it.
constexpr int kMaxVertices = 32;
using Poly = std::array<V2, kMaxVertices>;

// One Sutherland-Hodgman pass (§4.4 step 2): the part of the convex polygon in[0, n) where
// f(u) = (d x (u - q)) >= 0, i.e. left of the edge through q along d.
int clip_half_plane(const Poly& in, int n, Poly& out, const V2& q, const V2& d) {
  int m = 0;
  if (n == 0) return 0;
  auto f = [&](const V2& u) { return cross2(d, V2{u[0] - q[0], u[1] - q[1]}); };
  V2 a = in[n - 1];
  double fa = f(a);
  for (int k = 0; k < n; ++k) {
    const V2& b = in[k];
    const double fb = f(b);
    if ((fa >= 0) != (fb >= 0)) {  // the edge a -> b crosses the line: 0 <= t <= 1
      const double t = fa / (fa - fb);
      out[m++] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    }
    if (fb >= 0) out[m++] = b;
    a = b;
    fa = fb;
  }
  return m;
}

// One piece: its cell (i, j), area and first moment about the cell's corner (i h, j h).
struct Piece {
  long long i, j;
  double area, mx, my;
};

}  // namespace

std::vector<WallQuadraturePoint> clip_quadrature(const V3& v0, const V3& v1, const V3& v2, double h) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("clip_quadrature: spacing h must be > 0 and finite");
  for (const V3* v : {&v0, &v1, &v2})
    for (double c : *v)
      if (!std::isfinite(c)) throw std::invalid_argument("clip_quadrature: triangle vertex not finite");
  const V3 d1 = sub(v1, v0), d2 = sub(v2, v0), d12 = sub(v2, v1);
  const V3 c = cross(d1, d2);
  const double twice_area = std::sqrt(dot(c, c));
  const double lmax2 = std::max({dot(d1, d1), dot(d2, d2), dot(d12, d12)});
  if (!(twice_area > 64 * std::numeric_limits<double>::epsilon() * lmax2))
    throw std::invalid_argument("clip_quadrature: degenerate triangle (zero area or collinear vertices)");

  // In-plane frame anchored to the triangle: origin v0, e1 along v0 -> v1, e2 = n x e1. The
  // triangle is counter-clockwise in it, with P0 = (0, 0), P1 = (L, 0) and P2 above the axis.
  const double L = std::sqrt(dot(d1, d1));
  const V3 e1{d1[0] / L, d1[1] / L, d1[2] / L};
  const V3 n{c[0] / twice_area, c[1] / twice_area, c[2] / twice_area};
  const V3 e2 = cross(n, e1);
  const std::array<V2, 3> P{V2{0.0, 0.0}, V2{L, 0.0}, V2{dot(d2, e1), dot(d2, e2)}};
  const std::array<V2, 3> D{V2{P[1][0] - P[0][0], P[1][1] - P[0][1]}, V2{P[2][0] - P[1][0], P[2][1] - P[1][1]},
                            V2{P[0][0] - P[2][0], P[0][1] - P[2][1]}};  // edge k: P[k] -> P[k+1]
  const double area_T = 0.5 * twice_area;

  const double perimeter = std::sqrt(dot(d1, d1)) + std::sqrt(dot(d2, d2)) + std::sqrt(dot(d12, d12));
  const double estimate = area_T / (h * h) + 4 * perimeter / h + 16;
  if (estimate > 1e8)
    throw std::invalid_argument("clip_quadrature: spacing h too small for the triangle (about " +
                                std::to_string(static_cast<long long>(estimate)) + " squares)");

  // Rows of squares [i h, (i+1) h] x [j h, (j+1) h]; the triangle spans y in [0, P2.y].
  const long long jn = std::max(1LL, static_cast<long long>(std::ceil(P[2][1] / h)));
  std::vector<Piece> kept, slivers;
  std::vector<std::size_t> row_begin(static_cast<std::size_t>(jn) + 1, 0);
  const double sliver = 1e-14 * area_T;
  for (long long j = 0; j < jn; ++j) {
    row_begin[static_cast<std::size_t>(j)] = kept.size();
    const double y0 = static_cast<double>(j) * h, y1 = static_cast<double>(j + 1) * h;
    // x range of the triangle in the strip y0 <= y <= y1: the ends of its edges clipped to it
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    for (int k = 0; k < 3; ++k) {
      const V2 &a = P[k], &b = P[(k + 1) % 3];
      if (std::max(a[1], b[1]) < y0 || std::min(a[1], b[1]) > y1) continue;
      double t0 = 0, t1 = 1;
      if (a[1] != b[1]) {
        t0 = std::clamp((y0 - a[1]) / (b[1] - a[1]), 0.0, 1.0);
        t1 = std::clamp((y1 - a[1]) / (b[1] - a[1]), 0.0, 1.0);
      }
      for (double t : {t0, t1}) {
        const double x = a[0] + t * (b[0] - a[0]);
        xmin = std::min(xmin, x);
        xmax = std::max(xmax, x);
      }
    }
    if (!(xmin <= xmax)) continue;
    // one square of margin either side: the tests below reject what lies outside
    const long long i0 = static_cast<long long>(std::floor(xmin / h)) - 1;
    const long long i1 = static_cast<long long>(std::floor(xmax / h)) + 1;
    for (long long i = i0; i <= i1; ++i) {
      // The triangle seen from the square's corner O = (i h, j h): clipping in these local
      // coordinates keeps the shoelace sums well conditioned far from v0.
      const V2 O{static_cast<double>(i) * h, y0};
      const std::array<V2, 3> q{V2{P[0][0] - O[0], P[0][1] - O[1]}, V2{P[1][0] - O[0], P[1][1] - O[1]},
                                V2{P[2][0] - O[0], P[2][1] - O[1]}};
      Poly poly{V2{0.0, 0.0}, V2{h, 0.0}, V2{h, h}, V2{0.0, h}};
      // §4.4 step 1, exactly: a square is inside the triangle if its 4 corners are inside
      // the 3 half-planes, and misses it if its 4 corners are outside one of them.
      bool inside = true, outside = false;
      for (int k = 0; k < 3 && !outside; ++k) {
        int in_count = 0, out_count = 0;
        for (int v = 0; v < 4; ++v) {
          const double f = cross2(D[k], V2{poly[v][0] - q[k][0], poly[v][1] - q[k][1]});
          in_count += f >= 0;
          out_count += f <= 0;
        }
        inside = inside && in_count == 4;
        outside = out_count == 4;
      }
      if (outside) continue;
      if (inside) {
        kept.push_back({i, j, h * h, 0.5 * h * h * h, 0.5 * h * h * h});
        continue;
      }
      Poly tmp;
      int m = 4;
      m = clip_half_plane(poly, m, tmp, q[0], D[0]);
      m = clip_half_plane(tmp, m, poly, q[1], D[1]);
      m = clip_half_plane(poly, m, tmp, q[2], D[2]);
      if (m < 3) continue;
      // §4.4 step 3: area and first moment of the (counter-clockwise) piece by the shoelace
      // sums (not Heron's formula (4.90)).
      double a2 = 0, mx6 = 0, my6 = 0;
      for (int k = 0; k < m; ++k) {
        const V2 &a = tmp[k], &b = tmp[(k + 1) % m];
        const double cr = cross2(a, b);
        a2 += cr;
        mx6 += (a[0] + b[0]) * cr;
        my6 += (a[1] + b[1]) * cr;
      }
      const Piece piece{i, j, 0.5 * a2, mx6 / 6, my6 / 6};
      (piece.area < sliver ? slivers : kept).push_back(piece);
    }
  }
  row_begin[static_cast<std::size_t>(jn)] = kept.size();

  if (kept.empty()) {  // cannot happen for a valid triangle and h; kept for safety
    const double k3 = 1.0 / 3.0;
    return {WallQuadraturePoint{{v0[0] + k3 * (d1[0] + d2[0]), v0[1] + k3 * (d1[1] + d2[1]),
                                 v0[2] + k3 * (d1[2] + d2[2])},
                                area_T}};
  }

  // Centroids in the triangle's frame. The area centroid (not the thesis's barycentre of
  // the piece's vertices) makes each piece's midpoint term, hence the rule, exact for
  // linear integrands.
  std::vector<V2> centroid(kept.size());
  std::vector<double> weight(kept.size());
  for (std::size_t p = 0; p < kept.size(); ++p) {
    const Piece& k = kept[p];
    centroid[p] = {static_cast<double>(k.i) * h + k.mx / k.area, static_cast<double>(k.j) * h + k.my / k.area};
    weight[p] = k.area;
  }
  // Each sliver goes to the nearest kept piece among its 8 neighbouring squares (any kept
  // piece failing that): area and first moment added, so the totals stay exact.
  for (const Piece& s : slivers) {
    std::size_t best = kept.size();
    long long best_d2 = std::numeric_limits<long long>::max();
    for (long long j = std::max(0LL, s.j - 1); j <= std::min(jn - 1, s.j + 1); ++j) {
      const auto first = kept.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(j)]);
      const auto last = kept.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(j) + 1]);
      auto it = std::lower_bound(first, last, s.i - 1, [](const Piece& k, long long i) { return k.i < i; });
      for (; it != last && it->i <= s.i + 1; ++it) {
        const long long di = it->i - s.i, dj = j - s.j, dd = di * di + dj * dj;
        if (dd < best_d2) {
          best_d2 = dd;
          best = static_cast<std::size_t>(it - kept.begin());
        }
      }
    }
    const V2 O{static_cast<double>(s.i) * h, static_cast<double>(s.j) * h};
    if (best == kept.size()) {
      double best_dist = std::numeric_limits<double>::infinity();
      const V2 mid{O[0] + 0.5 * h, O[1] + 0.5 * h};
      for (std::size_t p = 0; p < kept.size(); ++p) {
        const double dx = centroid[p][0] - mid[0], dy = centroid[p][1] - mid[1], dist = dx * dx + dy * dy;
        if (dist < best_dist) {
          best_dist = dist;
          best = p;
        }
      }
    }
    // c' = (A c + M_s) / (A + a_s), with M_s = m_s + a_s O the sliver's moment about the origin
    V2& cb = centroid[best];
    const double A = weight[best] + s.area;
    cb = {cb[0] + (s.mx + s.area * (O[0] - cb[0])) / A, cb[1] + (s.my + s.area * (O[1] - cb[1])) / A};
    weight[best] = A;
  }

  std::vector<WallQuadraturePoint> points(kept.size());
  for (std::size_t p = 0; p < kept.size(); ++p) {
    const double s = centroid[p][0], t = centroid[p][1];
    points[p] = {{v0[0] + s * e1[0] + t * e2[0], v0[1] + s * e1[1] + t * e2[1], v0[2] + s * e1[2] + t * e2[2]},
                 weight[p]};
  }
  return points;
}

}  // namespace ondine
