#pragma once
// Device view of the NFM walls (thesis chapter 4): the facets, segments (2D) or triangles
// (3D), for the analytical Shepard factor (4.52-4.59, 4.60-4.82), the fill and the guards; the
// quadrature points of the wall integrals (4.20)-(4.25), each with its outward normal n_out
// (out of the fluid, nfm.md §0), its element length (2D) or area (3D) s_j and the wall
// velocity there; and the facets binned by cell.
#include "kernels/CellList.hpp"
#include "kernels/Fields.hpp"
#include "kernels/PeriodicBox.hpp"
#include "kernels/WallFacet.hpp"

namespace ondine {

// The facets: segments [a, b] (2D) or triangles (a, b, c) (3D), each with n_in and its wall.
template <int D>
struct WallFacets {
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> a, b, c, n_in;  // c: 3D only
  Kokkos::View<int*, MemSpace> wall;
  int count = 0;

  KOKKOS_INLINE_FUNCTION Facet<D> operator()(const int s) const {
    Facet<D> f;
    f.a = load<D>(a, s);
    f.b = load<D>(b, s);
    if constexpr (D == 3) f.c = load<D>(c, s);
    f.n_in = load<D>(n_in, s);
    return f;
  }
};

template <int D>
struct WallPoints {
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> x, n_out, u;
  Kokkos::View<double*, MemSpace> s;
  Kokkos::View<int*, MemSpace> wall;
  Kokkos::View<int*, MemSpace> no_slip;  // 1: no-slip (viscous wall term), 0: slip
  int count = 0;
};

// The facets near each cell of the particles' grid (cells no smaller than R): cell c lists
// every facet, or periodic image of a facet, that comes within R of a point of the cell
// (bounding boxes, so a superset), built once per wall motion (solver/WallModel.cpp). A
// particle visits the list of its own cell only, so its cost is that of the facets near it
// whatever the size of the mesh. Entry e is facet facet(e) seen from the particle shifted by
// image(e) periods (base-3 digits, one per axis: 0, 1, 2 for -1, 0, +1 periods); entries are
// ordered by image, then facet.
template <int D>
struct FacetCells {
  CellGrid<D> grid;
  Kokkos::View<int*, MemSpace> start;  // cells + 1
  Kokkos::View<int*, MemSpace> facet, image;
};

// f(s, x_s) for each facet s listed in the cell of x, x_s = x shifted to the facet's image.
template <int D, class F>
KOKKOS_INLINE_FUNCTION void for_each_facet_near(const FacetCells<D>& cells, const PeriodicBox<D>& box, const Vec<D>& x,
                                                F&& f) {
  int home[D];
  for (int k = 0; k < D; ++k) home[k] = cells.grid.coord(x[k], k);
  const int c = cells.grid.linear(home);
  for (int e = cells.start(c); e < cells.start(c + 1); ++e) {
    Vec<D> xs = x;
    for (int k = 0, code = cells.image(e); k < D; ++k, code /= 3) xs[k] += (code % 3 - 1) * box.len[k];
    f(cells.facet(e), xs);
  }
}

// The facets with the cells that find those near a point: what the refinement's wall
// clearances read (kernels/apr/), without visiting every facet of the mesh.
template <int D>
struct NearFacets {
  WallFacets<D> facets;
  FacetCells<D> cells;
};

// f(facet, x_s) for each facet near x whose span holds the projection of x_s (x moved into
// the facet's periodic image): the facets a point can be pushed against along their normal.
template <int D, class F>
KOKKOS_INLINE_FUNCTION void for_each_facet_over(const NearFacets<D>& w, const PeriodicBox<D>& box, const Vec<D>& x, F&& f) {
  if (w.facets.count == 0) return;
  for_each_facet_near<D>(w.cells, box, x, [&](const int s, const Vec<D>& xs) {
    const Facet<D> fs = w.facets(s);
    if (facet_spans<D>(xs, fs)) f(fs, xs);
  });
}

// gamma_i = 1 + sum of the facets' terms (2D 4.52-4.55, 3D 4.80-4.82) over the facets near
// particle i; clipped to [1e-3, 1] so that a particle pushed through a wall never divides by
// ~0. In a periodic axis the facets' images one period away are included too.
template <int D>
struct ShepardGammaPass {
  WallFacets<D> facets;
  FacetCells<D> cells;
  double R;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x;
  Kokkos::View<double*, MemSpace> gamma;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    double sum = 0.0;  // sum of the facets' terms; gamma from shepard_gamma_from_sum
    for_each_facet_near<D>(cells, box, load<D>(x, i), [&](const int s, const Vec<D>& xs) { sum += facet_gamma<D>(xs, facets(s), R); });
    const double g = shepard_gamma_from_sum(sum);
    gamma(i) = g < 1e-3 ? 1e-3 : (g > 1.0 ? 1.0 : g);
  }
};

}  // namespace ondine
