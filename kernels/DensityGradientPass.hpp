#pragma once
// Renormalised density gradient (thesis 2.42-2.44), read by the delta-SPH term
// and by the MUSCL wall state (4.30):
//   M_i = sum_j w_j (x_j - x_i) (x) grad_i W_ij,  <grad rho>_i = M_i^{-T} sum_j w_j (rho_j - rho_i) grad_i W_ij.
// Where M_i is singular (an isolated particle) the gradient is left unrenormalised.
// With Velocity (Riemann-SPH's MUSCL reconstruction, 2.78), the same loop also gathers the
// renormalised velocity gradient <grad u>_i = G_i M_i^{-1} (kernels/VelocityGradientSum.hpp).
// Exact for linear fields whatever the support (a wall or a free surface cuts it),
// which is why no wall integral is needed here.
//
// In viscous scenes with no-slip NFM walls (ConsistentLaplacian), the same neighbour
// loop, and a loop over the no-slip wall points within R, also gather the moment
// system of the consistent Laplacian's weights (kernels/ConsistentLaplacian.hpp) and
// solve it per particle into a scratch array of the evaluation (not a particle field).
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

// What the consistent Laplacian's moment system needs, and where its weights go.
template <int D>
struct LaplacianWeights {
  WallPoints<D> wall;
  CellList<D> wall_cells;
  double min_dn = 0;  // the |d_n| floor of the NFM wall term (4.85)
  double kappa = 1;   // fallback A = kappa I (kernels/MorrisLatticeFactor.hpp)
  field_view_t<field::ShepardGamma, D> gamma;
  LaplacianWeightView<D> weights;  // (A_i, b_i) per particle
};

template <int D, class Kernel, bool ConsistentLaplacian = false, bool Velocity = false>
struct DensityGradientPass {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;
  LaplacianWeights<D> lap = {};  // ConsistentLaplacian only
  field_view_t<field::Velocity, D> u;  // Velocity only
  VelocityGradientRows<D> grad_u;      // Velocity only

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const double rho_i = rho(i);
    Mat<D> M = Mat<D>::zero();
    Vec<D> g = Vec<D>::zero();
    using Basis = LaplacianBasis<D>;
    constexpr int K = Basis::K;
    double moments[K][K];  // sum c psi psi^T / r^2 (kernels/ConsistentLaplacian.hpp)
    double shepard = 0.0;
    double r_min = 1e300;  // the nearest pair or no-slip wall point (the weights' bounds)
    VelocityGradientSum<D> vel;  // Velocity: its G = sum_j w_j (u_j - u_i) (x) grad_i W_ij (M is the pass's own)
    Vec<D> ui;
    if constexpr (Velocity) ui = load<D>(u, i);
    if constexpr (ConsistentLaplacian) {
      for (int p = 0; p < K; ++p)
        for (int q = 0; q < K; ++q) moments[p][q] = 0.0;
      shepard = m(i) / rho_i * W.value(0.0);
    }
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double rho_j = rho(j);
      const double w = m(j) / rho_j;
      const double dWdr = W.derivative(r);
      const Vec<D> gradW = (dWdr / r) * xij;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) M.a[a][b] -= w * xij[a] * gradW[b];  // (x_j - x_i) = -x_ij
      g += (w * (rho_j - rho_i)) * gradW;
      if constexpr (Velocity) {
        const Vec<D> du = load<D>(u, j) - ui;
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) vel.G.a[a][b] += w * du[a] * gradW[b];
      }
      if constexpr (ConsistentLaplacian) {
        Basis::accumulate(moments, w * (rho_i + rho_j) / rho_i * dWdr / r / (r * r), xij);
        shepard += w * W.value(r);
        if (r < r_min) r_min = r;
      }
    });
    Mat<D> B;
    if (invert(M, B, 1e-12)) {
      Vec<D> r;
      for (int a = 0; a < D; ++a) {
        r[a] = 0.0;
        for (int b = 0; b < D; ++b) r[a] += B.a[b][a] * g[b];  // B^T g
      }
      g = r;
      if constexpr (Velocity) vel.G = vel.gradient(B);  // G B: row a is the gradient of u_a
    }
    store<D>(grad_rho, i, g);
    if constexpr (Velocity) grad_u.store(i, vel.G);
    if constexpr (ConsistentLaplacian) {
      // the no-slip wall points (4.85): k_q = 2 s_q W / d_n, the wall velocity as f_q
      int first = -1;
      bool smooth_wall_data = true;  // one wall velocity over the support (not a lid corner)
      for_each_point_within<D>(lap.wall_cells, box, lap.wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
        if (!lap.wall.no_slip(q)) return;
        const double k = 2.0 * lap.wall.s(q) * W.value(r) / fluid_side_dn<D>(xiq, load<D>(lap.wall.n_out, q), lap.min_dn);
        Basis::accumulate(moments, k / (r * r), xiq);
        if (r < r_min) r_min = r;
        if (first < 0) first = q;
        else if (norm2(load<D>(lap.wall.u, q) - load<D>(lap.wall.u, first)) > 0.0) smooth_wall_data = false;
      });
      // a support cut by a free surface, or meeting walls that move relative to each other
      // (the velocity jump at a lid corner), keeps the plain operator (ConsistentLaplacian.hpp)
      const double gamma_i = lap.gamma(i);
      if (Basis::solve(moments, shepard >= 0.9 * gamma_i && smooth_wall_data, lap.kappa, gamma_i, lap.weights, i)) {
        // within [0, max_weight kappa] on every pair and no-slip wall point, or the plain
        // operator (ConsistentLaplacian.hpp); checked pair by pair only where the bound over
        // all directions at the nearest distance does not already hold
        const double s_max = LaplacianBasis<D>::max_weight * lap.kappa;
        if (Basis::within_bounds(lap.weights, i, r_min, s_max)) return;
        bool bounded = true;
        const auto within = [&](const Vec<D>& xr) {
          const double s = Basis::weight(lap.weights, i, xr);
          return s >= 0.0 && s <= s_max;
        };
        for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int, const Vec<D>& xij, const double) {
          bounded = bounded && within(xij);
        });
        for_each_point_within<D>(lap.wall_cells, box, lap.wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double) {
          bounded = bounded && (!lap.wall.no_slip(q) || within(xiq));
        });
        if (!bounded) Basis::fall_back(lap.kappa, lap.weights, i);
      }
    }
  }

  void run(int n) const {
    Kokkos::parallel_for(ConsistentLaplacian ? "ondine::DensityGradient+consistent_laplacian" : "ondine::DensityGradient",
                         Kokkos::RangePolicy<ExecSpace>(0, n), *this);
  }
};

}  // namespace ondine
