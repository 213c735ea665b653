#pragma once
// The fluid blocks' half-space cuts (fluid_blocks[i].cut) on the device: block b's
// cuts are rows [first(b), first(b + 1)) of `cut`, each (point, normal out of the
// fluid), with the margin a lattice point of the fill may lie beyond it (zero, or with
// refinement zones the reach of a coarse point's finest descendants, so that the
// levels' lattices are cut at their own spacing: AdaptiveRefinement::trim_to_cuts).
#include "kernels/Fields.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

template <int D>
struct FillCuts {
  Kokkos::View<int*, MemSpace> first;  // blocks + 1
  Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace> cut;
  Kokkos::View<double*, MemSpace> margin;  // per cut, m
  Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace> box;  // per block: min, max (3 each)

  KOKKOS_INLINE_FUNCTION int blocks() const { return static_cast<int>(box.extent(0)); }

  // p on the fluid side of every cut of block b, or no farther beyond one than its margin
  // (with_margin)
  KOKKOS_INLINE_FUNCTION bool inside(const int b, const Vec<D>& p, const bool with_margin) const {
    for (int c = first(b); c < first(b + 1); ++c) {
      double side = 0;
      for (int k = 0; k < D; ++k) side += (p[k] - cut(c, k)) * cut(c, 3 + k);
      if (side > (with_margin ? margin(c) : 0.0)) return false;
    }
    return true;
  }

  // the first block whose box holds p, -1 if none
  KOKKOS_INLINE_FUNCTION int block_of(const Vec<D>& p) const {
    for (int b = 0; b < blocks(); ++b) {
      bool in = true;
      for (int k = 0; k < D; ++k) in = in && p[k] >= box(b, k) && p[k] <= box(b, 3 + k);
      if (in) return b;
    }
    return -1;
  }
};

}  // namespace ondine
