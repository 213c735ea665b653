#pragma once
// A Morris / NFM Laplacian exact for linear and quadratic fields, for viscous flows
// along no-slip walls (not in the thesis; docs/validation.md, Poiseuille). The pair
// weight of particle i becomes direction-dependent:
//   L(u)_i = sum_j c_ij s_i(x_ij) (u_i - u_j) + sum_q k_q s_i(x_iq) (u_i - u_q),
//   s_i(x) = (x.A_i.x + b_i.x) / |x|^2,
//   c_ij = w_j (rho_i + rho_j)/rho_i W'(r)/r (fluid, 2.31),  k_q = 2 s_q W_iq / d_n (no-slip wall points, 4.85),
// with the symmetric matrix A_i and the vector b_i chosen so that L vanishes on linear
// fields and equals tr H on u = 1/2 (x - x_i).H.(x - x_i): over the basis
// psi = (x.E_p.x (x^2, y^2, 2xy in 2D), x_a), of size K = D(D+1)/2 + D,
//   (sum_j c_ij psi psi^T / r^2 + sum_q k_q psi psi^T / r^2) (a, b) = gamma_i (-2 tr E_p, 0)
// (gamma_i: the NFM flux is divided by the Shepard factor afterwards, kernels/WallFluxPass.hpp).
// With A = I, b = 0 it is the plain operator. Why:
//  - next to a wall, the plain NFM operator (4.85) on the particle lattice is not zero
//    on linear fields (L(y) = 1.93, 1.28, 0.54 at R/dx = 3, 4, 6 in the first rows, an
//    O(1/dx) force on a sheared flow) and misses y^2 by 1-2 %: Poiseuille converged at
//    first order;
//  - in the bulk, on the sheared lattice of a channel flow whose rows slide past each
//    other, the plain operator's error on quadratics fluctuates by +-0.5 % from row to
//    row and does not shrink with dx at fixed R/dx (measured on the Poiseuille particles).
// The price: the pair weights are not antisymmetric (A_i != A_j), so momentum is
// conserved only to the consistency error; this operator is used only in scenes with
// no-slip walls, whose walls exchange momentum with the fluid anyway. Where the support
// is cut by a free surface (discrete Shepard sum below 0.9 gamma_i), where it meets
// no-slip walls of different velocities (a lid corner: no smooth field fits the jump),
// or where the system is singular or gives a non-positive diagonal, the weights fall
// back to the plain operator scaled by the lattice factor kappa
// (kernels/MorrisLatticeFactor.hpp). So do weights that are negative, or above 3 kappa,
// for one of the particle's pairs or wall points: with every c_ij s_i >= 0 the explicit viscous update
// of u_i is a positive average of its neighbours' (a discrete maximum principle), stable
// under the viscous step bound whatever the asymmetry; a negative weight (a disordered
// support next to a lid, measured at 100 x 100 in the Re = 1000 cavity) is anti-diffusive
// and blew the run up at t = 3 s; unbounded positive weights (a particle almost on a wall
// point) exceed the stiffness the viscous step bound allows for.
#include "kernels/Fields.hpp"
#include "kernels/Math.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

template <int D>
using LaplacianWeightView = Kokkos::View<double* [D * (D + 1) / 2 + D], Kokkos::LayoutLeft, MemSpace>;

// Solves M z = rhs in place (Gaussian elimination with partial pivoting; N <= 9).
// Returns false when a pivot is below tiny times the largest diagonal entry.
template <int N>
KOKKOS_INLINE_FUNCTION bool solve_small(double (&M)[N][N], double (&z)[N], double tiny) {
  double scale = 0.0;
  for (int p = 0; p < N; ++p) scale = kmath::fmax(scale, kmath::fabs(M[p][p]));
  if (!(scale > 0.0)) return false;
  for (int c = 0; c < N; ++c) {
    int piv = c;
    for (int r = c + 1; r < N; ++r)
      if (kmath::fabs(M[r][c]) > kmath::fabs(M[piv][c])) piv = r;
    if (!(kmath::fabs(M[piv][c]) > tiny * scale)) return false;
    if (piv != c) {
      for (int k = 0; k < N; ++k) {
        const double t = M[c][k];
        M[c][k] = M[piv][k];
        M[piv][k] = t;
      }
      const double t = z[c];
      z[c] = z[piv];
      z[piv] = t;
    }
    for (int r = c + 1; r < N; ++r) {
      const double f = M[r][c] / M[c][c];
      for (int k = c; k < N; ++k) M[r][k] -= f * M[c][k];
      z[r] -= f * z[c];
    }
  }
  for (int c = N - 1; c >= 0; --c) {
    double s = z[c];
    for (int k = c + 1; k < N; ++k) s -= M[c][k] * z[k];
    z[c] = s / M[c][c];
  }
  return true;
}

