#pragma once
// Guard interpolation of APR (thesis 5.24; 5.23 is the same operator on a mother):
// each guard i of level r takes its fields from the SPH particles j of every level
// in its Lx row, with its level's radius R_r,
//   <phi>_i = sum_j w_j phi_j W(x_ij, R_r) / sum_k w_k W(x_ik, R_r),  w_j = m_j / rho_j.
// Design choice (docs/apr.md): Shepard's estimate reproduces constants only. A
// guard between a coarse and a fine region (unequal one-sided weights) gets an
// O(R grad phi) error, and even a centred support smooths: O(R^2 phi'') (0.07 R^2
// phi'' with Wendland C2). Guards are the boundary condition of each level, and
// the two levels overlap by about R only, so such an error is amplified several
// times in the solution (Poiseuille flow: a 1.3 % velocity error with linear
// reconstruction, docs/apr.md). We therefore use moving least squares with the
// weights w_j W_ij, of degree 2 where the support allows it:
//   minimise sum_j w_j W_ij (phi_j - a . p(d_j))^2,  p(d) = (1, d, d_a d_b)/R powers, d_j = x_j - x_i,
//   phi_i = a_0, grad phi_i = (a_1 .. a_D) / R,
// exact for quadratic fields. Fallbacks, in order: degree 1 (exact for linear
// fields) where the quadratic system is ill-conditioned, and plain Shepard (5.24)
// where the support is strongly one-sided (the degree-1 Schur complement below a
// quarter of m0: near a free surface, where extrapolation is not robust, as the
// thesis notes). Guards with no source keep their fields. The density gradient
// (read by delta-SPH and the walls of the SPH neighbours) comes from the same fit;
// the SPH particles' own gradient is the renormalised one (2.42-2.44).
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

  static constexpr int NB = 1 + D + D * (D + 1) / 2;  // quadratic basis

  KOKKOS_INLINE_FUNCTION static void basis(const Vec<D>& e, double* p) {
    p[0] = 1.0;
    int k = 1;
    for (int a = 0; a < D; ++a) p[k++] = e[a];
    // centred on a typical second moment of the kernel (0.07 R^2), which keeps the
    // quadratic columns from nearly repeating the constant one (conditioning)
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) p[k++] = e[a] * e[b] - (a == b ? 0.07 : 0.0);
  }

  // Solves A a = rhs (NB x NB, NF right-hand sides) by Gaussian elimination with
  // partial pivoting; false when a pivot is below `tiny` (A is destroyed).
  KOKKOS_INLINE_FUNCTION static bool solve(double (*A)[NB], double (*rhs)[NB], double tiny) {
    for (int c = 0; c < NB; ++c) {
      int piv = c;
      for (int r = c + 1; r < NB; ++r)
        if (kmath::fabs(A[r][c]) > kmath::fabs(A[piv][c])) piv = r;
      if (!(kmath::fabs(A[piv][c]) > tiny)) return false;
      if (piv != c) {
        for (int k = 0; k < NB; ++k) {
          const double t = A[c][k];
          A[c][k] = A[piv][k];
          A[piv][k] = t;
        }
        for (int f = 0; f < NF; ++f) {
          const double t = rhs[f][c];
          rhs[f][c] = rhs[f][piv];
          rhs[f][piv] = t;
        }
      }
      for (int r = c + 1; r < NB; ++r) {
        const double l = A[r][c] / A[c][c];
        if (l == 0.0) continue;
        for (int k = c; k < NB; ++k) A[r][k] -= l * A[c][k];
        for (int f = 0; f < NF; ++f) rhs[f][r] -= l * rhs[f][c];
      }
    }
    for (int f = 0; f < NF; ++f)
      for (int r = NB - 1; r >= 0; --r) {
        double v = rhs[f][r];
        for (int k = r + 1; k < NB; ++k) v -= A[r][k] * rhs[f][k];
        rhs[f][r] = v / A[r][r];
      }
    return true;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const int nn = lx.num_neighbours(i);
    if (nn == 0) return;  // an SPH particle (no Lx row) or a guard without sources
    const double R = zones.R[birth(i)];
    const double inv_R = 1.0 / R;
    const Vec<D> xi = load<D>(x, i);
    // moments in units of R: A = sum w p p^T, rhs_f = sum w p phi_f
    double A[NB][NB], rhs[NF][NB];
    for (int a = 0; a < NB; ++a) {
      for (int b = 0; b < NB; ++b) A[a][b] = 0.0;
      for (int f = 0; f < NF; ++f) rhs[f][a] = 0.0;
    }
    // the fit is of phi - phi_ref (the first source's values): a large constant part
    // (rho ~ rho0) would otherwise cost digits through the conditioning
    double ref[NF];
    for (int f = 0; f < NF; ++f) ref[f] = source(lx.neighbour(i, 0), f);
    for (int n = 0; n < nn; ++n) {
      const int j = lx.neighbour(i, n);
      const Vec<D> e = inv_R * box.delta(load<D>(x, j), xi);  // (x_j - x_i) / R
      const double q = kmath::sqrt(norm2(e));
      if (q >= 1.0) continue;  // in the skin
      const double w = m(j) / rho(j) * W1.value(q);  // the 1/R^D factor cancels
      double p[NB];
      basis(e, p);
      for (int a = 0; a < NB; ++a) {
        const double wp = w * p[a];
        for (int b = a; b < NB; ++b) A[a][b] += wp * p[b];
        for (int f = 0; f < NF; ++f) rhs[f][a] += wp * (source(j, f) - ref[f]);
      }
    }
    const double m0 = A[0][0];
    if (!(m0 > 0.0)) return;
    for (int a = 0; a < NB; ++a)
      for (int b = 0; b < a; ++b) A[a][b] = A[b][a];
    // degree 1: Schur complement s = m0 - m1^T M2^{-1} m1 tells a one-sided support
    Mat<D> M2, B;
    Vec<D> m1;
    for (int a = 0; a < D; ++a) {
      m1[a] = A[0][1 + a];
      for (int b = 0; b < D; ++b) M2.a[a][b] = A[1 + a][1 + b];
    }
    double tiny = 1e-12;
    for (int a = 0; a < D; ++a) tiny *= m0;
    int degree = 0;
    Vec<D> Bm1 = Vec<D>::zero();
    double s = m0;
    if (invert(M2, B, tiny)) {
      Bm1 = B * m1;
      s = m0 - dot(m1, Bm1);
      if (s > 0.25 * m0) degree = 1;
    }
    double value[NF];
    Vec<D> grad_rho_i = Vec<D>::zero();
    if (degree == 1) {
      double A2[NB][NB], rhs2[NF][NB];
      for (int a = 0; a < NB; ++a) {
        for (int b = 0; b < NB; ++b) A2[a][b] = A[a][b];
        for (int f = 0; f < NF; ++f) rhs2[f][a] = rhs[f][a];
      }
      if (solve(A2, rhs2, 1e-9 * m0)) {
        // one step of iterative refinement (the elimination's own error)
        for (int a = 0; a < NB; ++a)
          for (int b = 0; b < NB; ++b) A2[a][b] = A[a][b];
        double res[NF][NB];
        for (int f = 0; f < NF; ++f)
          for (int a = 0; a < NB; ++a) {
            double v = rhs[f][a];
            for (int b = 0; b < NB; ++b) v -= A[a][b] * rhs2[f][b];
            res[f][a] = v;
          }
        if (solve(A2, res, 1e-9 * m0))
          for (int f = 0; f < NF; ++f)
            for (int a = 0; a < NB; ++a) rhs2[f][a] += res[f][a];
        degree = 2;
        // phi_i = a . p(0): the constant and the centred squares (p = -0.07 there)
        for (int f = 0; f < NF; ++f) {
          double v = rhs2[f][0];
          int k = 1 + D;
          for (int a = 0; a < D; ++a)
            for (int b = a; b < D; ++b, ++k)
              if (a == b) v -= 0.07 * rhs2[f][k];
          value[f] = ref[f] + v;
        }
        for (int a = 0; a < D; ++a) grad_rho_i[a] = rhs2[D][1 + a] * inv_R;
      }
    }
    if (degree == 1) {
      for (int f = 0; f < NF; ++f) {
        Vec<D> f1;
        for (int a = 0; a < D; ++a) f1[a] = rhs[f][1 + a];
        // (f0 - m1^T B f1) / s, with m1^T B f1 = (B m1) . f1 (M2 symmetric)
        const double v = (rhs[f][0] - dot(Bm1, f1)) / s;
        value[f] = ref[f] + v;
        if (f == D) grad_rho_i = inv_R * (B * (f1 - v * m1));
      }
    } else if (degree == 0) {
      for (int f = 0; f < NF; ++f) value[f] = ref[f] + rhs[f][0] / m0;
    }
    for (int a = 0; a < D; ++a) u(i, a) = value[a];
    rho(i) = value[D];
    if (grad_rho.data() != nullptr) store<D>(grad_rho, i, grad_rho_i);
  }
};

}  // namespace apr

}  // namespace ondine
