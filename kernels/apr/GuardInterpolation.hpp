#pragma once
// Guard interpolation of APR (thesis 5.24; 5.23 is the same operator on a mother):
// each guard i of level r takes its fields from the SPH particles j of every level
// in its Lx row, with the daughters' radius R_f (a daughter guard's own, a mother
// guard's daughters'),
//   <phi>_i = sum_j w_j phi_j W(x_ij, R_f) / sum_k w_k W(x_ik, R_f),  w_j = m_j / rho_j.
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
#include "kernels/WallSet.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

// The interpolation is split in two passes. GuardWeights computes, for each guard,
// the MLS shape functions psi_ij of its sources (value, and gradient components):
// phi_i = sum_j psi_ij phi_j. They depend on positions only, and are recomputed
// once per time step (at its first stage) and at each bookkeeping; GuardApply
// evaluates the sums at every Runge-Kutta stage with the stage's fields. Within
// a step the weights are those of the step's start: a locally affine motion of
// guard and sources keeps them exact for linear fields (docs/apr.md).
template <int D, class UnitKernel>
struct GuardWeights {
  static constexpr int NB = 1 + D + D * (D + 1) / 2;  // quadratic basis
  NeighbourList<D> lx;
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  UnitKernel W1;  // the scene's kernel at R = 1: W(r, R) = W1(r / R) / R^D
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> psi;  // (Lx entry, 1 + D): value, gradient
  // the sources within the radius used come first in the guard's Lx row (reordered here);
  // used(i) counts them, and GuardApply reads only those
  Kokkos::View<int*, MemSpace> used;
  // per guard: 1 once it was fitted at R_m (reset with the lists): later steps fit there directly
  Kokkos::View<int*, MemSpace> wide;

