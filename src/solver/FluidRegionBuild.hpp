#pragma once
// The fluid region of the walls (kernels/FluidRegion.hpp): the facets, and the closed walls
// as facet ranges with the side the fluid is on (a host loop over the walls).
#include <string>
#include <vector>

#include "kernels/FluidRegion.hpp"
#include "scene/Scene.hpp"
#include "solver/WallModel.hpp"

namespace ondine {

template <int D>
FluidRegion<D> fluid_region(const Scene& scene, const WallModel<D>& walls, const PeriodicBox<D>& box) {
  FluidRegion<D> region;
  region.facets = walls.facets();
  region.cells = walls.facet_cells();
  region.box = box;
  region.behind = scene.dx;
  std::vector<int> first, count, inside;
  int s0 = 0;
  for (const Wall& w : scene.walls) {
    const int ns = static_cast<int>(D == 3 ? w.mesh.triangles.size() : (w.closed ? w.points.size() : w.points.size() - 1));
    if (w.closed) {
      first.push_back(s0);
      count.push_back(ns);
      inside.push_back(w.fluid_inside ? 1 : 0);
    }
    s0 += ns;
  }
  auto dev = [](const std::vector<int>& v, const std::string& label) {
    Kokkos::View<int*, MemSpace> d(label, v.size());
    Kokkos::deep_copy(d, Kokkos::View<const int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(v.data(), v.size()));
    return d;
  };
  region.closed.first = dev(first, "ondine::NFM::closed_first");
  region.closed.count = dev(count, "ondine::NFM::closed_count");
  region.closed.fluid_inside = dev(inside, "ondine::NFM::closed_inside");
  region.closed.walls = static_cast<int>(first.size());
  return region;
}

}  // namespace ondine
