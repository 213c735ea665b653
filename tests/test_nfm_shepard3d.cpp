// Analytical Shepard factor of NFM walls in 3D (thesis 4.60-4.82) against the reference values
// of nfm.md §14, the closed-form flat wall, and a brute-force integration of the 3D Wendland C2
// kernel over the fluid side of triangulated walls (cube, 90 degree edges, icosphere).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/ShepardGamma3D.hpp"
#include "kernels/SmoothingKernels.hpp"

using namespace ondine;

namespace {

struct Tri {
  Vec<3> a, b, c, n_in;
};

Vec<3> v3(double x, double y, double z) { return Vec<3>{{x, y, z}}; }

Vec<3> cross(const Vec<3>& u, const Vec<3>& v) {
  return v3(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
}

double sum_of(const std::vector<Tri>& tris, const Vec<3>& x, double R) {
  double s = 0;
  for (const Tri& t : tris) s += shepard_gamma_triangle(x, t.a, t.b, t.c, t.n_in, R);
  return s;
}

double gamma_of(const std::vector<Tri>& tris, const Vec<3>& x, double R = 1.0) {
  return shepard_gamma_from_sum(sum_of(tris, x, R));
}

// The parallelogram o + [0,1] u + [0,1] v cut into nu x nv cells of 2 triangles each, fluid on
// the side of n_in; vertex (i, j) is grid_point(o, u, v, nu, nv, i, j), so that a particle can be
// put exactly above it. The diagonal and the listing order alternate from cell to cell.
Vec<3> grid_point(const Vec<3>& o, const Vec<3>& u, const Vec<3>& v, int nu, int nv, int i, int j) {
  return o + (double(i) / nu) * u + (double(j) / nv) * v;
}

void add_grid(std::vector<Tri>& out, const Vec<3>& o, const Vec<3>& u, const Vec<3>& v, int nu, int nv, const Vec<3>& n_in) {
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const Vec<3> p00 = grid_point(o, u, v, nu, nv, i, j), p10 = grid_point(o, u, v, nu, nv, i + 1, j);
      const Vec<3> p01 = grid_point(o, u, v, nu, nv, i, j + 1), p11 = grid_point(o, u, v, nu, nv, i + 1, j + 1);
      if ((i + j) % 2 == 0) {
        out.push_back({p00, p10, p11, n_in});
        out.push_back({p00, p01, p11, n_in});  // the other order
      } else {
        out.push_back({p10, p01, p00, n_in});
        out.push_back({p10, p11, p01, n_in});
      }
    }
}

// The cube [0, 2]^3 with the fluid inside, each face cut into m x m squares of 2 triangles.
std::vector<Tri> cube(int m) {
  std::vector<Tri> t;
  const double L = 2;
  for (int ax = 0; ax < 3; ++ax) {
    Vec<3> u = Vec<3>::zero(), v = Vec<3>::zero(), n = Vec<3>::zero(), o = Vec<3>::zero();
    u[(ax + 1) % 3] = L;
    v[(ax + 2) % 3] = L;
    n[ax] = 1;
    add_grid(t, o, u, v, m, m, n);  // face x_ax = 0
    o[ax] = L;
    add_grid(t, o, u, v, m, m, -1.0 * n);  // face x_ax = L
  }
  return t;
}

// Icosphere: an icosahedron subdivided `levels` times, vertices on the sphere of radius rs about
// c; the fluid inside or outside. Every other triangle is listed clockwise.
std::vector<Tri> icosphere(int levels, double rs, const Vec<3>& c, bool fluid_inside) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec<3>> p = {v3(-1, g, 0), v3(1, g, 0), v3(-1, -g, 0), v3(1, -g, 0), v3(0, -1, g), v3(0, 1, g),
                           v3(0, -1, -g), v3(0, 1, -g), v3(g, 0, -1), v3(g, 0, 1), v3(-g, 0, -1), v3(-g, 0, 1)};
  auto unit = [](const Vec<3>& a) { return (1.0 / std::sqrt(norm2(a))) * a; };
  for (Vec<3>& q : p) q = unit(q);
  struct F {
    Vec<3> a, b, c;
  };
  const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                        {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<F> faces;
  for (auto& k : f) faces.push_back({p[k[0]], p[k[1]], p[k[2]]});
  for (int l = 0; l < levels; ++l) {
    std::vector<F> next;
    for (const F& t : faces) {
      // a + b == b + a exactly: a shared edge gets the same midpoint in both of its faces
      const Vec<3> ab = unit(t.a + t.b), bc = unit(t.b + t.c), ca = unit(t.c + t.a);
      next.push_back({t.a, ab, ca});
      next.push_back({ab, t.b, bc});
      next.push_back({ca, bc, t.c});
      next.push_back({ab, bc, ca});
    }
    faces = next;
  }
  std::vector<Tri> out;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const F& t = faces[k];
    const Vec<3> a = c + rs * t.a, b = c + rs * t.b, cc = c + rs * t.c;
    Vec<3> n = unit(cross(b - a, cc - a));
    const bool outward = dot(n, a - c) > 0;
    if (outward == fluid_inside) n = -1.0 * n;
    if (k % 2) out.push_back({a, cc, b, n});
    else out.push_back({a, b, cc, n});
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Brute force. gamma(x) = int_fluid W(|y - x|) dy = int over directions of int_0^R chi W r^2 dr.
// A ray from x leaves or re-enters the fluid where it crosses a triangle, so triangle T adds
//   sign(dl) int_T d_n (G(min(rho, R)) - G(R)) / rho^3 dA,   rho = |y - x|, d_n = |dl|,
// to gamma (for x in the fluid, to 1 + the sum; for x in the solid, to the sum), with
// G(rho) = int_0^rho W(s) s^2 ds and d_n dA / rho^3 the solid angle of dA. The triangle is
// integrated in polar coordinates about the projection sigma of x: T is the signed sum of the
// triangles (sigma, s1, s2) over its edges; in each, the radial integral
//   inner(rho_max) = d_n int_{d_n}^{min(rho_max, R)} (G(rho) - G(R)) / rho^2 drho
// is exact (G / rho^2 is a polynomial of degree 6, G is a Gauss-Legendre integral of
// WendlandC2<3>::value, exact for its degree-7 integrand), and the angle is integrated by
// adaptive Gauss-Legendre. Nothing of Phi, Gamma or the singular weights is used.
constexpr double gl_x[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845, 0.9739065285171717};
constexpr double gl_w[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806, 0.0666713443086881};

template <class F>
double gl10(const F& f, double a, double b) {
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = 0;
  for (int k = 0; k < 5; ++k) s += gl_w[k] * (f(m - h * gl_x[k]) + f(m + h * gl_x[k]));
  return s * h;
}

template <class F>
double adaptive(const F& f, double a, double b, double whole, int depth = 40) {
  const double m = 0.5 * (a + b);
  const double l = gl10(f, a, m), r = gl10(f, m, b);
  if (depth == 0 || std::abs(l + r - whole) <= 1e-15) return l + r;
  return adaptive(f, a, m, l, depth - 1) + adaptive(f, m, b, r, depth - 1);
}

struct BruteForce {
  WendlandC2<3> W;
  double R, GR;
  explicit BruteForce(double R_) : W(R_), R(R_) { GR = G(R); }

  double G(double rho) const {
    rho = std::min(rho, R);
    return gl10([&](double s) { return W.value(s) * s * s; }, 0.0, rho);
  }
  double inner(double d, double rho_max) const {
    const double rm = std::min(rho_max, R);
    if (rm <= d) return 0.0;
    return d * gl10([&](double r) { return G(r) / (r * r); }, d, rm) - GR * (1.0 - d / rm);
  }
  // the term of triangle (v0, v1, v2), fluid on the side of n_in (a unit normal)
  double triangle(const Vec<3>& x, const Vec<3>& v0, const Vec<3>& v1, const Vec<3>& v2, const Vec<3>& n_in) const {
    const double dn = dot(n_in, x - v0);
    const double d = std::abs(dn);
    if (d >= R) return 0.0;
    const Vec<3> c = (1.0 / 3) * (v0 + v1 + v2);
    const double rb = std::max({std::sqrt(norm2(v0 - c)), std::sqrt(norm2(v1 - c)), std::sqrt(norm2(v2 - c))});
    if (std::sqrt(norm2(x - c)) >= R + rb) return 0.0;
    const Vec<3> sig = x - dn * n_in;
    const double orient = dot(cross(v1 - v0, v2 - v0), n_in) > 0 ? 1.0 : -1.0;
    const Vec<3>* v[3] = {&v0, &v1, &v2};
    double total = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec<3>& A = *v[k];
      const Vec<3>& B = *v[(k + 1) % 3];
      const double len = std::sqrt(norm2(B - A));
      const Vec<3> t = (1.0 / len) * (B - A);
      const double area2 = dot(cross(A - sig, B - sig), n_in) * orient;  // twice the signed area
      const double q = std::abs(area2) / len;
      // (sigma, A, B) of negligible area: its term is below area * max |integrand| = q len / 2 * G(R) / d^2
      if (0.5 * q * len * GR / (d * d) < 1e-15) continue;
      const double xa = dot(A - sig, t), xb = dot(B - sig, t);
      auto f = [&](double phi) {
        const double cph = std::cos(phi);
        const double p = cph > 0 ? q / cph : 1e300;
        return inner(d, std::sqrt(d * d + p * p));
      };
      std::vector<double> cuts = {std::atan(xa / q), std::atan(xb / q)};
      for (double pc : {std::sqrt(R * R - d * d), d, 2 * d, 0.3 * R})
        if (q < pc) {
          const double ph = std::acos(q / pc);
          cuts.push_back(ph);
          cuts.push_back(-ph);
        }
      cuts.push_back(0.0);
      std::sort(cuts.begin() + 2, cuts.end());
      double s = 0, lo = cuts[0], hi = cuts[1];
      double prev = lo;
      for (std::size_t j = 2; j <= cuts.size(); ++j) {
        const double nx = j < cuts.size() ? cuts[j] : hi;
        if (nx <= prev || nx > hi) continue;
        s += adaptive(f, prev, nx, gl10(f, prev, nx));
        prev = nx;
      }
      if (prev < hi) s += adaptive(f, prev, hi, gl10(f, prev, hi));
      total += (area2 > 0 ? 1.0 : -1.0) * s;
    }
    return (dn < 0 ? -1.0 : 1.0) * total;
  }
  // gamma of x, `in_fluid` saying on which side x lies
  double gamma(const std::vector<Tri>& tris, const Vec<3>& x, bool in_fluid) const {
    double s = in_fluid ? 1.0 : 0.0;
    for (const Tri& t : tris) s += triangle(x, t.a, t.b, t.c, t.n_in);
    return s;
  }
};

// Midpoint rule on a grid of cells of side h = 2 / n whose faces lie on the walls (planes
// x_k = multiple of h: the cube [0, 2]^3, the 90 degree edges), so that each cell is wholly in or
// out of the fluid, at spacings h and h / 2, Richardson-extrapolated (the error is c2 h^2 +
// O(h^4)): a volume integration independent of the triangle decomposition above.
template <class Inside>
double grid_gamma(const Vec<3>& x, double R, int n, Inside inside) {
  const WendlandC2<3> W(R);
  auto one = [&](int m) {
    const double h = 2.0 / m;
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = int(std::floor((x[k] - R) / h));
      hi[k] = int(std::ceil((x[k] + R) / h));
    }
    double s = 0;
    for (int i = lo[0]; i < hi[0]; ++i)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int k = lo[2]; k < hi[2]; ++k) {
          const Vec<3> y = v3((i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h);
          if (inside(y)) s += W.value(std::sqrt(norm2(y - x)));
        }
    return s * h * h * h;
  };
  const double c = one(n), f = one(2 * n);
  return (4 * f - c) / 3;
}

