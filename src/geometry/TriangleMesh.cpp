#include "geometry/TriangleMesh.hpp"

#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <unordered_map>

namespace ondine::geometry {

Point area_normal(const TriangleMesh& m, int t) {
  const Triangle& tri = m.triangles[t];
  const Point& a = m.vertices[tri[0]];
  return cross(m.vertices[tri[1]] - a, m.vertices[tri[2]] - a);
}

double triangle_area(const TriangleMesh& m, int t) { return 0.5 * norm(area_normal(m, t)); }

double total_area(const TriangleMesh& m) {
  double a = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) a += triangle_area(m, static_cast<int>(t));
  return a;
}

namespace {

void bounds(const TriangleMesh& m, Point& lo, Point& hi) {
  lo = hi = m.vertices.empty() ? Point{0, 0, 0} : m.vertices[0];
  for (const Point& p : m.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
}

}  // namespace

double bounding_box_diagonal(const TriangleMesh& m) {
  Point lo, hi;
  bounds(m, lo, hi);
  return norm(hi - lo);
}

double signed_volume(const TriangleMesh& m) {
  // about the box centre rather than the origin: no cancellation for a mesh far from it
  Point lo, hi;
  bounds(m, lo, hi);
  const Point c = 0.5 * (lo + hi);
  double v = 0;
  for (const Triangle& t : m.triangles)
    v += dot(m.vertices[t[0]] - c, cross(m.vertices[t[1]] - c, m.vertices[t[2]] - c));
  return v / 6;
}

void flip(TriangleMesh& m) {
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
}

void append(TriangleMesh& a, const TriangleMesh& b) {
  const int base = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

TriangleMesh weld(const std::vector<Point>& corners, double tolerance_asked) {
  const double tolerance = std::isfinite(tolerance_asked) && tolerance_asked > 0 ? tolerance_asked : 0;
  TriangleMesh m;
  Point lo{0, 0, 0}, hi{0, 0, 0};
  bool first = true;
  for (const Point& p : corners)
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = first ? p[k] : std::min(lo[k], p[k]);
        hi[k] = first ? p[k] : std::max(hi[k], p[k]);
      }
      first = false;
    }
  // a grid of cells at least `tolerance` wide: a vertex within the tolerance lies in one
  // of the 27 cells around; with no tolerance, equal coordinates only (in one cell). No
  // more than 10^12 cells along an axis, so that the cell numbers fit in 64 bits.
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double cell = std::max(tolerance > 0 ? tolerance : 1.0, 1e-12 * extent);
  struct Key {
    std::int64_t i, j, k;
    bool operator==(const Key& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct Hash {
    std::size_t operator()(const Key& c) const {
      return std::hash<std::int64_t>()(c.i * 73856093LL ^ c.j * 19349663LL ^ c.k * 83492791LL);
    }
  };
  std::unordered_map<Key, std::vector<int>, Hash> grid;
  const int nt = static_cast<int>(corners.size() / 3);
  m.triangles.resize(nt);
  for (int c = 0; c < 3 * nt; ++c) {
    const Point& p = corners[c];
    int found = -1;
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) {
      const Key key{static_cast<std::int64_t>(std::floor((p[0] - lo[0]) / cell)),
                    static_cast<std::int64_t>(std::floor((p[1] - lo[1]) / cell)),
                    static_cast<std::int64_t>(std::floor((p[2] - lo[2]) / cell))};
      const int reach = tolerance > 0 ? 1 : 0;
      for (int di = -reach; di <= reach && found < 0; ++di)
        for (int dj = -reach; dj <= reach && found < 0; ++dj)
          for (int dk = -reach; dk <= reach && found < 0; ++dk) {
            const auto it = grid.find({key.i + di, key.j + dj, key.k + dk});
            if (it == grid.end()) continue;
            for (int v : it->second) {
              const Point d = m.vertices[v] - p;
              if (tolerance > 0 ? norm(d) <= tolerance : (d[0] == 0 && d[1] == 0 && d[2] == 0)) {
                found = v;
                break;
              }
            }
          }
      if (found < 0) {
        found = static_cast<int>(m.vertices.size());
        m.vertices.push_back(p);
        grid[key].push_back(found);
      }
    } else {
      found = static_cast<int>(m.vertices.size());  // left alone: the checks name it
      m.vertices.push_back(p);
    }
    m.triangles[c / 3][c % 3] = found;
  }
  return m;
}

std::string format_point(const Point& p) {
  std::ostringstream o;
  o << std::setprecision(10) << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return o.str();
}

}  // namespace ondine::geometry
