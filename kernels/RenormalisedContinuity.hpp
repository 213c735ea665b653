#pragma once
// Renormalised continuity (scheme.renormalised_continuity): the divergence of the
// continuity equation (4.23)/(4.25) taken as the trace of the renormalised velocity
// gradient (2.42)-(2.44), with the NFM wall terms of (4.86) in the matrix:
//   M_i = sum_P w_j (x_j - x_i) (x) grad_i W_ij + sum_S s_q W_iq (x_q - x_i) (x) n_out,
//   G_i = sum_P w_j (u_j - u_i) (x) grad_i W_ij + sum_S s_q W_iq [u_q - u_i] (x) n_out,
// with [u_q - u_i] the whole jump at a no-slip wall point and its normal part at a slip one
// (where the fluid's tangential velocity is not the wall's; the plain (4.25) reads u.n only),
//   drho_i/dt = -rho_i tr(G_i M_i^{-1})          instead of  -rho_i tr(G_i) / gamma_i.
// M_i -> gamma_i I where the support is cut only by walls (continuum), so the two agree in
// the bulk and next to a wall; where a free surface cuts the support M_i is not gamma_i I
// and the plain divergence of a linear velocity field is wrong by O(|grad u|) in a layer R
// thick (a particle at depth d: M_nn = gamma_i - d sum_FS W). At a large sound speed the
// discrete continuity is then held to that wrong divergence: at a real sound speed the
// dam-break surge tip comes out blunter and slower; the delta-SPH term (delta c0 R), which lets
// the density relax over the flow time at c0 = 15 m/s, no longer does at c0 = 1480
// (docs/validation.md, "Design choices in the kernels, measured").
// Not in the seed for the continuity equation: (2.42)-(2.44) and (4.86) are used there for
// gradients and the free-surface normal. The renormalised divergence is exact for linear
// fields whatever cuts the support, but no longer the exact adjoint of the pressure gradient
// G_+ (2.51)-(2.57), so energy is not conserved to round-off by the pair.
// Where M_i is far from gamma_i I (det(M_i / gamma_i) <= min_det = 0.5: spray, a filament, the
// corner where a free surface meets a wall) the plain divergence is kept: there B_i = M_i^{-1}
// amplifies the gap between the two operators, and as the renormalised divergence is not the
// adjoint of the pressure gradient the acoustic system can then gain energy at a rate that
// grows with c0 (a smaller min_det blew the dam break up at c0 = 1480 m/s: docs/validation.md,
// "Design choices in the kernels, measured").
// Run after the flux and wall passes, which have already added -rho_i tr(G_i)/gamma_i to
// drho_i; this pass adds the difference (one more neighbour loop, only in scenes that ask).
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

template <int D, class Kernel, bool Walls>
struct RenormalisedContinuity {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  WallPoints<D> wall;  // Walls only
  CellList<D> wall_cells;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::ShepardGamma, D> gamma;  // Walls only
  field_view_t<field::DensityRate, D> drho;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    VelocityGradientSum<D> S;
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      S.add(m(j) / rho(j), xij, (W.derivative(r) / r) * xij, load<D>(u, j) - ui);
    });
    double g = 1.0;
    if constexpr (Walls) {
      for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
        const Vec<D> n = load<D>(wall.n_out, q);
        Vec<D> jump = load<D>(wall.u, q) - ui;
        if (!wall.no_slip(q)) jump = dot(jump, n) * n;  // a slip wall fixes only u.n (4.14)
        S.add(wall.s(q) * W.value(r), xiq, n, jump);
      });
      g = gamma(i);
    }
    constexpr double min_det = 0.5;  // det(M_i / gamma_i) below which the plain divergence is kept
    double scale = 1.0;  // gamma^D
    for (int k = 0; k < D; ++k) scale *= g;
    if (!(determinant(S.M) > min_det * scale)) return;
    Mat<D> B;
    if (!invert(S.M, B, 1e-12)) return;
    const Mat<D> grad_u = S.gradient(B);
    double plain = 0.0, renormalised = 0.0;
    for (int a = 0; a < D; ++a) {
      plain += S.G.a[a][a];
      renormalised += grad_u.a[a][a];
    }
    drho(i) += rho(i) * (plain / g - renormalised);
  }

  void run(int n) const {
    Kokkos::parallel_for("ondine::RenormalisedContinuity", Kokkos::RangePolicy<ExecSpace>(0, n), *this);
  }
};

}  // namespace ondine
