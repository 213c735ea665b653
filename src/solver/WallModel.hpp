#pragma once
// Host-side owner of the NFM walls: builds the segments and the midpoint
// quadrature points from the scene's polylines (each segment cut into elements
// no longer than the quadrature spacing, dx/4 by default, independent of the
// segment length), moves them rigidly for translating or oscillating walls, and
// keeps a cell list of the quadrature points for the particle-wall sums.
#include <string>
#include <vector>

#include "kernels/CellList.hpp"
#include "kernels/WallSet.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D>
class WallModel {
 public:
  WallModel() = default;
  WallModel(const Scene& scene, const PeriodicBox<D>& box, double cutoff);

  bool empty() const { return points_.count == 0; }
  int wall_count() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  const WallSegments<D>& segments() const { return segments_; }
  const WallPoints<D>& points() const { return points_; }
  const CellList<D>& cells() const { return cells_; }
  // rigid velocity of each wall at the last move_to (zero for fixed walls)
  const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& wall_velocity() const { return wall_velocity_; }
  // Wall positions and velocities at time t (rigid motion of each wall).
  void move_to(double t);
  bool moving() const { return moving_; }

 private:
  std::vector<Wall> walls_;
  std::vector<std::string> names_;
  WallSegments<D> segments_;
  WallPoints<D> points_;
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> seg_a0_, seg_b0_, x0_, wall_velocity_;
  CellList<D> cells_;
  PeriodicBox<D> box_;
  double cutoff_ = 0;
  bool moving_ = false;
};

extern template class WallModel<2>;
extern template class WallModel<3>;

}  // namespace ondine
