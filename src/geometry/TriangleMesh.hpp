#pragma once
// A host-side triangle mesh (3D walls, src/scene/CaseWalls3d.cpp): shared vertices and
// triangles of three vertex indices. The orientation of a triangle is its vertex order:
// (v1 - v0) x (v2 - v0) is its normal.
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace ondine::geometry {

using Point = std::array<double, 3>;
using Triangle = std::array<int, 3>;

struct TriangleMesh {
  std::vector<Point> vertices;
  std::vector<Triangle> triangles;
};

// A geometry that cannot be built or read; what() says what is wrong and what was expected.
class GeometryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline Point operator-(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Point operator+(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Point operator*(double s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Point& a) { return std::sqrt(dot(a, a)); }

// (v1 - v0) x (v2 - v0): twice the area times the unit normal
Point area_normal(const TriangleMesh& m, int t);
double triangle_area(const TriangleMesh& m, int t);
double total_area(const TriangleMesh& m);
// the diagonal of the axis-aligned bounding box (0 for an empty mesh)
double bounding_box_diagonal(const TriangleMesh& m);
// Σ (v0 · (v1 x v2)) / 6 about the bounding-box centre (divergence theorem): the enclosed
// volume of a closed, consistently ordered surface, positive when the normals point out
double signed_volume(const TriangleMesh& m);
// reverses the vertex order (and so the normal) of every triangle
void flip(TriangleMesh& m);
// appends b's vertices and triangles to a
void append(TriangleMesh& a, const TriangleMesh& b);
// Shared vertices from triangle soup: corners[3 t + k] is corner k of triangle t; corners
// closer than `tolerance` are merged into one vertex (the first one met); triangle order
// and vertex order within each triangle are kept.
TriangleMesh weld(const std::vector<Point>& corners, double tolerance);
// "(x, y, z)" with 10 significant digits, for messages
std::string format_point(const Point& p);

}  // namespace ondine::geometry
