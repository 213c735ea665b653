#pragma once
// The cell lists the APR lists L. and Lx are built from: a grid per level, with cells no
// smaller than that level's list cut-off R_l + skin_l, the cells of the domain's lattice of
// that size that the level's particles (owned and halos) span (the whole axis where it is
// periodic), the levels' grids numbered end to end in one CSR. A query of radius c scans ceil(c / cell) cells each way.
// With the domain's one grid of the coarsest cut-off a particle k levels finer scanned
// 4^k (2D) or 8^k (3D) times the cells its own cut-off needs (the refined cylinder's three
// levels: the lists' count and fill took 21 % of the run; perf/README.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "kernels/CellList.hpp"
#include "kernels/Fields.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

// A level's grid: the cells of the global lattice of its cut-off (origin the domain's corner, as
// make_cell_grid) from cell `first` on, `n` of them per axis. Cut from one lattice, the cells and
// the order a row is filled in are the same on any rank count (a restart from 2 ranks onto 1
// gives the same sums, bit for bit).
template <int D>
struct LevelGrid : CellGrid<D> {  // lo, inv_size, n, periodic, linear(), cells() of the cut grid
  int first[D];
};

template <int D>
struct LevelGrids {
  LevelGrid<D> grid[kAprMaxLevels];
  int base[kAprMaxLevels + 1] = {};  // each level's first cell in the CSR
  int levels = 0;
};

// The cell of x along axis k: along a periodic axis the cell of its image in the box (a
// particle of a rank that does not span a periodic axis, or a halo, may lie beyond it by
// more than a cell of a fine level), elsewhere clamped to the grid's end cells.
template <int D>
KOKKOS_INLINE_FUNCTION int level_cell_coord(const LevelGrid<D>& g, const double x, const int k) {
  const int c = static_cast<int>(kmath::floor((x - g.lo[k]) * g.inv_size[k])) - g.first[k];
  if (g.periodic[k]) return ((c % g.n[k]) + g.n[k]) % g.n[k];
  return c < 0 ? 0 : (c >= g.n[k] ? g.n[k] - 1 : c);
}

// Calls f(cell) for each cell of g within c of xi along every axis (the cells of the
// axis' range [xi - c, xi + c]; each cell once where a periodic axis has fewer cells than
// the range spans).
template <int D, class F>
KOKKOS_INLINE_FUNCTION void for_each_cell_within(const LevelGrid<D>& g, const Vec<D>& xi, const double c, F&& f) {
  int home[D], lo[D], hi[D], off[D];
  for (int k = 0; k < D; ++k) {
    home[k] = level_cell_coord<D>(g, xi[k], k);
    const int m = static_cast<int>(kmath::ceil(c * g.inv_size[k]));
    if (g.periodic[k] && g.n[k] < 2 * m + 1) {
      lo[k] = -home[k];
      hi[k] = g.n[k] - 1 - home[k];
    } else {
      lo[k] = -m;
      hi[k] = m;
    }
    off[k] = lo[k];
  }
  while (true) {
    int cc[D];
    bool inside = true;
    for (int k = 0; k < D; ++k) {
      cc[k] = home[k] + off[k];
      if (cc[k] < 0 || cc[k] >= g.n[k]) {
        if (g.periodic[k]) cc[k] = ((cc[k] % g.n[k]) + g.n[k]) % g.n[k];
        else inside = false;
      }
    }
    if (inside) f(g.linear(cc));
    int k = 0;
    while (k < D && ++off[k] > hi[k]) {
      off[k] = lo[k];
      ++k;
    }
    if (k == D) break;
  }
}

// Each level's lower corner and, negated, upper corner (one min-reduction of 2 D levels values).
template <int D>
struct LevelBounds {
  using value_type = double[];
  int value_count;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;
  KOKKOS_INLINE_FUNCTION void init(value_type v) const {
    for (int a = 0; a < value_count; ++a) v[a] = 1e300;
  }
  KOKKOS_INLINE_FUNCTION void join(volatile double* a, const volatile double* b) const {
    for (int k = 0; k < value_count; ++k) a[k] = b[k] < a[k] ? b[k] : a[k];
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type v) const {
    const int l = birth(i);
    for (int k = 0; k < D; ++k) {
      const double xk = x(i, k);
      double& mn = v[2 * D * l + k];
      double& mx = v[2 * D * l + D + k];
      mn = xk < mn ? xk : mn;
      mx = -xk < mx ? -xk : mx;
    }
  }
};