double flat_gamma(double d) { return 1 - 0.5 * std::pow(1 - d, 6) * (1 + 3 * d + 3 * d * d); }

}  // namespace

TEST_CASE("3D Shepard: edge primitive Phi", "[unit][nfm]") {
  // nfm.md §14
  CHECK(shepard_Phi(0.8, 0.5, 0.3) == Approx(0.0012891693).margin(1e-10));
  CHECK(shepard_Phi(1.0, 0.5, 0.3) == Approx(0.0012894189).margin(1e-10));
  CHECK(shepard_Phi(0.9, 0.2, 0.1) == Approx(0.0140110730).margin(1e-10));
  CHECK(shepard_Phi(1.0, 0.7, 0.6) == Approx(0.0001209444).margin(1e-10));
  // clipped at r = 1, zero at r <= a and beyond the support
  CHECK(shepard_Phi(1.7, 0.5, 0.3) == shepard_Phi(1.0, 0.5, 0.3));
  CHECK(shepard_Phi(0.5, 0.5, 0.3) == 0.0);
  CHECK(shepard_Phi(0.4, 0.5, 0.3) == 0.0);
  CHECK(shepard_Phi(1.2, 1.0, 0.3) == 0.0);
  // against quadrature of the integrand of (4.73), s = a + u^2 removing 1/sqrt(s - a)
  double max_err = 0;
  const double pts[][3] = {{0.9, 0.5, 0.3}, {0.6, 0.2, 0.15}, {1.0, 0.35, 0.05}, {0.95, 0.9, 0.1}, {0.7, 0.3, 0.29}, {0.8, 0.6, 0.0001}};
  for (const auto& p : pts) {
    const double r = p[0], a = p[1], d = p[2];
    auto f = [&](double u) {
      const double s = a + u * u;
      return 2 * d * std::sqrt(a * a - d * d) / (4 * M_PI) * std::pow(1 - s, 6) * (1 + 3 * s + 3 * s * s) /
             ((s * s - d * d) * std::sqrt(s + a));
    };
    const double ub = std::sqrt(std::min(r, 1.0) - a);
    const double ref = adaptive(f, 0.0, ub, gl10(f, 0.0, ub));
    max_err = std::max(max_err, std::abs(shepard_Phi(r, a, d) - ref));
  }
  CHECK(max_err < 1e-12);
  // d -> 0: Phi -> 0 (no division by d); p_sk -> 0: Phi -> Gamma(d) / 4 (half of the edge's jump)
  CHECK(shepard_Phi(0.9, 0.4, 0.0) == Approx(0.0).margin(1e-15));
  CHECK(std::abs(shepard_Phi(0.9, 0.4, 1e-13)) < 1e-12);
  CHECK(shepard_Phi(0.9, 0.3 + 1e-13, 0.3) == Approx(shepard_Gamma(0.3) / 4).margin(1e-6));
  CHECK(std::isfinite(shepard_Phi(0.9, 0.3, 0.3)));
}

