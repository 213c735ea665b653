#pragma once
// Renormalised velocity gradient (thesis 2.42-2.44), gathered pair by pair:
//   M_i = sum_j w_j (x_j - x_i) (x) grad_i W_ij,  G_i = sum_j w_j (u_j - u_i) (x) grad_i W_ij,
//   <grad u>_i = G_i M_i^{-1}   (row a: the gradient of u_a).
// Read by the velocity's MUSCL state at NFM wall points (kernels/WallVelocityState.hpp)
// and by particle shifting's Taylor correction (kernels/ShiftingPass.hpp), which also
// needs M_i^{-1} for its density gradient and so inverts M itself.
#include "kernels/Math.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

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
