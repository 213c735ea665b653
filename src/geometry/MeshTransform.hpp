#pragma once
// The placement of a 3D wall's mesh (case-file keys walls[i].scale, rotate, translate):
// x -> Rz Ry Rx (S x) + t, about the origin.
#include "geometry/TriangleMesh.hpp"

namespace ondine::geometry {

struct MeshTransform {
  Point scale{1, 1, 1};         // per axis, > 0 (a mirror would turn the triangles inside out)
  Point rotate_degrees{0, 0, 0};  // about x, then y, then z
  Point translate{0, 0, 0};     // m
};

Point place(const MeshTransform& t, const Point& p);
void place(const MeshTransform& t, TriangleMesh& m);

}  // namespace ondine::geometry