TEST_CASE("3D Shepard: flat wall, closed form and reference values", "[unit][nfm]") {
  // the square [-3, 3]^2 at z = 0, fluid above: as 2 triangles and as 10 x 10 x 2 triangles
  const Vec<3> o = v3(-3, -3, 0), u = v3(6, 0, 0), v = v3(0, 6, 0), up = v3(0, 0, 1);
  std::vector<Tri> two, grid;
  add_grid(two, o, u, v, 1, 1, up);
  add_grid(grid, o, u, v, 10, 10, up);
  auto P = [&](int i, int j) { return grid_point(o, u, v, 10, 10, i, j); };
  const double d[] = {0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9};
  const double ref[] = {0.514997, 0.574566, 0.646592, 0.774556, 0.872351, 0.974609, 0.998334, 0.999997};
  // in-plane positions: a generic one, on the 2-triangle diagonal, on a grid vertex, on a grid
  // edge, on a cell's diagonal, and next to (not on) a vertex
  const Vec<3> at[] = {v3(0.123, -0.456, 0), v3(0.7, 0.7, 0), P(4, 6), 0.5 * (P(3, 4) + P(4, 4)),
                       0.5 * (P(3, 4) + P(4, 5)), P(7, 2) + v3(1e-7, -3e-8, 0)};
  double max_ref = 0, max_closed = 0;
  for (int k = 0; k < 8; ++k)
    for (const Vec<3>& p : at) {
      const Vec<3> x = p + d[k] * up;
      for (const auto* m : {&two, &grid}) {
        const double g = gamma_of(*m, x);
        max_ref = std::max(max_ref, std::abs(g - ref[k]));
        max_closed = std::max(max_closed, std::abs(g - flat_gamma(d[k])));
      }
    }
  CHECK(max_ref < 6e-7);  // the table's 6 digits
  CHECK(max_closed < 1e-12);
  // far from the wall, and on it (d = 0), also on an edge and on a vertex
  CHECK(gamma_of(grid, v3(0.1, 0.2, 1.5)) == 1.0);
  for (const Vec<3>& p : at) {
    CHECK(gamma_of(grid, p) == Approx(0.5).margin(1e-14));
    CHECK(gamma_of(two, p) == Approx(0.5).margin(1e-14));
  }
  // the limit d -> 0 is continuous
  for (double dd : {1e-15, 1e-13, 1e-12, 1e-11, 1e-9})
    for (const Vec<3>& p : at) CHECK(gamma_of(grid, p + dd * up) == Approx(flat_gamma(dd)).margin(1e-12));
}

