#pragma once
// Device side of the domain decomposition (src/parallel/Decomposition.hpp): the
// owner of a cell by descending the bisection tree, and the halo destinations of
// a particle: every other rank whose ring of cells (one cell, at least R + skin,
// around its subdomain) holds the particle's cell, with the periodic image that
// rank sees it at.
#include "kernels/NeighbourList.hpp"
#include "kernels/OrbTypes.hpp"

namespace ondine {

// A periodic image as one code: digit k (base 5) is s_k + 2, the shift being
// s_k L_k, s_k in [-2, 2] (a particle that drifted past a periodic face since its
// last wrap, seen across that face).
constexpr int image_codes = 125;
KOKKOS_INLINE_FUNCTION int image_code_of(const int* s, int dim) {
  int code = 0, base = 1;
  for (int k = 0; k < dim; ++k) {
    code += (s[k] + 2) * base;
    base *= 5;
  }
  return code;
}
KOKKOS_INLINE_FUNCTION int image_shift(int code, int k) {
  for (int a = 0; a < k; ++a) code /= 5;
  return code % 5 - 2;
}

template <int D>
struct OrbLookup {
  CellGrid<D> grid;                                // the global grid of the decomposition
  Kokkos::View<OrbNode*, MemSpace> nodes;          // bisection tree, root first
  Kokkos::View<int* [6], Kokkos::LayoutRight, MemSpace> boxes;  // per rank: lo[3], hi[3]

  KOKKOS_INLINE_FUNCTION int owner_of_cell(const int* c) const {
    int node = 0;
    while (nodes(node).axis >= 0) node = c[nodes(node).axis] < nodes(node).cut ? nodes(node).left : nodes(node).right;
    return nodes(node).left;
  }
  // owner of a position already wrapped into the periodic box (clamped at open faces)
  KOKKOS_INLINE_FUNCTION int owner(const Vec<D>& x) const {
    int c[D];
    for (int k = 0; k < D; ++k) c[k] = grid.coord(x[k], k);
    return owner_of_cell(c);
  }
  KOKKOS_INLINE_FUNCTION bool spans(int rank, int k) const { return boxes(rank, k) == 0 && boxes(rank, 3 + k) == grid.n[k]; }

  // f(rank, image_code) once for every (rank != me, image) that needs the particle
  // at x as a halo. Owned positions are wrapped only at migration, so x may lie
  // past a periodic face: its cell is that of the wrapped position, and the image
  // includes the wrap.
  template <class F>
  KOKKOS_INLINE_FUNCTION void for_each_halo_destination(const int me, const Vec<D>& x, F&& f) const {
    int c[D], w[D];
    for (int k = 0; k < D; ++k) {
      w[k] = 0;
      if (grid.periodic[k]) {
        const double len = grid.n[k] / grid.inv_size[k];
        w[k] = -static_cast<int>(kmath::floor((x[k] - grid.lo[k]) / len));
      }
      c[k] = grid.coord(x[k] + w[k] * (grid.n[k] / grid.inv_size[k]), k);
    }
    int seen_rank[27], seen_code[27], nseen = 0;  // at most 3^D destinations
    int off[D];
    for (int k = 0; k < D; ++k) off[k] = -1;
    while (true) {
      int q[D], s[D];
      bool inside = true;
      for (int k = 0; k < D; ++k) {
        q[k] = c[k] + off[k];
        s[k] = 0;
        if (q[k] < 0 || q[k] >= grid.n[k]) {
          if (!grid.periodic[k]) inside = false;
          s[k] = q[k] < 0 ? 1 : -1;  // the rank over the periodic face sees x shifted by +-L
          q[k] += s[k] * grid.n[k];
        }
      }
      if (inside) {
        const int r = owner_of_cell(q);
        if (r != me) {
          // the receiver's grid is periodic along the axes it spans: it takes the
          // wrapped position there
          for (int k = 0; k < D; ++k) s[k] = spans(r, k) ? w[k] : s[k] + w[k];
          const int code = image_code_of(s, D);
          bool dup = false;
          for (int a = 0; a < nseen; ++a) dup = dup || (seen_rank[a] == r && seen_code[a] == code);
          if (!dup) {
            seen_rank[nseen] = r;
            seen_code[nseen] = code;
            ++nseen;
            f(r, code);
          }
        }
      }
      int k = 0;
      while (k < D && ++off[k] > 1) {
        off[k] = -1;
        ++k;
      }
      if (k == D) break;
    }
  }
};

// Work of each cell of the global grid for the bisection: one per particle plus
// its neighbours in the list (the pair interactions, thesis 5.5.2).
template <int D>
struct CellWork {
  CellGrid<D> grid;
  PeriodicBox<D> box;
  NeighbourList<D> list;
  field_view_t<field::Position, D> x;
  Kokkos::View<double*, MemSpace> work;
  bool pairs;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int c[D];
    for (int k = 0; k < D; ++k) c[k] = grid.coord(box.wrap(x(i, k), k), k);
    Kokkos::atomic_add(&work(grid.linear(c)), 1.0 + (pairs ? list.num_neighbours(i) : 0));
  }
};

}  // namespace ondine
