#pragma once
// The fluid blocks' half-space cuts of a scene on the device (kernels/FillCuts.hpp).
#include <cmath>

#include "kernels/FillCuts.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// The fluid blocks' cuts on the device. With refinement zones a lattice point may lie beyond
// a cut by the reach of its finest descendants, (dx/2)(1 - 2^-L) sum_k |n_k| with L levels
// below the coarse one: its daughters are then cut at their own spacing
// (AdaptiveRefinement::trim_to_cuts).
template <int D>
FillCuts<D> fill_cuts(const Scene& scene) {
  const int nb = static_cast<int>(scene.blocks.size());
  int ncut = 0;
  for (const FluidBlock& blk : scene.blocks) ncut += static_cast<int>(blk.cuts.size());
  FillCuts<D> f;
  f.first = Kokkos::View<int*, MemSpace>("ondine::Fill::cut_first", nb + 1);
  f.cut = Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace>("ondine::Fill::cut", ncut);
  f.margin = Kokkos::View<double*, MemSpace>("ondine::Fill::cut_margin", ncut);
  f.box = Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace>("ondine::Fill::block_box", nb);
  auto hf = Kokkos::create_mirror_view(f.first);
  auto hcut = Kokkos::create_mirror_view(f.cut);
  auto hm = Kokkos::create_mirror_view(f.margin);
  auto hb = Kokkos::create_mirror_view(f.box);
  const double reach = 0.5 * scene.dx * (1.0 - std::ldexp(1.0, -scene.max_refinement_level()));
  int c = 0;
  for (int b = 0; b < nb; ++b) {
    hf(b) = c;
    for (int a = 0; a < 3; ++a) {
      hb(b, a) = scene.blocks[b].box.min[a];
      hb(b, 3 + a) = scene.blocks[b].box.max[a];
    }
    for (const FluidBlock::Cut& k : scene.blocks[b].cuts) {
      double spread = 0;
      for (int a = 0; a < 3; ++a) {
        hcut(c, a) = k.point[a];
        hcut(c, 3 + a) = k.normal[a];
        if (a < D) spread += std::fabs(k.normal[a]);
      }
      hm(c) = reach * spread;
      ++c;
    }
  }
  hf(nb) = c;
  Kokkos::deep_copy(f.first, hf);
  Kokkos::deep_copy(f.cut, hcut);
  Kokkos::deep_copy(f.margin, hm);
  Kokkos::deep_copy(f.box, hb);
  return f;
}

}  // namespace ondine
