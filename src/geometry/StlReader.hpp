#pragma once
// Reads a binary or ASCII STL file (assimp) into a triangle mesh in the file's units:
// the triangles in the file's order, each with its vertex order as written, and equal
// corners (within 1e-9 of the bounding-box diagonal) merged into shared vertices, so
// that the mesh checks (MeshChecks.hpp) see the surface's edges. Several solids in one
// ASCII file are read one after the other. Throws GeometryError naming the file, with
// assimp's reason, for a file that cannot be read as STL.
#include <string>

#include "geometry/TriangleMesh.hpp"

namespace ondine::geometry {

TriangleMesh read_stl(const std::string& file);

}  // namespace ondine::geometry