  KOKKOS_INLINE_FUNCTION static void basis(const Vec<D>& e, double* p) {
    p[0] = 1.0;
    int k = 1;
    for (int a = 0; a < D; ++a) p[k++] = e[a];
    // centred on a typical second moment of the kernel (0.07 R^2), which keeps the
    // quadratic columns from nearly repeating the constant one (conditioning)
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) p[k++] = e[a] * e[b] - (a == b ? 0.07 : 0.0);
  }

  // Cholesky factor of the symmetric positive definite A (its lower triangle is
  // overwritten); false when a pivot falls below `tiny`.
  KOKKOS_INLINE_FUNCTION static bool cholesky(double (&A)[NB][NB], double tiny) {
    for (int j = 0; j < NB; ++j) {
      double d = A[j][j];
      for (int k = 0; k < j; ++k) d -= A[j][k] * A[j][k];
      if (!(d > tiny)) return false;
      d = kmath::sqrt(d);
      A[j][j] = d;
      for (int i = j + 1; i < NB; ++i) {
        double v = A[i][j];
        for (int k = 0; k < j; ++k) v -= A[i][k] * A[j][k];
        A[i][j] = v / d;
      }
    }
    return true;
  }
  // y <- (L L^T)^{-1} y, L in the lower triangle of A
  KOKKOS_INLINE_FUNCTION static void substitute(const double (&L)[NB][NB], double (&y)[NB]) {
    for (int i = 0; i < NB; ++i) {
      double v = y[i];
      for (int k = 0; k < i; ++k) v -= L[i][k] * y[k];
      y[i] = v / L[i][i];
    }
    for (int i = NB - 1; i >= 0; --i) {
      double v = y[i];
      for (int k = i + 1; k < NB; ++k) v -= L[k][i] * y[k];
      y[i] = v / L[i][i];
    }
  }

  // The fit of one guard at one radius: the degree reached (2, 1 or 0 = Shepard), and
  // what the shape functions need.
  struct Fit {
    int degree = 0;
    double inv_R = 0.0, m0 = 0.0, s = 0.0;
    double z[D + 1][NB];  // degree 2: A^{-1} p(0) (value), A^{-1} e_{1+a} (gradient)
    Mat<D> B;             // degree 1: M2^{-1}, the first moments m1 and B m1
    Vec<D> m1, Bm1;
  };

  KOKKOS_INLINE_FUNCTION void fit(const int i, const double R, Fit& f) const {
    const int first = lx.offsets(i), nn = lx.num_neighbours(i);
    f.inv_R = 1.0 / R;
    const Vec<D> xi = load<D>(x, i);
    // moments in units of R: A = sum w p p^T (upper triangle)
    double A[NB][NB];
    int count = 0;
    for (int a = 0; a < NB; ++a)
      for (int b = 0; b < NB; ++b) A[a][b] = 0.0;
    for (int n = 0; n < nn; ++n) {
      const int j = lx.neighbours(first + n);
      const Vec<D> e = f.inv_R * box.delta(load<D>(x, j), xi);  // (x_j - x_i) / R
      const double q = kmath::sqrt(norm2(e));
      if (q >= 1.0) continue;  // beyond this radius, or in the skin
      const double w = m(j) / rho(j) * W1.value(q);  // the 1/R^D factor cancels
      double p[NB];
      basis(e, p);
      for (int a = 0; a < NB; ++a) {
        const double wp = w * p[a];
        for (int b = a; b < NB; ++b) A[a][b] += wp * p[b];
      }
      ++count;
    }
    f.degree = 0;
    f.m0 = A[0][0];
    const double m0 = f.m0;
    for (int a = 0; a < NB; ++a)
      for (int b = 0; b < a; ++b) A[a][b] = A[b][a];
    // degree 1: the Schur complement s = m0 - m1^T M2^{-1} m1 tells a one-sided support
    Mat<D> M2;
    Vec<D>& m1 = f.m1;
    f.Bm1 = Vec<D>::zero();
    f.s = m0;
    for (int a = 0; a < D; ++a) {
      m1[a] = A[0][1 + a];
      for (int b = 0; b < D; ++b) M2.a[a][b] = A[1 + a][1 + b];
    }
    double tiny = 1e-12;
    for (int a = 0; a < D; ++a) tiny *= m0;
    if (m0 > 0.0 && invert(M2, f.B, tiny)) {
      f.Bm1 = f.B * m1;
      f.s = m0 - dot(m1, f.Bm1);
      if (f.s > 0.25 * m0) f.degree = 1;
    }
    double diag[NB];
    for (int a = 0; a < NB; ++a) diag[a] = A[a][a];  // the factorisation keeps A's strict upper triangle
    // the quadratic fit needs twice as many sources as unknowns and no pivot below
    // 1e-6 m0 (a full support's quadratic pivots are ~5e-3 m0): a nearly singular
    // fit amplifies round-off (and noise) without bound
    if (f.degree == 1 && count >= 2 * NB && cholesky(A, 1e-6 * m0)) {
      f.degree = 2;
      for (int c = 0; c <= D; ++c) {
        double b[NB];
        for (int a = 0; a < NB; ++a) b[a] = 0.0;
        if (c == 0) basis(Vec<D>::zero(), b);
        else b[c] = 1.0;
        for (int a = 0; a < NB; ++a) f.z[c][a] = b[a];
        substitute(A, f.z[c]);
        // one step of iterative refinement: the normal equations' condition number
        // (~1e6) would otherwise cost six digits of the weights
        double r[NB];
        for (int a = 0; a < NB; ++a) {
          double v = b[a] - diag[a] * f.z[c][a];
          for (int k = 0; k < NB; ++k)
            if (k != a) v -= (k > a ? A[a][k] : A[k][a]) * f.z[c][k];
          r[a] = v;
        }
        substitute(A, r);
        for (int a = 0; a < NB; ++a) f.z[c][a] += r[a];
      }
    }
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const int first = lx.offsets(i), nn = lx.num_neighbours(i);
    if (nn == 0) return;  // an SPH particle (no Lx row)
    // radius: the daughters' R_f for every guard, as the thesis prints it (5.24): a
    // daughter guard's own radius, and for a mother guard its daughters' (the quadratic
    // fit needs no wider support, and a support of R_m would hold 2^D times more sources)
    const int r = birth(i);
    const bool daughter = mother(i) == 0 && r > 0;
    bool at_Rm = daughter && wide(i) == 1;
    Fit f;
    fit(i, zones.R[at_Rm ? r - 1 : r + (mother(i) == 1 ? 1 : 0)], f);
    // A daughter guard deep in its transition layer has coarse sources only (spacing
    // 2 dx_f): 7 to 9 within R_f, fewer than a quadratic fit needs, and the linear one
    // smooths the field by ~0.07 R_f^2 u'' (a velocity deficit fed to the fine SPH
    // particles: on Poiseuille Re = 1 the whole channel lagged by 5e-4 of U_max). Such
    // a guard is fitted at its mother's radius R_m = 2 R_f (its Lx row reaches R_m); the
    // next steps fit it there directly (flag `wide`, reset when the lists are rebuilt).
    if (f.degree < 2 && daughter) {
      Fit g;
      fit(i, zones.R[at_Rm ? r : r - 1], g);
      if (g.degree > f.degree) {
        f = g;
        at_Rm = !at_Rm;
      }
      wide(i) = at_Rm ? 1 : 0;
    }
    const Vec<D> xi = load<D>(x, i);
    // the sources beyond the radius (the skin, or R_m where R_f sufficed) to the row's end
    int k = first;
    for (int n = first; n < first + nn; ++n) {
      const int j = lx.neighbours(n);
      if (f.inv_R * f.inv_R * norm2(box.delta(load<D>(x, j), xi)) < 1.0) {
        lx.neighbours(n) = lx.neighbours(k);
        lx.neighbours(k++) = j;
      }
    }
    used(i) = k - first;
    for (int n = 0; n < k - first; ++n) {
      const int j = lx.neighbours(first + n);
      const Vec<D> e = f.inv_R * box.delta(load<D>(x, j), xi);
      const double q = kmath::sqrt(norm2(e));
      double v = 0.0;
      Vec<D> g = Vec<D>::zero();
      if (q < 1.0 && f.m0 > 0.0) {
        const double w = m(j) / rho(j) * W1.value(q);
        if (f.degree == 2) {
          double p[NB];
          basis(e, p);
          for (int a = 0; a < NB; ++a) v += f.z[0][a] * p[a];
          v *= w;
          for (int c = 0; c < D; ++c) {
            double t = 0.0;
            for (int a = 0; a < NB; ++a) t += f.z[1 + c][a] * p[a];
            g[c] = w * t * f.inv_R;
          }
        } else if (f.degree == 1) {
          // phi = (f0 - (B m1) . f1) / s, grad = B (f1 - phi m1) / R
          v = w * (1.0 - dot(f.Bm1, e)) / f.s;
          g = f.inv_R * (f.B * (w * e - v * f.m1));
        } else {
          v = w / f.m0;  // Shepard (5.24)
        }
      }
      psi(first + n, 0) = v;
      for (int c = 0; c < D; ++c) psi(first + n, 1 + c) = g[c];
    }
  }
};

