#pragma once
// Whether a wall's triangle mesh meets itself: two triangles that share no vertex and
// cross (an edge of one passes through the other), found over a grid of the triangles'
// bounding boxes. Coplanar overlaps and triangles touching without crossing are not
// reported (docs/case-file.md, 3D walls).
#include <utility>

#include "geometry/TriangleMesh.hpp"

namespace ondine::geometry {

// the crossing pair (t, u), t < u, with the smallest t and then u; (-1, -1) when none
std::pair<int, int> first_crossing(const TriangleMesh& m);

}  // namespace ondine::geometry
