#pragma once
// Full (both-ways) neighbour list in CSR form (and the half list derived from it, build_half), built from a CellList with a
// cut-off R + skin, so that it stays valid until some particle has moved more
// than skin/2 (Verlet). Physics reads it only through num_neighbours(i) and
// neighbour(i, n). Two passes: count per particle, scan, fill; no atomics, so
// the order is the deterministic cell order.
#include <string>

#include "kernels/CellList.hpp"

namespace ondine {

// Calls f(j) for every j != i within the cut-off of i, in cell order.
template <int D, class PositionView>
struct CutoffVisitor {
  CellGrid<D> g;
  PeriodicBox<D> box;
  Kokkos::View<int*, MemSpace> start, perm;
  PositionView x;
  double cut2;

  template <class F>
  KOKKOS_INLINE_FUNCTION void operator()(const int i, F&& f) const {
    const Vec<D> xi = load<D>(x, i);
    int home[D];
    for (int k = 0; k < D; ++k) home[k] = g.coord(xi[k], k);
    for_each_adjacent_cell<D>(g, home, [&](const int c) {
      for (int a = start(c); a < start(c + 1); ++a) {
        const int j = perm(a);
        if (j != i && norm2(box.delta(xi, load<D>(x, j))) < cut2) f(j);
      }
    });
  }
};

// Verlet criterion of the skin: max_i |x_i - x_i(at the last build)|^2 (minimum
// image); the list is rebuilt once it reaches (skin/2)^2. With Kokkos::Max.
template <int D>
struct MaxDisplacement2 {
  using value_type = double;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x, x_build;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mx) const {
    const double d2 = norm2(box.delta(load<D>(x, i), load<D>(x_build, i)));
    if (d2 > mx) mx = d2;
  }
};

// The same with a skin per refinement level (local time stepping): max_i of the displacement
// over the half skin of particle i's birth level, squared; the lists hold while it is below 1.
template <int D>
struct MaxScaledDisplacement2 {
  using value_type = double;
  static constexpr int max_levels = 8;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x, x_build;
  Kokkos::View<int*, MemSpace> birth;
  double inv_half_skin2[max_levels];
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mx) const {
    const double d2 = norm2(box.delta(load<D>(x, i), load<D>(x_build, i))) * inv_half_skin2[birth(i)];
    if (d2 > mx) mx = d2;
  }
};

template <int D>
struct NeighbourList {
  Kokkos::View<int*, MemSpace> offsets;     // n + 1
  Kokkos::View<int*, MemSpace> neighbours;  // offsets(n)

  KOKKOS_INLINE_FUNCTION int num_neighbours(int i) const { return offsets(i + 1) - offsets(i); }
  KOKKOS_INLINE_FUNCTION int neighbour(int i, int n) const { return neighbours(offsets(i) + n); }

  int total() const {
    int t = 0;
    Kokkos::deep_copy(t, Kokkos::subview(offsets, offsets.extent(0) - 1));
    return t;
  }

  template <class PositionView>
  void build(const CellList<D>& cells, const PeriodicBox<D>& box, const PositionView& x, int n, double cutoff) {
    fill(n, CutoffVisitor<D, PositionView>{cells.grid, box, cells.cell_start, cells.sorted, x, cutoff * cutoff},
         "ondine::NeighbourList::");
  }

  // The half list of the particles [first, end) from their full list: each pair of two of them
  // once (j > i), every partner outside the range (halos, other levels) still from i's side.
  // Entries keep the full list's order.
  void build_half(const NeighbourList<D>& full, int first, int end) {
    fill(static_cast<int>(full.offsets.extent(0)) - 1, HalfVisitor{full.offsets, full.neighbours, first, end},
         "ondine::NeighbourList::half_");
  }

  // (public: nvcc refuses an extended lambda in a private member function)
  // calls f(j) for the entries of i's full list that the half list keeps
  struct HalfVisitor {
    Kokkos::View<int*, MemSpace> offsets, neighbours;
    int first, end;
    template <class F>
    KOKKOS_INLINE_FUNCTION void operator()(const int i, F&& f) const {
      for (int a = offsets(i); a < offsets(i + 1); ++a) {
        const int j = neighbours(a);
        if (j > i || j >= end || j < first) f(j);
      }
    }
  };

  // The CSR list of particles [0, n) whose partners visit(i, f) gives: count, scan, fill
  // (kernels labelled prefix + count / scan / fill).
  template <class Visit>
  void fill(int n, const Visit& visit, const std::string& prefix) {
    if (static_cast<int>(offsets.extent(0)) != n + 1) offsets = Kokkos::View<int*, MemSpace>(prefix + "offsets", n + 1);
    auto off = offsets;
    Kokkos::parallel_for(prefix + "count", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      int cnt = 0;
      visit(i, [&](int) { ++cnt; });
      off(i + 1) = cnt;
      if (i == 0) off(0) = 0;
    });
    Kokkos::parallel_scan(prefix + "scan", Kokkos::RangePolicy<ExecSpace>(0, n + 1),
                          KOKKOS_LAMBDA(const int i, int& partial, const bool final) {
                            partial += off(i);
                            if (final) off(i) = partial;
                          });
    const int total_pairs = total();
    if (static_cast<int>(neighbours.extent(0)) < total_pairs)
      neighbours = Kokkos::View<int*, MemSpace>(prefix + "neighbours", total_pairs + total_pairs / 8);
    auto nb = neighbours;
    Kokkos::parallel_for(prefix + "fill", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      int p = off(i);
      visit(i, [&](int j) { nb(p++) = j; });
    });
  }
};

}  // namespace ondine
