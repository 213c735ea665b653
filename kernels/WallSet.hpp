#pragma once
// Device view of the NFM walls (thesis chapter 4), 2D: the segments (for the
// analytical Shepard factor, 4.52-4.59) and the midpoint quadrature points of
// the wall integrals (4.20)-(4.25), each with its outward normal n_out (out of
// the fluid, nfm.md §0), its length s_j and the wall velocity there.
#include "kernels/Fields.hpp"
#include "kernels/PeriodicBox.hpp"
#include "kernels/ShepardGamma2D.hpp"

namespace ondine {

template <int D>
struct WallSegments {
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> a, b, n_in;
  Kokkos::View<int*, MemSpace> wall;
  int count = 0;
};

template <int D>
struct WallPoints {
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> x, n_out, u;
  Kokkos::View<double*, MemSpace> s;
  Kokkos::View<int*, MemSpace> wall;
  Kokkos::View<int*, MemSpace> no_slip;  // 1: no-slip (viscous wall term), 0: slip
  int count = 0;
};

// gamma_i = 1 + sum_s gamma_s over the segments within R (4.52); clipped to
// [1e-3, 1] so that a particle pushed through a wall never divides by ~0.
// In a periodic axis the segments' images one period away are included too.
// Every segment is visited for every particle: fine for the tens to hundreds of
// segments of the cases here; a cell binning of segments is the next step for
// large wall meshes.
template <int D>
struct ShepardGammaPass {
  WallSegments<D> seg;
  double R;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x;
  Kokkos::View<double*, MemSpace> gamma;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    double g = 0.0;  // sum of gamma_s (4.55); gamma from shepard_gamma_from_sum
    if constexpr (D == 2) {
      const int sx = box.periodic[0] ? 1 : 0, sy = box.periodic[1] ? 1 : 0;
      for (int ox = -sx; ox <= sx; ++ox)
        for (int oy = -sy; oy <= sy; ++oy) {
          Vec<D> xs = xi;
          xs[0] += ox * box.len[0];
          xs[1] += oy * box.len[1];
          for (int s = 0; s < seg.count; ++s)
            g += shepard_gamma_segment(xs, load<D>(seg.a, s), load<D>(seg.b, s), load<D>(seg.n_in, s), R);
        }
    }
    if constexpr (D == 2) g = shepard_gamma_from_sum(g);
    else g = 1.0;
    gamma(i) = g < 1e-3 ? 1e-3 : (g > 1.0 ? 1.0 : g);
  }
  void run(int n) const {
    Kokkos::parallel_for("ondine::NFM::shepard_gamma", Kokkos::RangePolicy<ExecSpace>(0, n), *this);
  }
};

}  // namespace ondine
