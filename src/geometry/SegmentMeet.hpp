#pragma once
// Whether two plane segments meet (cross, touch or overlap), to the round-off of coordinates
// of size `extent`: the test behind "a simple curve" for 2D walls and prism bases.
#include <algorithm>
#include <array>
#include <cmath>

namespace ondine::geometry {

using P2 = std::array<double, 2>;

inline double cross2(const P2& o, const P2& a, const P2& b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); }

// q on segment [a, b] (within round-off)
inline bool on_segment(const P2& a, const P2& b, const P2& q, double extent) {
  const double eps = 1e-12 * extent * extent, tol = 1e-12 * extent;
  return std::abs(cross2(a, b, q)) <= eps && std::min(a[0], b[0]) - tol <= q[0] && q[0] <= std::max(a[0], b[0]) + tol &&
         std::min(a[1], b[1]) - tol <= q[1] && q[1] <= std::max(a[1], b[1]) + tol;
}

inline bool segments_meet(const P2& a, const P2& b, const P2& c, const P2& d, double extent) {
  const double eps = 1e-12 * extent * extent;  // an area: the orientation test's round-off
  const double d1 = cross2(c, d, a), d2 = cross2(c, d, b), d3 = cross2(a, b, c), d4 = cross2(a, b, d);
  if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps))) return true;
  return on_segment(c, d, a, extent) || on_segment(c, d, b, extent) || on_segment(a, b, c, extent) || on_segment(a, b, d, extent);
}

}  // namespace ondine::geometry