TEST_CASE("3D Shepard: positions near a shared vertex or edge (tolerance band)", "[unit][nfm]") {
  // Around vertices (8 triangles meet at grid vertex (4, 6), 4 at (5, 6)) and a point of a grid
  // edge, at offsets from far below to far above the tolerance, in several directions and at
  // several heights: the triangles' weights must add up to 1 everywhere, so that gamma is the
  // flat wall's. On the plane z = 0, and on a tilted plane, where the triangles' normals differ
  // by round-off: a particle 1e-9 R from a vertex then sees p_sk with a relative error of 1e-7
  // (1e-16 d / p_sk), which the near-singular edge terms turn into errors of about 1e-9.
  double max_err[2] = {0, 0};
  int plane = 0;
  const double s3 = 1 / std::sqrt(3.0), s2 = 1 / std::sqrt(2.0);
  const Vec<3> planes[][3] = {{v3(-3, -3, 0), v3(6, 0, 0), v3(0, 6, 0)},
                              {v3(0.1, -0.2, 0.3), v3(6 * s2, -6 * s2, 0), v3(6 * s3, 6 * s3, 6 * s3)}};
  for (const auto& pl : planes) {
    const Vec<3> o = pl[0], u = pl[1], v = pl[2];
    const Vec<3> eu = (1 / std::sqrt(norm2(u))) * u, ev = (1 / std::sqrt(norm2(v))) * v;
    const Vec<3> up = (1 / std::sqrt(norm2(cross(u, v)))) * cross(u, v);
    std::vector<Tri> grid;
    add_grid(grid, o, u, v, 10, 10, up);
    for (const Vec<3>& c : {grid_point(o, u, v, 10, 10, 4, 6), grid_point(o, u, v, 10, 10, 5, 6),
                            0.5 * (grid_point(o, u, v, 10, 10, 2, 2) + grid_point(o, u, v, 10, 10, 3, 2))})
      for (double dd : {0.0, 1e-12, 1e-6, 0.01, 0.3, 0.9})
        for (double off : {0.0, 1e-16, 1e-14, 1e-13, 1e-12, 3e-12, 1e-11, 1e-10, 3e-10, 1e-9, 3e-9, 1e-7, 1e-4})
          for (double ang : {0.0, 0.1, 0.7853981633974483, 2.0, 3.14159265358979, 4.0, 5.5}) {
            const Vec<3> x = c + (off * std::cos(ang)) * eu + (off * std::sin(ang)) * ev + dd * up;
            max_err[plane] = std::max(max_err[plane], std::abs(gamma_of(grid, x) - flat_gamma(dd)));
          }
    ++plane;
  }
  const double max_err_z0 = max_err[0], max_err_tilted = max_err[1];
  CHECK(max_err_z0 < 1e-12);
  CHECK(max_err_tilted < 1e-8);
}

