#include "geometry/MeshPrimitives.hpp"

#include "geometry/SegmentMeet.hpp"

#include <algorithm>
#include <cmath>

namespace ondine::geometry {

namespace {


double orient(const P2& a, const P2& b, const P2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// the quad a b c d (in cyclic order) as two triangles with their normal along `out`
void add_quad(TriangleMesh& m, int a, int b, int c, int d, const Point& out) {
  const Point n = cross(m.vertices[b] - m.vertices[a], m.vertices[c] - m.vertices[a]);
  if (dot(n, out) >= 0) {
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
  } else {
    m.triangles.push_back({a, c, b});
    m.triangles.push_back({a, d, c});
  }
}

}  // namespace

TriangleMesh box_mesh(const Point& min, const Point& max, bool open_top) {
  for (int k = 0; k < 3; ++k)
    if (!(max[k] > min[k])) throw GeometryError("expected max > min in every axis");
  TriangleMesh m;
  for (int v = 0; v < 8; ++v)  // vertex v = i + 2 j + 4 k: x of max if i, y if j, z if k
    m.vertices.push_back({v & 1 ? max[0] : min[0], v & 2 ? max[1] : min[1], v & 4 ? max[2] : min[2]});
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      if (open_top && axis == 2 && side == 1) continue;
      const int b = (axis + 1) % 3, c = (axis + 2) % 3;
      const int fixed = side << axis;
      const int q[4] = {fixed, fixed | 1 << b, fixed | 1 << b | 1 << c, fixed | 1 << c};
      Point out{0, 0, 0};
      out[axis] = side ? 1 : -1;
      add_quad(m, q[0], q[1], q[2], q[3], out);
    }
  return m;
}

TriangleMesh rectangle_mesh(const Point& origin, const Point& u, const Point& v) {
  const double scale = norm(u) + norm(v);
  if (!(norm(cross(u, v)) > 1e-12 * scale * scale))
    throw GeometryError("u and v are zero or parallel: the rectangle has no area; expected two independent edge vectors");
  TriangleMesh m;
  m.vertices = {origin, origin + u, origin + u + v, origin + v};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

double polygon_twice_area(const std::vector<P2>& polygon) {
  double a = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const P2& p = polygon[i];
    const P2& q = polygon[(i + 1) % n];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a;
}

std::vector<Triangle> triangulate_polygon(const std::vector<P2>& polygon) {
  const int n = static_cast<int>(polygon.size());
  std::vector<int> ring(n);
  for (int i = 0; i < n; ++i) ring[i] = i;
  if (polygon_twice_area(polygon) < 0) std::reverse(ring.begin(), ring.end());
  P2 lo = polygon.empty() ? P2{0, 0} : polygon[0], hi = lo;
  for (const P2& p : polygon)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  const double diag2 = (hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]);
  const double eps = 1e-12 * diag2;
  std::vector<Triangle> out;
  while (ring.size() > 3) {
    const int m = static_cast<int>(ring.size());
    bool clipped = false;
    for (int i = 0; i < m && !clipped; ++i) {
      const int a = ring[(i + m - 1) % m], b = ring[i], c = ring[(i + 1) % m];
      const P2 &pa = polygon[a], &pb = polygon[b], &pc = polygon[c];
      // an ear: strictly convex (a vertex in line with its neighbours is kept, so that it
      // stays a vertex of the cap) with no other vertex inside or on it
      if (!(orient(pa, pb, pc) > eps)) continue;
      bool empty = true;
      for (int j = 0; j < m && empty; ++j) {
        const int q = ring[j];
        if (q == a || q == b || q == c) continue;
        const P2& pq = polygon[q];
        if (pq == pa || pq == pb || pq == pc) continue;
        empty = !(orient(pa, pb, pq) >= -eps && orient(pb, pc, pq) >= -eps && orient(pc, pa, pq) >= -eps);
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      ring.erase(ring.begin() + i);
      clipped = true;
    }
    if (!clipped)
      throw GeometryError("the polygon cannot be cut into triangles (it intersects itself, or " +
                          std::to_string(ring.size()) + " of its points are left in line); expected a simple polygon");
  }
  if (!(orient(polygon[ring[0]], polygon[ring[1]], polygon[ring[2]]) > eps))
    throw GeometryError("the polygon cannot be cut into triangles (its last three points are in line); expected a simple polygon");
  out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

TriangleMesh prism_mesh(const std::vector<P2>& base, double z0, double z1) {
  const int n = static_cast<int>(base.size());
  if (n < 3) throw GeometryError("expected at least 3 points in the base polygon, got " + std::to_string(n));
  if (!(z1 > z0)) throw GeometryError("expected z1 > z0 (the base at z0, the top at z1)");
  P2 lo = base[0], hi = lo;
  for (const P2& p : base)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  const double diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  for (int i = 0; i < n; ++i) {
    const P2 &a = base[i], &b = base[(i + 1) % n];
    if (std::hypot(b[0] - a[0], b[1] - a[1]) <= 1e-9 * diag)
      throw GeometryError("the edge from point " + std::to_string(i) + " to point " + std::to_string((i + 1) % n) +
                          " (0-based) has zero length (a repeated point; do not repeat the first point at the end)");
  }
  // a simple polygon: edges that are not neighbours do not meet (a bowtie's cross)
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the first point
      if (segments_meet(base[i], base[(i + 1) % n], base[j], base[(j + 1) % n], diag))
        throw GeometryError("the edges from point " + std::to_string(i) + " to point " + std::to_string(i + 1) + " and from point " +
                            std::to_string(j) + " to point " + std::to_string((j + 1) % n) +
                            " (0-based) meet; expected a simple polygon (no edge crossing or touching another)");
    }
  if (!(std::fabs(polygon_twice_area(base)) > 1e-12 * diag * diag))
    throw GeometryError("the base polygon has no area (its points are in line)");
  // counter-clockwise in xy, so that the side walls' normals point out
  std::vector<P2> ccw = base;
  if (polygon_twice_area(ccw) < 0) std::reverse(ccw.begin(), ccw.end());
  TriangleMesh m;
  for (const P2& p : ccw) m.vertices.push_back({p[0], p[1], z0});
  for (const P2& p : ccw) m.vertices.push_back({p[0], p[1], z1});
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  for (const Triangle& t : triangulate_polygon(ccw)) {
    m.triangles.push_back({n + t[0], n + t[1], n + t[2]});  // top: +z
    m.triangles.push_back({t[0], t[2], t[1]});              // bottom: -z
  }
  return m;
}

TriangleMesh cylinder_mesh(const Point& centre, const Point& axis, double radius, double length, int segments, bool caps) {
  if (!(norm(axis) > 0)) throw GeometryError("expected a non-zero axis direction");
  if (!(radius > 0) || !(length > 0)) throw GeometryError("expected a positive radius and length");
  if (segments < 3) throw GeometryError("expected at least 3 segments");
  const Point a = (1.0 / norm(axis)) * axis;
  // (e1, e2, a) right-handed, e1 normal to a from the coordinate axis least along it
  int least = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(a[k]) < std::fabs(a[least])) least = k;
  Point w{0, 0, 0};
  w[least] = 1;
  Point e1 = cross(a, w);
  e1 = (1.0 / norm(e1)) * e1;
  const Point e2 = cross(a, e1);
  const int n = segments;
  TriangleMesh m;
  const double pi = std::acos(-1.0);
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < n; ++k) {
      const double th = 2 * pi * k / n;
      m.vertices.push_back(centre + (ring * length) * a + (radius * std::cos(th)) * e1 + (radius * std::sin(th)) * e2);
    }
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    m.triangles.push_back({k, j, n + j});
    m.triangles.push_back({k, n + j, n + k});
  }
  if (caps) {
    m.vertices.push_back(centre);
    m.vertices.push_back(centre + length * a);
    const int bottom = 2 * n, top = 2 * n + 1;
    for (int k = 0; k < n; ++k) {
      const int j = (k + 1) % n;
      m.triangles.push_back({top, n + k, n + j});
      m.triangles.push_back({bottom, j, k});
    }
  }
  return m;
}

}  // namespace ondine::geometry
