#pragma once
// Host-side builders of the device lookup of a decomposition (kernels/OrbLookup.hpp).
#include "kernels/OrbLookup.hpp"
#include "parallel/Decomposition.hpp"

namespace ondine {

// Device copy of a decomposition over `grid`.
template <int D>
OrbLookup<D> make_orb_lookup(const Decomposition& d, const CellGrid<D>& grid) {
  OrbLookup<D> o;
  o.grid = grid;
  const auto& nodes = d.nodes();
  o.nodes = Kokkos::View<OrbNode*, MemSpace>("ondine::Decomposition::nodes", nodes.empty() ? 1 : nodes.size());
  auto hn = Kokkos::create_mirror_view(o.nodes);
  if (nodes.empty()) hn(0) = OrbNode{-1, 0, 0, 0};
  for (std::size_t k = 0; k < nodes.size(); ++k) hn(k) = nodes[k];
  Kokkos::deep_copy(o.nodes, hn);
  const int p = d.ranks() > 0 ? d.ranks() : 1;
  o.boxes = Kokkos::View<int* [6], Kokkos::LayoutRight, MemSpace>("ondine::Decomposition::boxes", p);
  auto hb = Kokkos::create_mirror_view(o.boxes);
  for (int r = 0; r < p; ++r)
    for (int k = 0; k < 3; ++k) {
      hb(r, k) = d.ranks() > 0 ? d.box(r).lo[k] : 0;
      hb(r, 3 + k) = d.ranks() > 0 ? d.box(r).hi[k] : (k < D ? grid.n[k] : 1);
    }
  Kokkos::deep_copy(o.boxes, hb);
  return o;
}

// The cell grid a rank builds its neighbour lists on: its own cells plus the ring
// of halo cells, non-periodic, except along axes its subdomain spans whole,
// where it keeps the global grid (and its periodicity). Cells align with the
// global grid's.
template <int D>
CellGrid<D> local_cell_grid(const CellGrid<D>& global, const CellBox& b) {
  CellGrid<D> g = global;
  for (int k = 0; k < D; ++k) {
    if (b.lo[k] == 0 && b.hi[k] == global.n[k]) continue;
    const double size = 1.0 / global.inv_size[k];
    g.lo[k] = global.lo[k] + (b.lo[k] - 1) * size;
    g.n[k] = b.hi[k] - b.lo[k] + 2;
    g.periodic[k] = false;
  }
  return g;
}

}  // namespace ondine