TEST_CASE("3D Shepard: a single triangle", "[unit][nfm]") {
  const BruteForce bf(1.0);
  // vertex order and the length or tilt of n_in do not matter (n_in only picks the side)
  const Vec<3> a = v3(0.1, -0.2, 0.05), b = v3(0.9, 0.1, -0.1), c = v3(0.2, 0.7, 0.15);
  const Vec<3> n = (1.0 / std::sqrt(norm2(cross(b - a, c - a)))) * cross(b - a, c - a);
  const Vec<3> xs[] = {v3(0.3, 0.2, 0.25), v3(0.3, 0.2, -0.2), v3(1.1, 0.6, 0.3), v3(-0.4, 0.1, -0.05), v3(0.5, 0.4, 0.6)};
  double max_perm = 0, max_bf = 0, max_odd = 0;
  for (const Vec<3>& x : xs) {
    const double g = shepard_gamma_triangle(x, a, b, c, n, 1.0);
    for (double s : {1.0, -1.0}) {
      const Vec<3> ni = s * n;
      const Vec<3> nt = ni + v3(0.05, -0.03, 0.02);  // not unit, not normal: same side
      for (double gg : {shepard_gamma_triangle(x, a, b, c, ni, 1.0), shepard_gamma_triangle(x, b, c, a, nt, 1.0),
                        shepard_gamma_triangle(x, a, c, b, ni, 1.0), shepard_gamma_triangle(x, c, b, a, nt, 1.0)})
        max_perm = std::max(max_perm, std::abs(gg - s * g));
    }
    // brute force, from both sides (the sign flip of a particle behind the plane)
    max_bf = std::max(max_bf, std::abs(g - bf.triangle(x, a, b, c, n)));
    max_bf = std::max(max_bf, std::abs(shepard_gamma_triangle(x, a, b, c, -1.0 * n, 1.0) - bf.triangle(x, a, b, c, -1.0 * n)));
    // odd in the signed distance: the mirror image through the plane gives -g
    const Vec<3> mirror = x - 2 * dot(n, x - a) * n;
    max_odd = std::max(max_odd, std::abs(shepard_gamma_triangle(mirror, a, b, c, n, 1.0) + g));
  }
  CHECK(max_perm < 1e-14);
  CHECK(max_bf < 1e-9);
  CHECK(max_odd < 1e-14);
  CHECK(shepard_gamma_triangle(v3(0.3, 0.2, 2.0), a, b, c, n, 1.0) == 0.0);
  // sigma on a vertex of a large triangle (the other edges out of reach): -theta / (2 pi) Gamma(d),
  // theta = 90, 60 and 135 degrees; on an edge: -Gamma / 2
  const double R = 0.5, dn = 0.2;
  const BruteForce bfR(R);
  const Vec<3> z = v3(0, 0, 1);
  struct Case {
    Vec<3> p, q, r;
    double frac;
  };
  const double h = 10 * std::sqrt(3.0) / 2;
  const Case cases[] = {{v3(0, 0, 0), v3(10, 0, 0), v3(0, 10, 0), 0.25},
                        {v3(0, 0, 0), v3(10, 0, 0), v3(5, h, 0), 1.0 / 6},
                        {v3(0, 0, 0), v3(10, 0, 0), v3(-10, 10, 0), 135.0 / 360},
                        {v3(-5, 0, 0), v3(5, 0, 0), v3(0, 10, 0), 0.5}};
  for (const Case& k : cases) {
    const Vec<3> x = v3(0, 0, dn);
    const double g = shepard_gamma_triangle(x, k.p, k.q, k.r, z, R);
    CHECK(g == Approx(-k.frac * shepard_Gamma(dn / R)).margin(1e-14));
    CHECK(g == Approx(bfR.triangle(x, k.p, k.q, k.r, z)).margin(1e-9));
    // behind: the opposite
    CHECK(shepard_gamma_triangle(v3(0, 0, -dn), k.p, k.q, k.r, z, R) == Approx(k.frac * shepard_Gamma(dn / R)).margin(1e-14));
    // on the plane (d = 0): -theta / (4 pi)
    CHECK(shepard_gamma_triangle(v3(0, 0, 0), k.p, k.q, k.r, z, R) == Approx(-0.5 * k.frac).margin(1e-14));
  }
}

