#pragma once
// Renormalised density gradient (thesis 2.42-2.44), read by the delta-SPH term
// and by the MUSCL wall state (4.30):
//   M_i = sum_j w_j (x_j - x_i) (x) grad_i W_ij,  <grad rho>_i = M_i^{-T} sum_j w_j (rho_j - rho_i) grad_i W_ij.
// Where M_i is singular (an isolated particle) the gradient is left unrenormalised.
// Exact for linear fields whatever the support (a wall or a free surface cuts it),
// which is why the wall terms need no wall integral here.
//
// Scenes with walls also get, in the same neighbour loop (WallState), what the
// wall pass needs near a wall (kernels/WallFluxPass.hpp):
//  - the renormalised velocity gradient G_i (G_ab = du_a/dx_b), same M_i, for the
//    MUSCL reconstruction of the momentum at the wall point (4.30, phi = rho u);
//  - with Morris viscosity (LaplacianOfX), the fluid part of the Morris operator
//    applied to the coordinates, Lx_i = sum_j w_j (rho_i + rho_j)/rho_i W'(r)/r x_ij,
//    for the first-order consistency correction of the NFM Laplacian (4.85).
// They are scratch arrays of the evaluation (wall_state below), not particle fields.
#include "kernels/NeighbourLoops.hpp"

namespace ondine {

// Per-particle scratch of one evaluation, read by the wall pass of the same evaluation.
template <int D>
struct WallGradients {
  Kokkos::View<double* [D][D], Kokkos::LayoutLeft, MemSpace> grad_u;  // G_i(a, b) = du_a/dx_b
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> lap_x;      // fluid part of L_MEA(x)_i
};

template <int D, class Kernel, bool WallState = false, bool LaplacianOfX = false>
struct DensityGradientPass {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;
  field_view_t<field::Velocity, D> u = {};  // WallState only
  WallGradients<D> wall_state = {};

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const double rho_i = rho(i);
    Mat<D> M = Mat<D>::zero();
    Vec<D> g = Vec<D>::zero();
    Vec<D> gu[D];  // sum_j w_j (u_j,a - u_i,a) grad_i W_ij, one vector per component a
    Vec<D> lx = Vec<D>::zero();
    Vec<D> ui = Vec<D>::zero();
    if constexpr (WallState) {
      ui = load<D>(u, i);
      for (int a = 0; a < D; ++a) gu[a] = Vec<D>::zero();
    }
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double rho_j = rho(j);
      const double w = m(j) / rho_j;
      const double dWdr = W.derivative(r);
      const Vec<D> gradW = (dWdr / r) * xij;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) M.a[a][b] -= w * xij[a] * gradW[b];  // (x_j - x_i) = -x_ij
      g += (w * (rho_j - rho_i)) * gradW;
      if constexpr (WallState) {
        const Vec<D> uji = load<D>(u, j) - ui;
        for (int a = 0; a < D; ++a) gu[a] += (w * uji[a]) * gradW;
      }
      if constexpr (LaplacianOfX) lx += (w * (rho_i + rho_j) / rho_i * dWdr / r) * xij;
    });
    Mat<D> B;
    const bool renormalised = invert(M, B, 1e-12);
    store<D>(grad_rho, i, renormalised ? transpose_times(B, g) : g);
    if constexpr (WallState) {
      for (int a = 0; a < D; ++a) {
        const Vec<D> row = renormalised ? transpose_times(B, gu[a]) : gu[a];
        for (int b = 0; b < D; ++b) wall_state.grad_u(i, a, b) = row[b];
      }
    }
    if constexpr (LaplacianOfX) store<D>(wall_state.lap_x, i, lx);
  }

  // B^T v
  KOKKOS_INLINE_FUNCTION static Vec<D> transpose_times(const Mat<D>& B, const Vec<D>& v) {
    Vec<D> r;
    for (int a = 0; a < D; ++a) {
      r[a] = 0.0;
      for (int b = 0; b < D; ++b) r[a] += B.a[b][a] * v[b];
    }
    return r;
  }

  void run(int n) const {
    Kokkos::parallel_for(WallState ? "ondine::DensityGradient+wall_state" : "ondine::DensityGradient",
                         Kokkos::RangePolicy<ExecSpace>(0, n), *this);
  }
};

}  // namespace ondine