// phi_i = phi_ref + sum_j psi_ij (phi_j - phi_ref) for u and rho (and grad rho from
// the gradient weights), phi_ref the first source's value: sum_j psi_ij = 1 holds
// to round-off only, and rho ~ rho0 would otherwise lose digits.
template <int D>
struct GuardApply {
  NeighbourList<D> lx;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> psi;
  Kokkos::View<int*, MemSpace> used;  // the sources within the guard's radius (GuardWeights)
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::DensityGradient, D> grad_rho;  // unallocated: not interpolated
  // NFM walls (count 0 without): a guard is not integrated, so no wall term keeps it
  // in the fluid; within dx_l / 2 of a wall facet (segment or triangle) whose span holds
  // it, the part of its interpolated velocity that points into the wall is removed (no
  // penetration).
  NearFacets<D> walls;
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;

  KOKKOS_INLINE_FUNCTION void no_penetration(const int i, Vec<D>& ui) const {
    const double reach = 0.5 * zones.dx[birth(i)];
    for_each_facet_over<D>(walls, box, load<D>(x, i), [&](const Facet<D>& f, const Vec<D>& xs) {
      const double d = facet_signed_distance<D>(xs, f);  // > 0 on the fluid side
      const double un = dot(ui, f.n_in);
      if (d < reach && un < 0.0) ui -= un * f.n_in;
    });
  }

  // The limiter: a value outside [lo - (hi - lo), hi + (hi - lo)], the sources' range widened
  // by its own width, is an extrapolation of the fit, not a feature of the field (a
  // quadratic fit's overshoot at a smooth extremum is a fraction of the range); it is put
  // back into [lo, hi]. Returns true when it limited.
  KOKKOS_INLINE_FUNCTION static bool limit(double& v, const double lo, const double hi) {
    const double w = hi - lo;
    if (v >= lo - w && v <= hi + w) return false;
    v = v < lo ? lo : hi;
    return true;
  }

  // counts the guards whose interpolated density or velocity was limited
  KOKKOS_INLINE_FUNCTION void operator()(const int i, std::int64_t& limited) const {
    const int first = lx.offsets(i), nn = used(i);
    if (nn == 0) return;  // a guard without sources keeps its fields
    const int j0 = lx.neighbours(first);
    const Vec<D> u0 = load<D>(u, j0);
    const double r0 = rho(j0);
    Vec<D> ui = Vec<D>::zero(), g = Vec<D>::zero(), ulo = Vec<D>::zero(), uhi = Vec<D>::zero();
    double ri = 0.0, sum = 0.0, rlo = 0.0, rhi = 0.0;  // relative to the first source's
    for (int n = 0; n < nn; ++n) {
      const int j = lx.neighbours(first + n);
      const double v = psi(first + n, 0);
      sum += v;
      const Vec<D> du = load<D>(u, j) - u0;
      ui += v * du;
      const double dr = rho(j) - r0;
      ri += v * dr;
      for (int c = 0; c < D; ++c) g[c] += psi(first + n, 1 + c) * dr;
      rlo = dr < rlo ? dr : rlo;
      rhi = dr > rhi ? dr : rhi;
      for (int c = 0; c < D; ++c) {
        ulo[c] = du[c] < ulo[c] ? du[c] : ulo[c];
        uhi[c] = du[c] > uhi[c] ? du[c] : uhi[c];
      }
    }
    if (sum == 0.0) return;  // no source within the radius
    bool limited_here = false;
    if (limit(ri, rlo, rhi)) {
      limited_here = true;
      g = Vec<D>::zero();  // the fit's gradient is as unreliable as its value
    }
    for (int c = 0; c < D; ++c) limited_here = limit(ui[c], ulo[c], uhi[c]) || limited_here;
    if (limited_here) ++limited;
    ui += u0;
    no_penetration(i, ui);
    store<D>(u, i, ui);
    rho(i) = r0 + ri;
    if (grad_rho.data() != nullptr) store<D>(grad_rho, i, g);
  }
};

}  // namespace apr

}  // namespace ondine
