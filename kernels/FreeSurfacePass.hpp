#pragma once
// Free-surface detection of Marrone et al. (2010) with the NFM renormalisation
// matrix and normal (thesis 4.86-4.87), so that particles next to a wall are not
// taken for surface particles:
//   B^-1 = (1/gamma_i) [ sum_P w_j (x_j - x_i) (x) grad_i W_ij + sum_S s_q (x_q - x_i) (x) n_q W_iq ]
//   n~   = -B v / |B v|,  v = sum_P w_j grad_i W_ij + sum_S s_q n_q W_iq   (n = n_out)
// lambda = smallest eigenvalue of (the symmetric part of) B^-1: > 0.75 interior,
// < 0.2 surface, otherwise the umbrella test with h = R/2 (Marrone's smoothing
// length; thresholds and scan region from that paper, not from the seed): i is
// on the surface when no neighbour lies in the umbrella around T = x_i + h n~.
#include "kernels/CellList.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

namespace detail {
// smallest eigenvalue of a symmetric D x D matrix (closed forms)
template <int D>
KOKKOS_INLINE_FUNCTION double min_eigenvalue_sym(const Mat<D>& m) {
  if constexpr (D == 2) {
    const double tr = m.a[0][0] + m.a[1][1], det = m.a[0][0] * m.a[1][1] - m.a[0][1] * m.a[1][0];
    const double disc = kmath::sqrt(kmath::fmax(0.25 * tr * tr - det, 0.0));
    return 0.5 * tr - disc;
  } else {
    const double p1 = m.a[0][1] * m.a[0][1] + m.a[0][2] * m.a[0][2] + m.a[1][2] * m.a[1][2];
    const double q = (m.a[0][0] + m.a[1][1] + m.a[2][2]) / 3.0;
    const double p2 = (m.a[0][0] - q) * (m.a[0][0] - q) + (m.a[1][1] - q) * (m.a[1][1] - q) +
                      (m.a[2][2] - q) * (m.a[2][2] - q) + 2.0 * p1;
    const double p = kmath::sqrt(p2 / 6.0);
    if (p < 1e-300) return q;
    Mat<3> b;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) b.a[r][c] = (m.a[r][c] - (r == c ? q : 0.0)) / p;
    double rr = determinant(b) / 2.0;
    rr = kmath::fmax(-1.0, kmath::fmin(1.0, rr));
    const double phi = kmath::acos(rr) / 3.0;
    return q + 2.0 * p * kmath::cos(phi + 2.0 * 3.14159265358979323846 / 3.0);
  }
}
}  // namespace detail

template <int D, class Kernel, bool Walls>
struct FreeSurfacePass {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R, R2;
  WallPoints<D> wall;
  CellList<D> wall_cells;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::ShepardGamma, D> gamma;  // only read with walls
  field_view_t<field::FreeSurface, D> surface;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    Mat<D> M = Mat<D>::zero();
    Vec<D> v = Vec<D>::zero();
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double w = m(j) / rho(j);
      const Vec<D> gradW = (W.derivative(r) / r) * xij;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) M.a[a][b] -= w * xij[a] * gradW[b];
      v += w * gradW;
    });
    double inv_gamma = 1.0;
    if constexpr (Walls) {
      inv_gamma = 1.0 / gamma(i);
      for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
        const double sW = wall.s(q) * W.value(r);
        const Vec<D> nq = load<D>(wall.n_out, q);
        for (int a2 = 0; a2 < D; ++a2)
          for (int b2 = 0; b2 < D; ++b2) M.a[a2][b2] -= sW * xiq[a2] * nq[b2];
        v += sW * nq;
      });
    }
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) M.a[a][b] *= inv_gamma;
    Mat<D> S;
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) S.a[a][b] = 0.5 * (M.a[a][b] + M.a[b][a]);
    const double lambda = detail::min_eigenvalue_sym<D>(S);
    double flag = 0.0;
    if (lambda < 0.2) {
      flag = 1.0;
    } else if (lambda <= 0.75) {
      Mat<D> B;
      Vec<D> nt = invert(M, B, 1e-12) ? B * v : v;
      const double len = kmath::sqrt(norm2(nt));
      if (len > 0) {
        nt *= -1.0 / len;
        const double h = 0.5 * R;
        Vec<D> T = xi + h * nt;
        bool blocked = false;
        for_each_listed_neighbour<D>(list, i, [&](const int j) {
          const Vec<D> xji = box.delta(load<D>(x, j), xi);  // x_j - x_i
          const double rji = kmath::sqrt(norm2(xji));
          const Vec<D> xjT = (xji + xi) - T;
          if (rji >= 1.4142135623730951 * h) {
            blocked = norm2(xjT) < h * h;
          } else {
            const double along = dot(nt, xjT);
            const double across = kmath::sqrt(kmath::fmax(norm2(xjT) - along * along, 0.0));
            blocked = (along < 0 ? -along : along) + across < h;
          }
          return blocked;
        });
        flag = blocked ? 0.0 : 1.0;
      }
    }
    surface(i) = flag;
  }

  void run(int n) const { Kokkos::parallel_for("ondine::FreeSurface", Kokkos::RangePolicy<ExecSpace>(0, n), *this); }
};

}  // namespace ondine
