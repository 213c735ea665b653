#pragma once
// The ways a pass meets its neighbours, shared by every kernel, the term-pack pair loop
// included: through the CSR neighbour list, or through a cell list of points (wall
// quadrature points, or particles around a wall point). The first two call
// f(index, x_centre - x_point (minimum image), r) for points strictly within sqrt(R2);
// skin pairs are skipped. for_each_listed_neighbour visits every entry of the list, the
// skin's included, until f returns true.
#include "kernels/CellList.hpp"
#include "kernels/NeighbourList.hpp"

namespace ondine {

template <int D, class PositionView, class F>
KOKKOS_INLINE_FUNCTION void for_each_neighbour_within(const NeighbourList<D>& list, const PeriodicBox<D>& box,
                                                      const PositionView& x, const int i, const Vec<D>& xi,
                                                      const double R2, F&& f) {
  const int nn = list.num_neighbours(i);
  for (int n = 0; n < nn; ++n) {
    const int j = list.neighbour(i, n);
    const Vec<D> xij = box.delta(xi, load<D>(x, j));
    const double r2 = norm2(xij);
    if (r2 >= R2) continue;
    f(j, xij, kmath::sqrt(r2));
  }
}

template <int D, class F>
KOKKOS_INLINE_FUNCTION void for_each_listed_neighbour(const NeighbourList<D>& list, const int i, F&& f) {
  const int nn = list.num_neighbours(i);
  for (int n = 0; n < nn; ++n)
    if (f(list.neighbour(i, n))) return;
}

template <int D, class PositionView, class F>
KOKKOS_INLINE_FUNCTION void for_each_point_within(const CellList<D>& cells, const PeriodicBox<D>& box,
                                                  const PositionView& points, const Vec<D>& xc, const double R2,
                                                  F&& f) {
  int home[D];
  for (int k = 0; k < D; ++k) home[k] = cells.grid.coord(xc[k], k);
  for_each_adjacent_cell<D>(cells.grid, home, [&](const int c) {
    for (int a = cells.cell_start(c); a < cells.cell_start(c + 1); ++a) {
      const int q = cells.sorted(a);
      const Vec<D> d = box.delta(xc, load<D>(points, q));
      const double r2 = norm2(d);
      if (r2 >= R2) continue;
      f(q, d, kmath::sqrt(r2));
    }
  });
}

}  // namespace ondine
