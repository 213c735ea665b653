#pragma once
// Renormalised velocity gradient (thesis 2.42-2.44), gathered pair by pair:
//   M_i = sum_j w_j (x_j - x_i) (x) grad_i W_ij,  G_i = sum_j w_j (u_j - u_i) (x) grad_i W_ij,
//   <grad u>_i = G_i M_i^{-1}   (row a: the gradient of u_a).
// Read by the velocity's MUSCL state at NFM wall points (kernels/WallVelocityState.hpp)
// and by particle shifting's Taylor correction (kernels/ShiftingPass.hpp), which also
// needs M_i^{-1} for its density gradient and so inverts M itself.
#include "kernels/Fields.hpp"
#include "kernels/Math.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

// A gradient stored as particle fields, one row (the gradient of u_k) per field TX, TY, TZ
template <int D, class TX, class TY, class TZ>
struct GradientRows {
  field_view_t<TX, D> g0;
  field_view_t<TY, D> g1;
  field_view_t<TZ, D> g2;  // 3D only
  KOKKOS_INLINE_FUNCTION double operator()(int i, int k, int b) const { return k == 0 ? g0(i, b) : k == 1 ? g1(i, b) : g2(i, b); }
  KOKKOS_INLINE_FUNCTION Mat<D> load(int i) const {
    Mat<D> g;
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) g.a[a][b] = (*this)(i, a, b);
    return g;
  }
  KOKKOS_INLINE_FUNCTION void store(int i, const Mat<D>& g) const {
    for (int b = 0; b < D; ++b) {
      g0(i, b) = g.a[0][b];
      g1(i, b) = g.a[1][b];
      if constexpr (D == 3) g2(i, b) = g.a[2][b];
    }
  }
};

// <grad u>_i: written by DensityGradientPass for Riemann-SPH's MUSCL reconstruction
// (kernels/terms/RiemannLeduc.hpp)
template <int D>
using VelocityGradientRows = GradientRows<D, field::VelocityGradientX, field::VelocityGradientY, field::VelocityGradientZ>;

template <int D>
struct VelocityGradientSum {
  Mat<D> M = Mat<D>::zero();  // sum_j w_j (x_j - x_i) (x) grad_i W_ij
  Mat<D> G = Mat<D>::zero();  // sum_j w_j (u_j - u_i) (x) grad_i W_ij

  // xij = x_i - x_j; any constant factor of grad W cancels in the renormalisation
  KOKKOS_INLINE_FUNCTION void add(const double w, const Vec<D>& xij, const Vec<D>& gradW, const Vec<D>& du) {
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) {
        M.a[a][b] -= w * xij[a] * gradW[b];
        G.a[a][b] += w * du[a] * gradW[b];
      }
  }

  // G B, with B = M^{-1} (or the caller's fallback where M is singular)
  KOKKOS_INLINE_FUNCTION Mat<D> gradient(const Mat<D>& B) const {
    Mat<D> out = Mat<D>::zero();
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b)
        for (int c = 0; c < D; ++c) out.a[a][b] += G.a[a][c] * B.a[c][b];
    return out;
  }

  // <grad u>_i; zero where M_i is singular (an isolated particle)
  KOKKOS_INLINE_FUNCTION Mat<D> gradient() const {
    Mat<D> B;
    if (!invert(M, B, 1e-12)) return Mat<D>::zero();
    return gradient(B);
  }
};

}  // namespace ondine