template <int D>
struct LevelCells {
  LevelGrids<D> grids;
  Kokkos::View<int*, MemSpace> cell_of;     // CSR cell of each particle
  Kokkos::View<int*, MemSpace> cell_start;  // size cells + 1
  Kokkos::View<int*, MemSpace> sorted;      // particle indices in cell order (by index within a cell)

  // n particles (owned and halos), each binned in its birth level's grid; cutoff[l] = R_l + skin_l.
  void build(const PeriodicBox<D>& box, const double* cutoff, const int levels, const field_view_t<field::Position, D>& x,
             const field_view_t<field::AprBirthLevel, D>& birth, const int n) {
    std::vector<double> bounds(2 * D * levels);
    if (n > 0)
      Kokkos::parallel_reduce("ondine::APR::level_bounds", Kokkos::RangePolicy<ExecSpace>(0, n),
                              LevelBounds<D>{2 * D * levels, x, birth}, bounds.data());
    else
      std::fill(bounds.begin(), bounds.end(), std::numeric_limits<double>::infinity());
    grids.levels = levels;
    grids.base[0] = 0;
    for (int l = 0; l < levels; ++l) {
      LevelGrid<D>& g = grids.grid[l];
      for (int k = 0; k < D; ++k) {
        const int cells = box.len[k] > cutoff[l] ? static_cast<int>(box.len[k] / cutoff[l]) : 1;  // make_cell_grid's
        g.lo[k] = box.lo[k];
        g.inv_size[k] = cells / box.len[k];
        g.periodic[k] = box.periodic[k];
        g.first[k] = 0;
        g.n[k] = cells;
        if (!box.periodic[k]) {
          const double mn = bounds[2 * D * l + k], mx = -bounds[2 * D * l + D + k];
          const auto clamp = [&](double x) {
            const double c = std::floor((x - box.lo[k]) * g.inv_size[k]);
            return c < 0 ? 0 : (c >= cells ? cells - 1 : static_cast<int>(c));
          };
          if (mn <= mx) {  // else no particle of this level: the whole lattice, empty
            g.first[k] = clamp(mn);
            g.n[k] = clamp(mx) - g.first[k] + 1;
          }
        }
      }
      grids.base[l + 1] = grids.base[l] + g.cells();
    }
    const int ncell = grids.base[levels];
    if (static_cast<int>(cell_of.extent(0)) < n) cell_of = Kokkos::View<int*, MemSpace>("ondine::APR::LevelCells::cell_of", n);
    if (static_cast<int>(sorted.extent(0)) < n) sorted = Kokkos::View<int*, MemSpace>("ondine::APR::LevelCells::sorted", n);
    if (static_cast<int>(cell_start.extent(0)) < ncell + 1)
      cell_start = Kokkos::View<int*, MemSpace>("ondine::APR::LevelCells::cell_start", ncell + 1 + ncell / 8);
    Kokkos::deep_copy(cell_start, 0);
    const auto start = cell_start;
    const LevelGrids<D> gs = grids;
    const auto cell = cell_of;
    const auto perm = sorted;
    Kokkos::parallel_for("ondine::APR::LevelCells::count", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      const int l = birth(i);
      int c[D];
      for (int k = 0; k < D; ++k) c[k] = level_cell_coord<D>(gs.grid[l], x(i, k), k);
      const int idx = gs.base[l] + gs.grid[l].linear(c);
      cell(i) = idx;
      Kokkos::atomic_increment(&start(idx + 1));
    });
    // the scan, the fill and each cell by particle index (CellList.hpp)
    finish_cells("ondine::APR::LevelCells", start, cell, perm, n, ncell);
  }
};

}  // namespace apr

}  // namespace ondine
