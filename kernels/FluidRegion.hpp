#pragma once
// Which lattice points of the initial fill lie in the fluid: on the fluid side
// of every closed wall (inside a tank, outside a body; crossing-number test in 2D,
// winding number in 3D), not just behind a facet of an open wall, and at least `clearance` from every wall facet (dx/2 unless
// the block's wall_clearance says otherwise). Also the impermeability
// diagnostic: particles closer than 0.1 dx to a wall or on its solid side.
#include "kernels/FillCuts.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

// Closed walls as ranges of facets, with the side the fluid is on.
struct ClosedWallRanges {
  Kokkos::View<int*, MemSpace> first, count;  // facet range of each closed wall
  Kokkos::View<int*, MemSpace> fluid_inside;  // 1: tank, 0: body
  int walls = 0;
};

template <int D>
struct FluidRegion {
  WallFacets<D> facets;
  FacetCells<D> cells;  // the facets near each cell: clearances and depths below R only
  PeriodicBox<D> box;
  ClosedWallRanges closed;
  double behind = 0;  // depth behind a facet that counts as crossed (dx)

  // 1 when p is in the fluid with at least `clearance` (< R) to every facet
  KOKKOS_INLINE_FUNCTION bool contains(const Vec<D>& p, double clearance) const {
    bool out = false;
    for_each_facet_near<D>(cells, box, p, [&](const int s, const Vec<D>& ps) {
      if (out) return;
      const Facet<D> f = facets(s);
      if (facet_distance2<D>(ps, f) < clearance * clearance) out = true;
      // behind a facet of an open wall (its solid side), less than `behind` from it: crossed.
      // A closed wall's side is the exact test below: the depth test would take the fluid beside
      // a body part thinner than `behind` (an acute tip) for fluid behind its far face.
      if (in_closed_wall(s)) return;
      const double dn = facet_signed_distance<D>(ps, f);
      if (dn < 0 && dn > -behind && facet_spans<D>(ps, f)) out = true;
    });
    if (out) return false;
    for (int w = 0; w < closed.walls; ++w)
      if (inside_closed(p, w) != (closed.fluid_inside(w) == 1)) return false;
    return true;
  }

  KOKKOS_INLINE_FUNCTION bool in_closed_wall(const int s) const {
    for (int w = 0; w < closed.walls; ++w)
      if (s >= closed.first(w) && s < closed.first(w) + closed.count(w)) return true;
    return false;
  }

  // p inside closed wall w: the crossing number of its polygon (2D), its winding number (3D)
  KOKKOS_INLINE_FUNCTION bool inside_closed(const Vec<D>& p, const int w) const {
    if constexpr (D == 2) {
      bool inside = false;
      for (int s = closed.first(w); s < closed.first(w) + closed.count(w); ++s) {
        const Vec<2> a = load<2>(facets.a, s), b = load<2>(facets.b, s);
        if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
          inside = !inside;
      }
      return inside;
    } else {
      double winding = 0.0;  // -1 inside a tank (n_in inwards), +1 inside a body
      for (int s = closed.first(w); s < closed.first(w) + closed.count(w); ++s) winding += triangle_winding(p, facets(s));
      return closed.fluid_inside(w) == 1 ? winding < -0.5 : winding > 0.5;
    }
  }
};

// keep(i) = 1 for lattice points in the fluid region, with the clearance of the
// point's block (fluid_blocks[b].wall_clearance): block b holds the lattice indices
// (global ids before renumbering) [block_end(b - 1), block_end(b)).
template <int D>
struct FluidRegionFilter {
  FluidRegion<D> region;
  bool walls;  // false: the blocks' cuts only
  Kokkos::View<std::int64_t*, MemSpace> block_end;
  Kokkos::View<double*, MemSpace> block_clearance;  // m
  FillCuts<D> cuts;  // the blocks' half-space cuts, with their margins
  field_view_t<field::Position, D> x;
  field_view_t<field::GlobalId, D> id;
  Kokkos::View<int*, MemSpace> keep;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int b = 0;
    while (b + 1 < static_cast<int>(block_end.extent(0)) && id(i) >= block_end(b)) ++b;
    const Vec<D> p = load<D>(x, i);
    const bool in = (!walls || region.contains(p, block_clearance(b))) && cuts.inside(b, p, true);
    keep(i) = in ? 1 : 0;
  }
};

// Counts particles that have leaked (outside the fluid region) or come closer than `near` to a
// wall; with refinement (`level` allocated) `near` is the coarse level's and a particle of birth
// level l is held to near / 2^l.
template <int D>
struct WallLeakCount {
  FluidRegion<D> region;
  double near;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> level = {};
  KOKKOS_INLINE_FUNCTION void operator()(const int i, long& c) const {
    const double d = level.extent(0) > static_cast<std::size_t>(i) ? near / static_cast<double>(1 << level(i)) : near;
    if (!region.contains(load<D>(x, i), d)) ++c;
  }
};

// The check of a fill before the first step: the particles within R of a wall facet,
// beside its span, counted per wall on the facet's fluid side (n_in) and on its solid
// side: count(w, 0) in front, count(w, 1) behind. A wall whose fluid_side is the wrong way
// round has its fluid behind it.
template <int D>
struct WallSideCount {
  WallFacets<D> facets;
  FacetCells<D> cells;
  PeriodicBox<D> box;
  double R;
  field_view_t<field::Position, D> x;
  Kokkos::View<long* [2], Kokkos::LayoutRight, MemSpace> count;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for_each_facet_near<D>(cells, box, load<D>(x, i), [&](const int s, const Vec<D>& p) {
      const Facet<D> f = facets(s);
      const double dn = facet_signed_distance<D>(p, f);
      if (dn > -R && dn < R && facet_spans<D>(p, f)) Kokkos::atomic_increment(&count(facets.wall(s), dn >= 0 ? 0 : 1));
    });
  }
};

// Exclusive scan of keep flags into new indices; total in the return value.
struct KeepScan {
  Kokkos::View<int*, MemSpace> keep, index;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& partial, const bool final) const {
    if (final) index(i) = partial;
    partial += keep(i);
  }
};

// gather list: order(index(i)) = i for kept i
struct KeepGather {
  Kokkos::View<int*, MemSpace> keep, index, order;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (keep(i)) order(index(i)) = i;
  }
};

}  // namespace ondine

namespace ondine {
// id(i) = offset + i
struct Iota {
  Kokkos::View<std::int64_t*, MemSpace> id;
  std::int64_t offset = 0;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { id(i) = offset + i; }
};
// index(i) = i
struct Iota32 {
  Kokkos::View<int*, MemSpace> index;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { index(i) = i; }
};
}  // namespace ondine
