#pragma once
// Host-side owner of the NFM walls: builds the facets and the quadrature points, from the
// scene's polylines in 2D (each segment cut into elements no longer than the quadrature
// spacing, dx/4 by default, independent of the segment length) and from its triangle meshes
// in 3D (each triangle's clipped quadrature, §4.4, at kWallQuadratureSpacing3D dx by
// default); moves them rigidly for translating or oscillating walls; and keeps a cell list of
// the quadrature points for the particle-wall sums and the facets binned by cell.
#include <string>
#include <vector>

#include "kernels/CellList.hpp"
#include "kernels/WallSet.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// The default spacing of the 3D wall quadrature, in dx (geometry/TriangleQuadrature.hpp).
constexpr double kWallQuadratureSpacing3D = 0.5;

// The wall quadrature's spacing for particles of spacing dx: the case's
// discretisation.wall_quadrature_spacing (m) or wall_quadrature_spacing_dx (times dx), or
// dx / 4 (2D) and kWallQuadratureSpacing3D dx (3D)
template <int D>
double wall_quadrature_spacing(const Scene& scene, double dx) {
  if (scene.wall_quadrature_spacing > 0) return scene.wall_quadrature_spacing;
  if (scene.wall_quadrature_spacing_dx > 0) return scene.wall_quadrature_spacing_dx * dx;
  return D == 2 ? dx / 4 : kWallQuadratureSpacing3D * dx;
}

template <int D>
class WallModel {
 public:
  WallModel() = default;
  // facet_cells false: the points and their cells only, for a refinement level's walls (the
  // facet queries read the base model's facet cells), so no host rebuild of facet cells runs
  // when the walls move
  // spacing: the quadrature points' spacing along the walls (m; wall_quadrature_spacing)
  WallModel(const Scene& scene, const PeriodicBox<D>& box, double cutoff, double spacing, bool facet_cells = true);

  bool empty() const { return points_.count == 0; }
  int wall_count() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  const WallFacets<D>& facets() const { return facets_; }
  const FacetCells<D>& facet_cells() const { return facet_cells_; }
  NearFacets<D> near_facets() const { return {facets_, facet_cells_}; }
  const WallPoints<D>& points() const { return points_; }
  const CellList<D>& cells() const { return cells_; }
  // rigid velocity of each wall at the last move_to (zero for fixed walls)
  const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& wall_velocity() const { return wall_velocity_; }
  // per wall: angular velocity (3) and centre of rotation (3), zero for walls that do not rotate
  const Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace>& wall_spin() const { return wall_spin_; }
  // Wall positions and velocities at time t (rigid motion of each wall).
  void move_to(double t);
  bool moving() const { return moving_; }

 private:
  std::vector<Wall> walls_;
  std::vector<std::string> names_;

 public:  // (device lambdas: not in a private member function)
  void place_points_and_facets(const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& disp,
                               const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& vel,
                               const Kokkos::View<double* [9], Kokkos::LayoutRight, MemSpace>& rot);

 private:
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> n_in0_, n_out0_;  // moving walls: the normals at rest
  Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace> wall_spin_;      // per wall: omega (3), centre (3)

  WallFacets<D> facets_;
  FacetCells<D> facet_cells_;
  std::vector<double> host_a_, host_b_, host_c_;  // the facets at rest, for the facet cells
  std::vector<int> host_facet_wall_;
  bool facets_moved_ = false;                      // the facet cells hold displaced facets
  WallPoints<D> points_;
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> seg_a0_, seg_b0_, seg_c0_, x0_, wall_velocity_;
  CellList<D> cells_;
  PeriodicBox<D> box_;
  double cutoff_ = 0;
  bool moving_ = false;
  bool with_facet_cells_ = true;
};

// The facet cells of facets at rest, for a cut-off (tests and tools; WallModel keeps its own).
template <int D>
FacetCells<D> make_facet_cells(const PeriodicBox<D>& box, double cutoff, const WallFacets<D>& facets);

extern template class WallModel<2>;
extern template class WallModel<3>;

}  // namespace ondine
