#pragma once
// Checks of a wall's triangle mesh before the first step (case-file walls[i], 3D): each
// returns the first problem in words (triangles named by their 0-based index, vertices
// by their coordinates), or an empty string.
#include <string>

#include "geometry/TriangleMesh.hpp"

namespace ondine::geometry {

// In this order: a non-finite coordinate; a triangle of zero area (< 1e-12 d², d the
// bounding-box diagonal); two triangles on the same three vertices; an edge shared by
// three or more triangles; two triangles that traverse their shared edge in the same
// direction (their orders disagree); and, when `need_closed`, an edge of one triangle
// only (a hole) and a surface that encloses no volume (|V| < 1e-10 d³).
// `closed_because` ends the message of a hole (why a closed surface is needed).
std::string mesh_problem(const TriangleMesh& m, bool need_closed, const std::string& closed_because = "");

// Two triangles that share no vertex and cross (geometry/MeshIntersection.hpp), with their
// corners, or an empty string. Run on STL files (the primitives are built simple): its grid
// has cells of the largest triangle's size, so a fan of thin triangles costs its square.
std::string crossing_problem(const TriangleMesh& m);

// edges used by one triangle only (0: a closed surface)
std::size_t count_open_edges(const TriangleMesh& m);

}  // namespace ondine::geometry