TEST_CASE("3D Shepard: random triangles against brute force", "[unit][nfm]") {
  // random triangles (acute, obtuse, thin) and particles in front of, behind and beside them
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double R = 0.8;
  const BruteForce bf(R);
  double max_err = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec<3> a = v3(U(rng), U(rng), U(rng)), b = v3(U(rng), U(rng), U(rng)), c = v3(U(rng), U(rng), U(rng));
    const Vec<3> nc = cross(b - a, c - a);
    if (norm2(nc) < 1e-6) continue;
    const Vec<3> n = (1 / std::sqrt(norm2(nc))) * nc;
    const Vec<3> x = (1.0 / 3) * (a + b + c) + v3(0.6 * U(rng), 0.6 * U(rng), 0.6 * U(rng));
    if (std::abs(dot(n, x - a)) < 1e-3) continue;  // the brute force wants d > 0
    max_err = std::max(max_err, std::abs(shepard_gamma_triangle(x, a, b, c, n, R) - bf.triangle(x, a, b, c, n)));
  }
  CHECK(max_err < 1e-9);
}

TEST_CASE("3D Shepard: 90 degree edges and the inside of a cube", "[unit][nfm]") {
  const double L = 4;
  // interior edge, fluid x > 0, z > 0: floor z = 0 (x in [0, L]) and wall x = 0 (z in [0, L]),
  // y in [-L, L], cut into squares of 0.5 so that y = 0 is a grid line
  std::vector<Tri> inner, outer;
  add_grid(inner, v3(0, -L, 0), v3(L, 0, 0), v3(0, 2 * L, 0), 8, 16, v3(0, 0, 1));
  add_grid(inner, v3(0, -L, 0), v3(0, 0, L), v3(0, 2 * L, 0), 8, 16, v3(1, 0, 0));
  // exterior edge, solid x < 0, z < 0: top z = 0 (x in [-L, 0]) and side x = 0 (z in [-L, 0])
  add_grid(outer, v3(-L, -L, 0), v3(L, 0, 0), v3(0, 2 * L, 0), 8, 16, v3(0, 0, 1));
  add_grid(outer, v3(0, -L, -L), v3(0, 0, L), v3(0, 2 * L, 0), 8, 16, v3(1, 0, 0));
  double max_ref = 0;
  auto ref = [&](const std::vector<Tri>& m, double x, double z, double g) {
    for (double y : {0.0, 0.1234, 0.25})  // on a grid line (y = 0), elsewhere
      max_ref = std::max(max_ref, std::abs(gamma_of(m, v3(x, y, z)) - g));
  };
  ref(inner, 0.3, 0.4, 0.816618);
  ref(inner, 0.5, 0.05, 0.559746);
  ref(outer, 0.2, -0.3, 0.802165);
  ref(outer, 0.05, 0.05, 0.819063);
  // the cube [0, 2]^3, faces cut into 9 x 9 x 2 right triangles (legs 2/9)
  const auto box = cube(9);
  const double pts[][4] = {{0.1, 0.1, 0.1, 0.269876}, {0.25, 0.45, 0.4, 0.741323}, {0.05, 0.75, 0.4, 0.537960}, {0.5, 0.5, 0.5, 0.924631}};
  for (const auto& p : pts) max_ref = std::max(max_ref, std::abs(gamma_of(box, v3(p[0], p[1], p[2])) - p[3]));
  CHECK(max_ref < 6e-7);  // the table's 6 digits
  // at the edge line and the corner: 1/4, 1/8 (inside), 3/4 (outside edge), approached from
  // any direction, including from a face's plane within 1e-10 of the edge
  CHECK(gamma_of(inner, v3(1e-7, 0.3, 1e-7)) == Approx(0.25).margin(1e-6));
  CHECK(gamma_of(inner, v3(1e-10, 0.3, 0.0)) == Approx(0.25).margin(1e-9));
  CHECK(gamma_of(inner, v3(0.0, 0.3, 1e-10)) == Approx(0.25).margin(1e-9));
  CHECK(gamma_of(outer, v3(1e-10, 0.3, 0.0)) == Approx(0.75).margin(1e-9));
  CHECK(gamma_of(box, v3(1e-8, 1e-8, 1e-8)) == Approx(0.125).margin(1e-6));
  // against brute force, R != 1, off the reference points
  const double R = 0.7;
  const BruteForce bf(R);
  double max_bf = 0;
  for (const Vec<3>& x : {v3(0.11, 0.05, 0.23), v3(0.4, -0.3, 0.02), v3(0.6, 0.1, 0.6), v3(0.25, 0.0, 0.5)})
    max_bf = std::max(max_bf, std::abs(gamma_of(inner, x, R) - bf.gamma(inner, x, true)));
  for (const Vec<3>& x : {v3(0.11, 0.05, -0.23), v3(-0.4, 0.3, 0.02), v3(0.05, 0.0, 0.01), v3(0.3, 0.5, 0.3)})
    max_bf = std::max(max_bf, std::abs(gamma_of(outer, x, R) - bf.gamma(outer, x, true)));
  CHECK(max_bf < 1e-9);
}

