#include "geometry/MeshIntersection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ondine::geometry {

namespace {

// segment [p, q] passes through triangle (a, b, c): its ends strictly on both sides of the
// plane (beyond `eps`, a length) and the crossing point inside the triangle or on its edges
bool segment_crosses(const Point& p, const Point& q, const Point& a, const Point& b, const Point& c, double eps) {
  const Point n = cross(b - a, c - a);
  const double ln = norm(n);
  if (!(ln > 0)) return false;
  const double dp = dot(n, p - a) / ln, dq = dot(n, q - a) / ln;
  if (!((dp > eps && dq < -eps) || (dp < -eps && dq > eps))) return false;
  const Point x = p + (dp / (dp - dq)) * (q - p);
  // its barycentric coordinates (each edge's side, over |n|^2) not below round-off
  const double n2 = ln * ln, tol = -1e-12;
  return dot(cross(b - a, x - a), n) / n2 >= tol && dot(cross(c - b, x - b), n) / n2 >= tol && dot(cross(a - c, x - c), n) / n2 >= tol;
}

bool triangles_cross(const TriangleMesh& m, int t, int u, double eps) {
  const auto& A = m.triangles[t];
  const auto& B = m.triangles[u];
  const Point* pa[3] = {&m.vertices[A[0]], &m.vertices[A[1]], &m.vertices[A[2]]};
  const Point* pb[3] = {&m.vertices[B[0]], &m.vertices[B[1]], &m.vertices[B[2]]};
  for (int k = 0; k < 3; ++k) {
    if (segment_crosses(*pa[k], *pa[(k + 1) % 3], *pb[0], *pb[1], *pb[2], eps)) return true;
    if (segment_crosses(*pb[k], *pb[(k + 1) % 3], *pa[0], *pa[1], *pa[2], eps)) return true;
  }
  return false;
}

}  // namespace

std::pair<int, int> first_crossing(const TriangleMesh& m) {
  const int n = static_cast<int>(m.triangles.size());
  if (n < 2) return {-1, -1};
  const double d = bounding_box_diagonal(m), eps = 1e-10 * d;
  std::vector<Point> lo(n), hi(n);
  Point mlo = m.vertices[m.triangles[0][0]], mhi = mlo;
  double extent = 0;
  for (int t = 0; t < n; ++t) {
    lo[t] = hi[t] = m.vertices[m.triangles[t][0]];
    for (int k = 1; k < 3; ++k)
      for (int a = 0; a < 3; ++a) {
        lo[t][a] = std::min(lo[t][a], m.vertices[m.triangles[t][k]][a]);
        hi[t][a] = std::max(hi[t][a], m.vertices[m.triangles[t][k]][a]);
      }
    for (int a = 0; a < 3; ++a) {
      mlo[a] = std::min(mlo[a], lo[t][a]);
      mhi[a] = std::max(mhi[a], hi[t][a]);
      extent = std::max(extent, hi[t][a] - lo[t][a]);
    }
  }
  // cells about the largest triangle's size, at most some 64 per triangle along the box
  double h = std::max(extent, 1e-12 * d);
  for (int a = 0; a < 3; ++a) h = std::max(h, (mhi[a] - mlo[a]) / 4096.0);
  auto cell = [&](double v, int a) { return static_cast<std::int64_t>(std::floor((v - mlo[a]) / h)); };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) { return (i * 8192 + j) * 8192 + k; };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  for (int t = 0; t < n; ++t)
    for (std::int64_t i = cell(lo[t][0] - eps, 0); i <= cell(hi[t][0] + eps, 0); ++i)
      for (std::int64_t j = cell(lo[t][1] - eps, 1); j <= cell(hi[t][1] + eps, 1); ++j)
        for (std::int64_t k = cell(lo[t][2] - eps, 2); k <= cell(hi[t][2] + eps, 2); ++k) grid[key(i, j, k)].push_back(t);
  std::pair<int, int> best{-1, -1};
  for (const auto& [c, list] : grid)
    for (std::size_t x = 0; x < list.size(); ++x)
      for (std::size_t y = x + 1; y < list.size(); ++y) {
        const int t = std::min(list[x], list[y]), u = std::max(list[x], list[y]);
        if (best.first >= 0 && std::make_pair(t, u) >= best) continue;
        // each pair once: in the lowest cell both boxes reach
        std::int64_t at[3];
        bool apart = false;
        for (int a = 0; a < 3; ++a) {
          if (lo[t][a] > hi[u][a] + eps || lo[u][a] > hi[t][a] + eps) apart = true;
          at[a] = cell(std::max(lo[t][a], lo[u][a]) - eps, a);
        }
        if (apart || key(at[0], at[1], at[2]) != c) continue;
        const auto& A = m.triangles[t];
        const auto& B = m.triangles[u];
        bool shared = false;
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) shared = shared || A[p] == B[q];
        if (!shared && triangles_cross(m, t, u, eps)) best = {t, u};
      }
  return best;
}

}  // namespace ondine::geometry
