#pragma once
// Guard interpolation of APR (thesis 5.24; 5.23 is the same operator on a mother):
// each guard i of level r takes its fields from the SPH particles j of every level
// in its Lx row, with its level's radius R_r,
//   <phi>_i = sum_j w_j phi_j W(x_ij, R_r) / sum_k w_k W(x_ik, R_r),  w_j = m_j / rho_j.
// Design choice (docs/apr.md): Shepard's estimate reproduces constants only, so a
// guard between a coarse and a fine region (unequal one-sided weights) gets an
// O(dx grad phi) error. We add the first-order moment correction (moving least
// squares of degree 1 with the weights w_j W_ij): with d_j = x_j - x_i,
//   m0 = sum w W, m1 = sum w W d, M2 = sum w W d d^T, f0 = sum w W phi, f1 = sum w W phi d,
//   phi_i = (f0 - m1^T M2^{-1} f1) / (m0 - m1^T M2^{-1} m1),
// exact for linear fields wherever M2 is invertible. Where the support is
// strongly one-sided (the corrected denominator below a quarter of m0: near a
// free surface, where the extrapolation is not robust) the plain Shepard value
// (5.24) is used, as in the thesis. Guards with no source keep their fields.
// The same fit gives the guard's density gradient, b = M2^{-1} (f1 - m1 rho_i),
// read by delta-SPH and the walls of its SPH neighbours (the SPH particles' own
// gradient is the renormalised one, 2.42-2.44); zero where M2 is singular.
#include "kernels/NeighbourList.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

// Interpolated: the velocity and density, and the density gradient when the scene
// has one (grad_rho allocated).
template <int D, class UnitKernel>
struct GuardInterpolation {
  static constexpr int NF = D + 1;
  NeighbourList<D> lx;
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  UnitKernel W1;  // the scene's kernel at R = 1: W(r, R) = W1(r / R) / R^D
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;
  field_view_t<field::AprBirthLevel, D> birth;

  KOKKOS_INLINE_FUNCTION double source(const int j, const int c) const {
    return c < D ? u(j, c) : rho(j);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const int nn = lx.num_neighbours(i);
    if (nn == 0) return;  // an SPH particle (no Lx row) or a guard without sources
    const double R = zones.R[birth(i)];
    const double inv_R = 1.0 / R;
    const Vec<D> xi = load<D>(x, i);
    double m0 = 0.0;
    Vec<D> m1 = Vec<D>::zero();
    Mat<D> M2 = Mat<D>::zero();
    double f0[NF];
    Vec<D> f1[NF];
    for (int c = 0; c < NF; ++c) {
      f0[c] = 0.0;
      f1[c] = Vec<D>::zero();
    }
    for (int n = 0; n < nn; ++n) {
      const int j = lx.neighbour(i, n);
      const Vec<D> d = box.delta(load<D>(x, j), xi);  // x_j - x_i
      const double r = kmath::sqrt(norm2(d));
      if (r >= R) continue;  // in the skin
      const double w = m(j) / rho(j) * W1.value(r * inv_R);  // the 1/R^D factor cancels
      m0 += w;
      m1 += w * d;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) M2.a[a][b] += w * d[a] * d[b];
      for (int c = 0; c < NF; ++c) {
        const double phi = source(j, c);
        f0[c] += w * phi;
        f1[c] += (w * phi) * d;
      }
    }
    if (!(m0 > 0.0)) return;
    Mat<D> B;
    double tiny = 1e-12;
    for (int a = 0; a < D; ++a) tiny *= m0 * R * R;
    bool corrected = invert(M2, B, tiny);
    Vec<D> Bm1 = Vec<D>::zero();
    double denom = m0;
    if (corrected) {
      Bm1 = B * m1;
      denom = m0 - dot(m1, Bm1);
      corrected = denom > 0.25 * m0;
    }
    for (int c = 0; c < NF; ++c) {
      // (f0 - m1^T B f1) / denom, with m1^T B f1 = (B m1) . f1 (M2 symmetric)
      const double v = corrected ? (f0[c] - dot(Bm1, f1[c])) / denom : f0[c] / m0;
      if (c < D) u(i, c) = v;
      else rho(i) = v;
    }
    if (grad_rho.data() != nullptr) {
      Vec<D> g = Vec<D>::zero();
      if (invert(M2, B, tiny)) g = B * (f1[D] - rho(i) * m1);
      store<D>(grad_rho, i, g);
    }
  }
};

}  // namespace apr

}  // namespace ondine
