#include "geometry/MeshChecks.hpp"

#include "geometry/MeshIntersection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <tuple>

namespace ondine::geometry {

namespace {

// one triangle's use of an edge: the edge's vertices (lo < hi), the triangle, and
// whether the triangle goes from lo to hi
struct HalfEdge {
  int lo, hi, triangle;
  bool forward;
};

// half-edges sorted by edge, then by triangle: the uses of one edge are consecutive
std::vector<HalfEdge> sorted_half_edges(const TriangleMesh& m) {
  std::vector<HalfEdge> h;
  h.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      h.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t), a < b});
    }
  std::sort(h.begin(), h.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  return h;
}

// calls f(first, count) for each edge's run of half-edges
template <class F>
void for_each_edge(const std::vector<HalfEdge>& h, F f) {
  for (std::size_t i = 0; i < h.size();) {
    std::size_t j = i + 1;
    while (j < h.size() && h[j].lo == h[i].lo && h[j].hi == h[i].hi) ++j;
    f(i, j - i);
    i = j;
  }
}

// vertices are named by their coordinates: their numbers are those of the merged vertices,
// which the user's file does not show
std::string edge(const TriangleMesh& m, const HalfEdge& e) {
  return "the edge from " + format_point(m.vertices[e.lo]) + " to " + format_point(m.vertices[e.hi]);
}

}  // namespace

std::string crossing_problem(const TriangleMesh& m) {
  std::ostringstream o;
  const auto [t, u] = first_crossing(m);
  if (t >= 0) {
    auto corners = [&](int k) {
      return format_point(m.vertices[m.triangles[k][0]]) + ", " + format_point(m.vertices[m.triangles[k][1]]) + ", " +
             format_point(m.vertices[m.triangles[k][2]]);
    };
    o << "triangles " << t << " (" << corners(t) << ") and " << u << " (" << corners(u)
      << ") (0-based) cross each other; expected a surface that does not meet itself";
  }
  return o.str();
}

std::size_t count_open_edges(const TriangleMesh& m) {
  std::size_t open = 0;
  for_each_edge(sorted_half_edges(m), [&](std::size_t, std::size_t n) { open += n == 1; });
  return open;
}

std::string mesh_problem(const TriangleMesh& m, bool need_closed, const std::string& closed_because) {
  std::ostringstream o;
  if (m.triangles.empty()) return "the mesh has no triangles";
  const int nv = static_cast<int>(m.vertices.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (m.triangles[t][k] < 0 || m.triangles[t][k] >= nv)
        return "triangle " + std::to_string(t) + " (0-based) refers to a vertex that does not exist";
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Point& p = m.vertices[m.triangles[t][k]];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        o << "triangle " << t << " (0-based) has a non-finite coordinate at its corner " << k << " " << format_point(p)
          << "; expected finite numbers";
        return o.str();
      }
    }

  const double d = bounding_box_diagonal(m);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (!(triangle_area(m, static_cast<int>(t)) >= 1e-12 * d * d)) {
      const Triangle& tri = m.triangles[t];
      o << "triangle " << t << " (0-based) has zero area (its corners coincide or are in line): "
        << format_point(m.vertices[tri[0]]) << ", " << format_point(m.vertices[tri[1]]) << ", "
        << format_point(m.vertices[tri[2]]) << "; expected three corners spanning an area";
      return o.str();
    }

  {  // the same three vertices, in any order: sorted triples, sorted
    std::vector<std::pair<Triangle, int>> key(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      Triangle s = m.triangles[t];
      std::sort(s.begin(), s.end());
      key[t] = {s, static_cast<int>(t)};
    }
    std::sort(key.begin(), key.end());
    int first = -1, second = -1;  // the repeat that comes first: the smallest second index
    for (std::size_t i = 0; i < key.size();) {
      std::size_t j = i + 1;
      while (j < key.size() && key[j].first == key[i].first) ++j;
      if (j - i > 1 && (second < 0 || key[i + 1].second < second)) {
        first = key[i].second;
        second = key[i + 1].second;
      }
      i = j;
    }
    if (first >= 0) {
      o << "triangles " << first << " and " << second << " (0-based) are the same triangle (the same three vertices "
        << format_point(m.vertices[m.triangles[first][0]]) << ", " << format_point(m.vertices[m.triangles[first][1]])
        << ", " << format_point(m.vertices[m.triangles[first][2]]) << "); expected each triangle once";
      return o.str();
    }
  }

  const std::vector<HalfEdge> h = sorted_half_edges(m);
  // the problem edge whose first triangle comes first
  auto first_edge = [&](auto bad) {
    std::size_t at = h.size(), count = 0;
    for_each_edge(h, [&](std::size_t i, std::size_t n) {
      if (bad(i, n) && (at == h.size() || h[i].triangle < h[at].triangle)) {
        at = i;
        count = n;
      }
    });
    return std::make_pair(at, count);
  };

  const auto [nm, nm_count] = first_edge([](std::size_t, std::size_t n) { return n > 2; });
  if (nm < h.size()) {
    o << edge(m, h[nm]) << " is shared by " << nm_count << " triangles (";
    for (std::size_t k = 0; k < nm_count; ++k) o << (k ? ", " : "") << h[nm + k].triangle;
    o << ", 0-based); expected at most 2 (a manifold surface)";
    return o.str();
  }

  const auto [same, same_count] = first_edge([&](std::size_t i, std::size_t n) { return n == 2 && h[i].forward == h[i + 1].forward; });
  (void)same_count;
  if (same < h.size()) {
    o << "triangles " << h[same].triangle << " and " << h[same + 1].triangle
      << " (0-based) are ordered inconsistently: both go the same way along their shared " << edge(m, h[same]).substr(4)
      << ", so one of them is turned inside out; expected neighbouring triangles that traverse a shared edge in opposite directions";
    return o.str();
  }

  if (need_closed) {
    const auto [open, open_count] = first_edge([](std::size_t, std::size_t n) { return n == 1; });
    (void)open_count;
    if (open < h.size()) {
      std::size_t n_open = 0;
      for_each_edge(h, [&](std::size_t, std::size_t n) { n_open += n == 1; });
      o << "the surface is not closed: " << n_open << (n_open == 1 ? " edge belongs" : " edges belong")
        << " to one triangle only, the first " << edge(m, h[open]).substr(4) << " of triangle " << h[open].triangle
        << " (0-based); expected a closed surface (every edge shared by two triangles)" << closed_because;
      return o.str();
    }
    const double v = signed_volume(m);
    if (!(std::fabs(v) >= 1e-10 * d * d * d)) {
      o << "the closed surface encloses no volume (" << v << " by the divergence theorem); expected a surface around a solid or a fluid region";
      return o.str();
    }
  }
  return "";
}

}  // namespace ondine::geometry