TEST_CASE("3D Shepard: random positions in the cube against brute force", "[unit][nfm]") {
  const auto box = cube(9);
  const double R = 1.0;
  const BruteForce bf(R);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double max_err = 0;
  for (int k = 0; k < 40; ++k) {
    // near the corner, an edge or a face (up to R from each)
    const Vec<3> x = v3(1e-3 + 1.1 * U(rng), 1e-3 + 1.1 * U(rng), 1e-3 + 1.1 * U(rng));
    max_err = std::max(max_err, std::abs(gamma_of(box, x, R) - bf.gamma(box, x, true)));
  }
  // and projections on vertices and edges of the faces' triangles (legs 2/9)
  for (const Vec<3>& x : {v3(2.0 / 9, 4.0 / 9, 0.3), v3(1.0 / 9, 1.0 / 9, 0.05), v3(0.3, 2.0 / 9, 2.0 / 9), v3(0.2, 1.0 / 9, 0.4)})
    max_err = std::max(max_err, std::abs(gamma_of(box, x, R) - bf.gamma(box, x, true)));
  CHECK(max_err < 1e-9);
}

TEST_CASE("3D Shepard: brute force agrees with a volume integration", "[unit][nfm]") {
  // the brute-force reference above checked against an integration of W over the fluid's volume:
  // inside the cube, and around an exterior edge (fluid x > 0 or z > 0), from both sides
  const auto box = cube(9);
  std::vector<Tri> outer;
  add_grid(outer, v3(-4, -4, 0), v3(4, 0, 0), v3(0, 8, 0), 8, 16, v3(0, 0, 1));
  add_grid(outer, v3(0, -4, -4), v3(0, 0, 4), v3(0, 8, 0), 8, 16, v3(1, 0, 0));
  auto in_box = [](const Vec<3>& y) { return y[0] > 0 && y[0] < 2 && y[1] > 0 && y[1] < 2 && y[2] > 0 && y[2] < 2; };
  auto in_outer = [](const Vec<3>& y) { return y[0] > 0 || y[2] > 0; };
  const BruteForce bf(1.0);
  double max_err = 0;
  for (const Vec<3>& x : {v3(0.1, 0.1, 0.1), v3(0.3, 0.17, 0.55), v3(0.05, 0.8, 0.4)})
    max_err = std::max(max_err, std::abs(bf.gamma(box, x, true) - grid_gamma(x, 1.0, 96, in_box)));
  for (const Vec<3>& x : {v3(0.2, 0.1, -0.3), v3(0.05, -0.2, 0.05)})
    max_err = std::max(max_err, std::abs(bf.gamma(outer, x, true) - grid_gamma(x, 1.0, 96, in_outer)));
  const Vec<3> solid = v3(-0.05, 0.1, -0.1);
  max_err = std::max(max_err, std::abs(bf.gamma(outer, solid, false) - grid_gamma(solid, 1.0, 96, in_outer)));
  CHECK(max_err < 1e-6);
}

