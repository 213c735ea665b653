#pragma once
// Quadrature of a wall triangle by clipping (thesis §4.4, method/nfm.md §11), for the 3D NFM
// surface integrals. The secondary mesh is a Cartesian grid of squares of side h in the
// triangle's plane, anchored to the triangle (origin v0, axes e1 = (v1 - v0)/|v1 - v0| and
// e2 = n x e1), not to the particle as in the thesis: the points are built once per mesh and
// move rigidly with the wall. Each square that meets the triangle is clipped against it
// (a square wholly inside is kept whole) and each non-empty piece gives one point: the area
// centroid of the piece, with its area as weight. Plain C++17, host only.
#include <array>
#include <vector>

namespace ondine {

struct WallQuadraturePoint {
  std::array<double, 3> x;  // the area centroid of one piece (in the triangle's plane)
  double area;              // its area: the weight s_j of (4.91)
};

// The points of the triangle (v0, v1, v2) on a grid of squares of side h.
// - The weights sum to the triangle's area to round-off, and the rule is exact for linear
//   integrands (area centroids, not the thesis's vertex barycentres).
// - A piece of area below 1e-14 of the triangle's (a sliver cut off by a grid line that
//   passes through a vertex or along an edge to round-off) is merged into a neighbouring
//   piece: its area and first moment are added to it, so both sums stay exact.
// - Points come row by row (along e2), each row along e1; at most one per square, so a
//   triangle smaller than h gives one point, its centroid, with its area.
// Throws std::invalid_argument for a degenerate triangle (non-finite or collinear vertices),
// for h <= 0 or not finite, and for an h so small that the triangle spans over 1e8 squares.
std::vector<WallQuadraturePoint> clip_quadrature(const std::array<double, 3>& v0, const std::array<double, 3>& v1,
                                                 const std::array<double, 3>& v2, double h);

}  // namespace ondine
