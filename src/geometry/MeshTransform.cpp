#include "geometry/MeshTransform.hpp"

#include <cmath>

namespace ondine::geometry {

namespace {

// cos and sin of an angle in degrees, exact at multiples of 90 (a box turned by 90
// degrees stays axis-aligned to the last bit)
void cos_sin(double degrees, double& c, double& s) {
  const double quarter = degrees / 90;
  if (quarter == std::round(quarter)) {
    const long long q = static_cast<long long>(std::round(quarter));
    const int r = static_cast<int>(((q % 4) + 4) % 4);
    const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
    c = cs[r];
    s = sn[r];
    return;
  }
  const double rad = degrees * std::acos(-1.0) / 180;
  c = std::cos(rad);
  s = std::sin(rad);
}

}  // namespace

Point place(const MeshTransform& t, const Point& p) {
  Point x{p[0] * t.scale[0], p[1] * t.scale[1], p[2] * t.scale[2]};
  double c, s;
  cos_sin(t.rotate_degrees[0], c, s);  // about x
  x = {x[0], c * x[1] - s * x[2], s * x[1] + c * x[2]};
  cos_sin(t.rotate_degrees[1], c, s);  // about y
  x = {c * x[0] + s * x[2], x[1], -s * x[0] + c * x[2]};
  cos_sin(t.rotate_degrees[2], c, s);  // about z
  x = {c * x[0] - s * x[1], s * x[0] + c * x[1], x[2]};
  return x + t.translate;
}

void place(const MeshTransform& t, TriangleMesh& m) {
  for (Point& p : m.vertices) p = place(t, p);
}

}  // namespace ondine::geometry