TEST_CASE("3D Shepard: a triangulated sphere from inside and outside", "[unit][nfm]") {
  const double R = 0.7, rs = 2 * R;
  const Vec<3> c = v3(0.3, -0.2, 0.1);
  const auto in = icosphere(2, rs, c, true), out = icosphere(2, rs, c, false);
  REQUIRE(in.size() == 320);
  const BruteForce bf(R);
  // directions: generic ones, a vertex of the mesh, the midpoint of an edge, a face centroid
  std::vector<Vec<3>> dirs = {v3(0.3, 0.5, 0.81), v3(-0.7, 0.2, 0.1), v3(0.1, -0.9, -0.4), v3(-0.2, -0.3, 0.93)};
  dirs.push_back(in[7].a - c);
  dirs.push_back(0.5 * (in[7].a + in[7].b) - c);
  dirs.push_back((1.0 / 3) * (in[11].a + in[11].b + in[11].c) - c);
  double max_in = 0, max_out = 0, max_solid = 0;
  for (Vec<3> u : dirs) {
    u = (1.0 / std::sqrt(norm2(u))) * u;
    // inside: the faces lie within rs of c (sagitta < 0.02 R here), so these are in the fluid
    for (double depth : {0.03, 0.1, 0.3, 0.7, 1.2}) {
      const Vec<3> x = c + (rs - depth * R) * u;
      max_in = std::max(max_in, std::abs(gamma_of(in, x, R) - bf.gamma(in, x, true)));
      // with the fluid outside the same point is in the solid: gamma = the sum alone (there the
      // support must reach the wall; deeper, the sum is 0 and reads as the fluid side, gamma = 1)
      if (depth < 1) max_solid = std::max(max_solid, std::abs(gamma_of(out, x, R) - bf.gamma(out, x, false)));
    }
    for (double gap : {0.005, 0.02, 0.1, 0.35, 0.7}) {
      const Vec<3> x = c + (rs + gap * R) * u;
      max_out = std::max(max_out, std::abs(gamma_of(out, x, R) - bf.gamma(out, x, true)));
    }
  }
  // projections exactly on a vertex and on an edge of one triangle of a curved (non-coplanar) fan:
  // there the angle fraction of each triangle is exact (the fan's weights need not add up to 1)
  for (double h : {0.02, 0.1, 0.4})
    for (const Vec<3>& p : {in[7].a, 0.5 * (in[7].a + in[7].b), in[7].c}) {
      const Vec<3> xi = p + (h * R) * in[7].n_in, xo = p + (h * R) * out[7].n_in;
      max_in = std::max(max_in, std::abs(gamma_of(in, xi, R) - bf.gamma(in, xi, true)));
      max_out = std::max(max_out, std::abs(gamma_of(out, xo, R) - bf.gamma(out, xo, true)));
    }
  CHECK(max_in < 1e-9);
  CHECK(max_out < 1e-9);
  CHECK(max_solid < 1e-9);
  // far inside: 1
  CHECK(gamma_of(in, c, R) == 1.0);
}

TEST_CASE("3D Shepard: the solid side of a wall (a particle that crossed it)", "[unit][nfm]") {
  // behind a flat wall the sum is +Gamma(d) > 0, so gamma = sum (shepard_gamma_from_sum): the
  // kernel mass on the fluid side, continuous through the wall (just under 1/2 right behind it)
  const Vec<3> o = v3(-3, -3, 0), u = v3(6, 0, 0), v = v3(0, 6, 0), up = v3(0, 0, 1);
  std::vector<Tri> grid;
  add_grid(grid, o, u, v, 10, 10, up);
  CHECK(gamma_of(grid, v3(0.123, 0.2, -1e-9)) == Approx(0.5).margin(1e-8));
  CHECK(gamma_of(grid, v3(0.123, 0.2, -1e-9)) < 0.5);
  CHECK(gamma_of(grid, grid_point(o, u, v, 10, 10, 4, 6) - 1e-9 * up) == Approx(0.5).margin(1e-8));
  for (double d : {0.01, 0.1, 0.3, 0.5, 0.9}) {
    CHECK(gamma_of(grid, v3(0.123, 0.2, -d)) == Approx(1.0 - flat_gamma(d)).margin(1e-12));
    CHECK(gamma_of(grid, v3(0.123, 0.2, d)) == Approx(flat_gamma(d)).margin(1e-12));
  }
  // fluid side near distance R: 1 + sum rounds about 1 and stays on the fluid side
  CHECK(gamma_of(grid, v3(0.123, 0.2, 1.0 - 1e-12)) == Approx(1.0).margin(1e-12));
  // points that crossed the walls of an interior edge or of the cube, against brute force
  const double R = 0.7;
  const BruteForce bf(R);
  std::vector<Tri> inner;
  add_grid(inner, v3(0, -4, 0), v3(4, 0, 0), v3(0, 8, 0), 8, 16, v3(0, 0, 1));
  add_grid(inner, v3(0, -4, 0), v3(0, 0, 4), v3(0, 8, 0), 8, 16, v3(1, 0, 0));
  double max_err = 0;
  for (const Vec<3>& x : {v3(-0.02, 0.1, 0.3), v3(-0.05, 0.0, 0.01), v3(-0.01, 0.2, -0.02), v3(0.3, 0.0, -0.1)})
    max_err = std::max(max_err, std::abs(gamma_of(inner, x, R) - bf.gamma(inner, x, false)));
  const auto box = cube(9);
  for (const Vec<3>& x : {v3(-0.05, 0.3, 0.4), v3(-0.02, -0.03, 0.5), v3(-0.01, -0.02, -0.03)})
    max_err = std::max(max_err, std::abs(gamma_of(box, x, R) - bf.gamma(box, x, false)));
  CHECK(max_err < 1e-9);
}
