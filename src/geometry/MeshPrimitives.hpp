#pragma once
// Triangle meshes of simple shapes (3D walls, docs/case-file.md `walls`). Closed shapes,
// and the open-top box and the open tube, come with their normals pointing out of the
// shape; the rectangle with its normal along u x v. Invalid input throws GeometryError.
#include <vector>

#include "geometry/TriangleMesh.hpp"

namespace ondine::geometry {

// an axis-aligned box (min < max in every axis): 8 vertices, 12 triangles, or 10 with
// the face at max z left out (open_top)
TriangleMesh box_mesh(const Point& min, const Point& max, bool open_top);

// the parallelogram origin + a u + b v, a, b in [0, 1]: 2 triangles, normal along u x v
TriangleMesh rectangle_mesh(const Point& origin, const Point& u, const Point& v);

// the polygon `base` of the xy plane (either orientation, at least 3 points, no
// zero-length edge) extruded from z0 to z1 > z0; its caps are triangulated by ear
// clipping, so the polygon may be concave (not self-intersecting)
TriangleMesh prism_mesh(const std::vector<std::array<double, 2>>& base, double z0, double z1);

// a regular polygon of `segments` sides inscribed in the circle of `radius` about
// `centre`, in the plane normal to `axis`, extruded by `length` along the axis; with
// caps, each closed by a fan about its centre, else an open tube
TriangleMesh cylinder_mesh(const Point& centre, const Point& axis, double radius, double length, int segments, bool caps);

// Ear clipping of a simple polygon: triangles of indices into `polygon`, each ordered
// counter-clockwise. A vertex in line with its neighbours stays a vertex of the
// triangles (no T-junction with the side walls). Throws GeometryError when no ear is
// found (a self-intersecting polygon).
std::vector<Triangle> triangulate_polygon(const std::vector<std::array<double, 2>>& polygon);

// twice the signed area of a polygon of the xy plane (> 0: counter-clockwise)
double polygon_twice_area(const std::vector<std::array<double, 2>>& polygon);

}  // namespace ondine::geometry
