#pragma once
// Cell-linked list with cells at least as large as the cut-off: count per cell,
// exclusive scan into offsets, fill, then sort each cell by particle index so
// that the order (and so every sum over neighbours) is deterministic. Kokkos'
// BinSort is not used because its fill order within a bin depends on thread
// timing; see docs/design.md.
#include <string>

#include "kernels/PeriodicBox.hpp"

namespace ondine {

template <int D>
struct CellGrid {
  double lo[D], inv_size[D];
  int n[D];
  bool periodic[D];

  KOKKOS_INLINE_FUNCTION int coord(double x, int k) const {
    int c = static_cast<int>(kmath::floor((x - lo[k]) * inv_size[k]));
    return c < 0 ? 0 : (c >= n[k] ? n[k] - 1 : c);
  }
  KOKKOS_INLINE_FUNCTION int linear(const int* c) const {
    int idx = c[D - 1];
    for (int k = D - 2; k >= 0; --k) idx = idx * n[k] + c[k];
    return idx;
  }
  int cells() const {
    int t = 1;
    for (int k = 0; k < D; ++k) t *= n[k];
    return t;
  }
};

// Grid over the domain box with cells no smaller than `cutoff` in any axis.
template <int D>
CellGrid<D> make_cell_grid(const PeriodicBox<D>& box, double cutoff) {
  CellGrid<D> g;
  for (int k = 0; k < D; ++k) {
    g.lo[k] = box.lo[k];
    g.n[k] = static_cast<int>(box.len[k] / cutoff);
    if (g.n[k] < 1) g.n[k] = 1;
    g.inv_size[k] = g.n[k] / box.len[k];
    g.periodic[k] = box.periodic[k];
  }
  return g;
}

// The rest of a cell list's build once each particle's cell is in cell_of and the cells'
// counts in start(c + 1) (start(0) = 0): the exclusive scan into offsets, the fill, then an
// insertion sort of each cell (a handful of particles) by particle index, for determinism.
inline void finish_cells(const std::string& name, const Kokkos::View<int*, MemSpace>& start, const Kokkos::View<int*, MemSpace>& cell_of,
                         const Kokkos::View<int*, MemSpace>& perm, const int n, const int ncell) {
  Kokkos::parallel_scan(name + "::scan", Kokkos::RangePolicy<ExecSpace>(0, ncell + 1),
                        KOKKOS_LAMBDA(const int c, int& partial, const bool final) {
                          partial += start(c);
                          if (final) start(c) = partial;
                        });
  Kokkos::View<int*, MemSpace> cursor(name + "::cursor", ncell);
  Kokkos::parallel_for(name + "::fill", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
    const int c = cell_of(i);
    perm(start(c) + Kokkos::atomic_fetch_add(&cursor(c), 1)) = i;
  });
  Kokkos::parallel_for(name + "::order", Kokkos::RangePolicy<ExecSpace>(0, ncell), KOKKOS_LAMBDA(const int c) {
    const int b = start(c), e = start(c + 1);
    for (int a = b + 1; a < e; ++a) {
      const int v = perm(a);
      int p = a - 1;
      while (p >= b && perm(p) > v) {
        perm(p + 1) = perm(p);
        --p;
      }
      perm(p + 1) = v;
    }
  });
}

template <int D>
struct CellList {
  CellGrid<D> grid;
  Kokkos::View<int*, MemSpace> cell_of;     // cell of each particle
  Kokkos::View<int*, MemSpace> cell_start;  // size cells+1
  Kokkos::View<int*, MemSpace> sorted;      // particle indices in cell order

  template <class PositionView>
  void build(const CellGrid<D>& g, const PositionView& x, int n) {
    grid = g;
    const int ncell = g.cells();
    if (static_cast<int>(cell_of.extent(0)) < n) cell_of = Kokkos::View<int*, MemSpace>("ondine::CellList::cell_of", n);
    if (static_cast<int>(sorted.extent(0)) < n) sorted = Kokkos::View<int*, MemSpace>("ondine::CellList::sorted", n);
    if (static_cast<int>(cell_start.extent(0)) != ncell + 1)
      cell_start = Kokkos::View<int*, MemSpace>("ondine::CellList::cell_start", ncell + 1);
    else
      Kokkos::deep_copy(cell_start, 0);
    auto cell_of_ = cell_of;
    auto start = cell_start;
    auto perm = sorted;
    Kokkos::parallel_for("ondine::CellList::count", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      int c[D];
      for (int k = 0; k < D; ++k) c[k] = g.coord(x(i, k), k);
      const int idx = g.linear(c);
      cell_of_(i) = idx;
      Kokkos::atomic_increment(&start(idx + 1));
    });
    finish_cells("ondine::CellList", start, cell_of_, perm, n, ncell);
  }
};

// Visits the cells adjacent to `home` (3^D of them, fewer at non-periodic edges;
// a periodic axis with fewer than 3 cells visits each of its cells once).
template <int D, class F>
KOKKOS_INLINE_FUNCTION void for_each_adjacent_cell(const CellGrid<D>& g, const int* home, F&& f) {
  int lo[D], hi[D];
  for (int k = 0; k < D; ++k) {
    if (g.periodic[k] && g.n[k] < 3) {
      lo[k] = -home[k];
      hi[k] = g.n[k] - 1 - home[k];
    } else {
      lo[k] = -1;
      hi[k] = 1;
    }
  }
  int off[D];
  for (int k = 0; k < D; ++k) off[k] = lo[k];
  while (true) {
    int c[D];
    bool inside = true;
    for (int k = 0; k < D; ++k) {
      c[k] = home[k] + off[k];
      if (c[k] < 0 || c[k] >= g.n[k]) {
        if (g.periodic[k]) c[k] = (c[k] + g.n[k]) % g.n[k];
        else inside = false;
      }
    }
    if (inside) f(g.linear(c));
    int k = 0;
    while (k < D && ++off[k] > hi[k]) {
      off[k] = lo[k];
      ++k;
    }
    if (k == D) break;
  }
}

}  // namespace ondine
