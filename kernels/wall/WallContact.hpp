#pragma once
// The fluid's contact with the wall at each wall quadrature point q (not in the seeds):
//   theta_q = min(1, sum_j V_j W(x_q - x_j) / gamma_q),
// the kernel-weighted volume of the fluid around q over the wall geometry's own Shepard factor
// there (gamma_q: 1/2 on a flat wall, (4.60)-(4.82) at x_q moved 1e-6 R into the fluid). It is 1
// where the fluid fills the wall's side of the support (a lattice in contact: within a few per
// cent of 1), and falls to 0 as a free surface backs away from q across a gap of R.
// With scheme.wall_contact the wall's acoustic terms, the impedance rho c u_n of the normal
// flux (4.14) and the continuity term (4.25), read theta_q u_n in place of u_n: water that
// moves towards a wall across an air gap within R of it is not stopped, nor compressed, by the
// wall before it reaches it (docs/validation.md, "The triangular water column").
#include "kernels/NeighbourLoops.hpp"
#include "kernels/WallFacet.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

template <int D, class Kernel>
struct WallContactPass {
  WallPoints<D> wall;
  CellList<D> cells;  // the particles' cell list
  WallFacets<D> facets;
  FacetCells<D> facet_cells;
  PeriodicBox<D> box;
  Kernel W;
  double R;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  Kokkos::View<double*, MemSpace> theta;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    const Vec<D> xq = load<D>(wall.x, q), n = load<D>(wall.n_out, q);
    const Vec<D> inside = xq + (-1e-6 * R) * n;
    double g = 0.0;
    for_each_facet_near<D>(facet_cells, box, inside, [&](const int s, const Vec<D>& xs) { g += facet_gamma<D>(xs, facets(s), R); });
    g = shepard_gamma_from_sum(g);
    double sw = 0.0;
    for_each_point_within<D>(cells, box, x, xq, R * R, [&](const int j, const Vec<D>&, const double r) { sw += m(j) / rho(j) * W.value(r); });
    const double t = g > 1e-3 ? sw / g : 1.0;
    theta(q) = t < 1.0 ? t : 1.0;
  }
};

}  // namespace ondine
