#pragma once
// Renormalised density gradient (thesis 2.42-2.44), read by the delta-SPH term:
//   M_i = sum_j w_j (x_j - x_i) (x) grad_i W_ij,  <grad rho>_i = M_i^{-T} sum_j w_j (rho_j - rho_i) grad_i W_ij.
// Where M_i is singular (an isolated particle) the gradient is left unrenormalised.
#include "kernels/NeighbourLoops.hpp"

namespace ondine {

template <int D, class Kernel>
struct DensityGradientPass {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const double rho_i = rho(i);
    Mat<D> M = Mat<D>::zero();
    Vec<D> g = Vec<D>::zero();
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double rho_j = rho(j);
      const double w = m(j) / rho_j;
      const Vec<D> gradW = (W.derivative(r) / r) * xij;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) M.a[a][b] -= w * xij[a] * gradW[b];  // (x_j - x_i) = -x_ij
      g += (w * (rho_j - rho_i)) * gradW;
    });
    Mat<D> B;
    if (invert(M, B, 1e-12)) {
      Vec<D> r;
      for (int a = 0; a < D; ++a) {
        r[a] = 0.0;
        for (int b = 0; b < D; ++b) r[a] += B.a[b][a] * g[b];  // B^T g
      }
      g = r;
    }
    store<D>(grad_rho, i, g);
  }

  void run(int n) const {
    Kokkos::parallel_for("ondine::DensityGradient", Kokkos::RangePolicy<ExecSpace>(0, n), *this);
  }
};

}  // namespace ondine
