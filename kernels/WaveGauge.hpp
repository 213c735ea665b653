#pragma once
// Wave gauges: the Shepard sum S(y) = sum_j m_j / rho_j W(|y - x_j|) (thesis
// 2.40) at points y spaced along a vertical line, from the particle cell list;
// the free-surface elevation is where S falls through 1/2 (the value of a
// half-filled support), the highest such level on the line. Only the particles
// a rank owns count (halos would be counted twice over the ranks).
// With refinement zones (Levels = true) only the SPH particles count, each with its
// own level's radius, as for the probes and wall forces (a mother guard and its
// daughters would count the same water twice); Kernel is then the kernel at R = 1.
#include "kernels/NeighbourLoops.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

template <int D, class Kernel, bool Levels = false>
struct GaugeShepardSum {
  CellList<D> cells;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  int owned;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> points;
  Kokkos::View<double*, MemSpace> sum;
  RefinementZones<D> zones = {};  // Levels only (R2: the coarsest level's)
  field_view_t<field::AprBirthLevel, D> birth = {};
  field_view_t<field::AprGuard, D> guard = {};

  KOKKOS_INLINE_FUNCTION void operator()(const int s) const {
    const Vec<D> xs = load<D>(points, s);
    double acc = 0.0;
    for_each_point_within<D>(cells, box, x, xs, R2, [&](const int j, const Vec<D>&, const double r) {
      if (j >= owned) return;
      if constexpr (Levels) {
        if (!guard(j)) acc += m(j) / rho(j) * level_kernel<D>(zones, W, birth(j), r);
      } else {
        acc += m(j) / rho(j) * W.value(r);
      }
    });
    sum(s) = acc;
  }
};

// The elevation where the Shepard sum, sampled at heights z_0 < z_1 < ..., last
// falls through 1/2 going up (linear between samples): the top of the line if the
// sum is still >= 1/2 there, z_0 if it never reaches 1/2.
inline double gauge_level(const double* z, const double* shepard, int n) {
  if (n > 0 && shepard[n - 1] >= 0.5) return z[n - 1];
  for (int k = n - 1; k > 0; --k)
    if (shepard[k - 1] >= 0.5 && shepard[k] < 0.5)
      return z[k - 1] + (shepard[k - 1] - 0.5) / (shepard[k - 1] - shepard[k]) * (z[k] - z[k - 1]);
  return z[0];
}

}  // namespace ondine
