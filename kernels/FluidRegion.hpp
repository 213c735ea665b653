#pragma once
// Which lattice points of the initial fill lie in the fluid: on the fluid side
// of every closed wall (inside a tank, outside a body; crossing-number test) and
// at least `clearance` from every wall segment (dx/2 unless the block's
// wall_clearance says otherwise). Also the impermeability
// diagnostic: particles closer than 0.1 dx to a wall or on its solid side.
#include "kernels/WallSet.hpp"

namespace ondine {

namespace detail {
KOKKOS_INLINE_FUNCTION double segment_distance2(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b) {
  const Vec<2> ab = b - a;
  double t = dot(p - a, ab) / norm2(ab);
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return norm2(p - (a + t * ab));
}
}  // namespace detail

// Closed walls as ranges of segments, with the side the fluid is on.
struct ClosedWallRanges {
  Kokkos::View<int*, MemSpace> first, count;  // segment range of each closed wall
  Kokkos::View<int*, MemSpace> fluid_inside;  // 1: tank, 0: body
  int walls = 0;
};

template <int D>
struct FluidRegion {
  WallSegments<D> seg;
  ClosedWallRanges closed;
  double behind = 0;  // depth behind a segment that counts as crossed (dx)

  // 1 when p is in the fluid with at least `clearance` to every segment
  KOKKOS_INLINE_FUNCTION bool contains(const Vec<D>& p, double clearance) const {
    if constexpr (D != 2) {
      return true;  // walls are 2D only (the parser refuses 3D walls)
    } else {
      return contains2(p, clearance);
    }
  }
  KOKKOS_INLINE_FUNCTION bool contains2(const Vec<2>& p, double clearance) const {
    for (int s = 0; s < seg.count; ++s) {
      const Vec<2> a = load<2>(seg.a, s), b = load<2>(seg.b, s);
      if (detail::segment_distance2(p, a, b) < clearance * clearance) return false;
      // behind a segment (its solid side), less than `behind` from it: crossed (open walls too)
      const double t = dot(p - a, b - a) / norm2(b - a);
      const double dn = dot(load<2>(seg.n_in, s), p - a);
      if (t >= 0 && t <= 1 && dn < 0 && dn > -behind) return false;
    }
    for (int w = 0; w < closed.walls; ++w) {
      bool inside = false;
      for (int s = closed.first(w); s < closed.first(w) + closed.count(w); ++s) {
        const Vec<2> a = load<2>(seg.a, s), b = load<2>(seg.b, s);
        if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
          inside = !inside;
      }
      if (inside != (closed.fluid_inside(w) == 1)) return false;
    }
    return true;
  }
};

// keep(i) = 1 for lattice points in the fluid region, with the clearance of the
// point's block (fluid_blocks[b].wall_clearance): block b holds the lattice indices
// (global ids before renumbering) [block_end(b - 1), block_end(b)).
template <int D>
struct FluidRegionFilter {
  FluidRegion<D> region;
  Kokkos::View<std::int64_t*, MemSpace> block_end;
  Kokkos::View<double*, MemSpace> block_clearance;  // m
  field_view_t<field::Position, D> x;
  field_view_t<field::GlobalId, D> id;
  Kokkos::View<int*, MemSpace> keep;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int b = 0;
    while (b + 1 < static_cast<int>(block_end.extent(0)) && id(i) >= block_end(b)) ++b;
    keep(i) = region.contains(load<D>(x, i), block_clearance(b)) ? 1 : 0;
  }
};

// Counts particles that have leaked (outside the fluid region) or come closer than `near` to a wall.
template <int D>
struct WallLeakCount {
  FluidRegion<D> region;
  double near;
  field_view_t<field::Position, D> x;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, long& c) const {
    if (!region.contains(load<D>(x, i), near)) ++c;
  }
};

// The check of a fill before the first step (2D): the particles within R of a wall
// segment, beside its span, counted per wall on the segment's fluid side (n_in) and on its
// solid side: count(w, 0) in front, count(w, 1) behind. A wall whose fluid_side is the
// wrong way round has its fluid behind it.
template <int D>
struct WallSideCount {
  WallSegments<D> seg;
  double R;
  field_view_t<field::Position, D> x;
  Kokkos::View<long* [2], Kokkos::LayoutRight, MemSpace> count;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if constexpr (D == 2) {
      const Vec<2> p = load<2>(x, i);
      for (int s = 0; s < seg.count; ++s) {
        const Vec<2> a = load<2>(seg.a, s), b = load<2>(seg.b, s);
        const double t = dot(p - a, b - a) / norm2(b - a);
        const double dn = dot(load<2>(seg.n_in, s), p - a);
        if (t >= 0 && t <= 1 && dn > -R && dn < R) Kokkos::atomic_increment(&count(seg.wall(s), dn >= 0 ? 0 : 1));
      }
    }
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