template <int D>
struct LaplacianBasis {
  static constexpr int N = D * (D + 1) / 2;  // quadratic part
  static constexpr int K = N + D;            // with the linear part
  // bound on a pair weight s_i(x) / kappa: the viscous time-step bound (2.103) assumes the
  // plain operator's stiffness; weights up to 3 kappa keep RK4 within its stability limit
  static constexpr double max_weight = 3.0;
  // psi(x): x_a^2 (a < D), then 2 x_a x_b (a < b), then x_a
  KOKKOS_FORCEINLINE_FUNCTION static void psi(const Vec<D>& x, double* f) {
    int p = 0;
    for (int a = 0; a < D; ++a) f[p++] = x[a] * x[a];
    for (int a = 0; a < D; ++a)
      for (int b = a + 1; b < D; ++b) f[p++] = 2.0 * x[a] * x[b];
    for (int a = 0; a < D; ++a) f[p++] = x[a];
  }
  // moments += c psi psi^T, its upper triangle (q >= p; solve mirrors it)
  KOKKOS_FORCEINLINE_FUNCTION static void accumulate(double (&moments)[K][K], double c, const Vec<D>& x) {
    double f[K];
    psi(x, f);
    for (int p = 0; p < K; ++p) {
      const double cp = c * f[p];
      for (int q = p; q < K; ++q) moments[p][q] += cp * f[q];
    }
  }
  // the weight s_i(x) = (x.A_i.x + b_i.x) / |x|^2 of a pair, from the stored (a, b)
  template <class View>
  KOKKOS_FORCEINLINE_FUNCTION static double weight(const View& ab, int i, const Vec<D>& x) {
    double f[K];
    psi(x, f);
    double s = 0.0;
    for (int p = 0; p < K; ++p) s += ab(i, p) * f[p];
    return s / norm2(x);
  }
  // (a, b) from the moment system (consumed), or the fallback kappa I. The wall pass divides
  // the particle's whole flux by gamma_i (4.20-4.25), so the system's right-hand side is
  // gamma_i (-2 tr E_p, 0): the operator is exact after that division.
  // Returns whether the consistent weights were kept.
  template <class View>
  KOKKOS_INLINE_FUNCTION static bool solve(double (&moments)[K][K], bool complete, double kappa, double gamma,
                                           const View& ab, int i) {
    for (int p = 0; p < K; ++p)
      for (int q = 0; q < p; ++q) moments[p][q] = moments[q][p];
    double z[K];
    for (int p = 0; p < K; ++p) z[p] = p < D ? -2.0 * gamma : 0.0;
    bool ok = complete && solve_small<K>(moments, z, 1e-10);
    for (int p = 0; p < D; ++p) ok = ok && z[p] > 0.0;
    for (int p = 0; p < K; ++p) ab(i, p) = ok ? z[p] : (p < D ? kappa : 0.0);
    return ok;
  }
  // A sufficient test that s_i(x) lies within [0, s_max] for every x with |x| >= r_min:
  // s = e.A.e + b.e / |x| (e = x / |x|) lies within [lo - |b| / r_min, hi + |b| / r_min] for
  // the Gershgorin bounds [lo, hi] on A's eigenvalues, kept off the ends by a margin far
  // above the evaluation's round-off. When it holds, every pair's evaluated weight is within
  // the bounds; when not, they must be checked pair by pair
  template <class View>
  KOKKOS_INLINE_FUNCTION static bool within_bounds(const View& ab, int i, double r_min, double s_max) {
    double A[D][D];
    int p = D;
    for (int a = 0; a < D; ++a) A[a][a] = ab(i, a);
    for (int a = 0; a < D; ++a)
      for (int b = a + 1; b < D; ++b) A[a][b] = A[b][a] = ab(i, p++);
    double b2 = 0.0;
    for (int a = 0; a < D; ++a) b2 += ab(i, N + a) * ab(i, N + a);
    double lo = A[0][0], hi = A[0][0];
    for (int a = 0; a < D; ++a) {
      double off = 0.0;
      for (int b = 0; b < D; ++b)
        if (b != a) off += kmath::fabs(A[a][b]);
      lo = kmath::fmin(lo, A[a][a] - off);
      hi = kmath::fmax(hi, A[a][a] + off);
    }
    const double reach = kmath::sqrt(b2) / r_min, margin = 1e-9 * s_max;
    return lo - reach >= margin && hi + reach <= s_max - margin;  // false on a NaN (r_min = 0)
  }
  template <class View>
  KOKKOS_INLINE_FUNCTION static void fall_back(double kappa, const View& ab, int i) {
    for (int p = 0; p < K; ++p) ab(i, p) = p < D ? kappa : 0.0;
  }
};

}  // namespace ondine
