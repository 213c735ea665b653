#pragma once
// Particle shifting (Lind et al., Xu et al.; thesis 2.107-2.111), applied once
// per time step:
//   grad C_i = sum_j w_j (1 + f_ij) grad_i W_ij,  f_ij = 0.2 (W_ij / W(dx))^4   (2.110)-(2.111)
//   dx_i = -c R^2 grad C_i, c = 0.5 in the thesis                               (2.109)
// (c beyond 0.187 at R/dx = 3 makes the shift unstable on the lattice: kernels/ShiftingStability.hpp)
// clamped to |dx_i| <= max_shift = 0.02 dx per step (not in the seed: (2.109) has
// no time scale, so applied at every step it moves particles much faster than
// the flow; with the clamp shifting is a slow regularisation. Measured on the
// Taylor-Green vortex at 50 x 50, t = 0.5: 9.2 % error with a 0.2 dx clamp,
// 0.68 % with 0.02 dx, and no kinetic energy injected in inviscid runs), and the
// Taylor correction of the fields (2.107)
//   phi_i^ = phi_i + (grad phi)_i . dx_i
// with renormalised gradients (2.42)-(2.44) of velocity and density.
// Writes the shifted state into (x_out, u_out, rho_out); the caller swaps.
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

// With NFM walls the concentration gradient gets the wall term of (4.89),
// sum_S s_q W_iq n_out, so that a particle next to a wall is not pushed into it.
// With walls or a free surface the anti-clumping part f_ij of (2.110)-(2.111) is left out. The
// wall term balances the "1" of (1 + f_ij) only, so near a wall, and at a surface, that part
// pushes one way; and under gravity, where the lattice is compressed with depth, W_ij / W(dx)
// grows downwards and the part lifts the particles. Measured in the still 2D tank
// (cases/hydrostatic_tank_2d.yaml, 2 s): the pressure's L-inf error is 0.019 unshifted, 0.185
// shifted with f, 0.118 with f projected along the walls, 0.059 with f only where the support
// is whole, and 0.012 without f. Flows without walls or surface (every axis periodic) keep it.
//
// With a free surface (Surface = true), the concentration gradient of a truncated support
// points into the fluid, so (2.109) would push the surface particles out of it. As in Lind et
// al. (2012) and the delta+-SPH of Sun et al. (2017), a particle that is on the free surface
// (the flag of 4.86-4.87, computed just before) or has a surface particle within R keeps only
// the tangential part of its shift, dx - (dx . n~) n~, with n~ its renormalised outward normal
// of (4.87) (walls included): the surface is not pushed out, and the particles along it are
// still regularised. The flags of the neighbours are read, so they must be fresh in the halos.
template <int D, class Kernel, bool Walls = false, bool Surface = false>
struct ShiftingPass {
  NeighbourList<D> list;
  PeriodicBox<D> box;       // minimum image of the neighbours and wall points
  PeriodicBox<D> wrap_box;  // wraps the shifted positions (the integrator's)
  Kernel W;
  double R2, cR2, W_dx, max_shift;  // cR2: c R^2 of (2.109)
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::Position, D> x_out;
  field_view_t<field::Velocity, D> u_out;
  field_view_t<field::Density, D> rho_out;
  WallPoints<D> wall;       // read with Walls only
  CellList<D> wall_cells;
  field_view_t<field::FreeSurface, D> surface;  // read with Surface only

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const Vec<D> ui = load<D>(u, i);
    const double rho_i = rho(i);
    VelocityGradientSum<D> S;  // M_i and the velocity moment
    Vec<D> grho = Vec<D>::zero(), gradC = Vec<D>::zero();
    Vec<D> v = Vec<D>::zero();     // Surface: sum_P w_j grad_i W_ij + sum_S s_q n_q W_iq (4.87)
    Mat<D> Mw = Mat<D>::zero();    // Surface: the wall part of the NFM matrix (4.86)
    bool near_surface = false;
    if constexpr (Surface) near_surface = surface(i) > 0.5;
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double rho_j = rho(j);
      const double w = m(j) / rho_j;
      const Vec<D> gradW = (W.derivative(r) / r) * xij;
      // the anti-clumping part (2.111) only without walls and surface: see the note above
      if constexpr (!Walls && !Surface) {
        const double ratio = W.value(r) / W_dx;
        const double f = 0.2 * ratio * ratio * ratio * ratio;
        gradC += (w * (1.0 + f)) * gradW;
      } else {
        gradC += w * gradW;
      }
      S.add(w, xij, gradW, load<D>(u, j) - ui);
      grho += (w * (rho_j - rho_i)) * gradW;
      if constexpr (Surface) {
        v += w * gradW;
        near_surface = near_surface || surface(j) > 0.5;
      }
    });
    if constexpr (Walls) {
      for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
        const double sW = wall.s(q) * W.value(r);
        const Vec<D> nq = load<D>(wall.n_out, q);
        gradC += sW * nq;
        if constexpr (Surface) {
          v += sW * nq;
          for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b) Mw.a[a][b] -= sW * xiq[a] * nq[b];
        }
      });
    }
    Vec<D> dx = (-cR2) * gradC;
    if constexpr (Surface) {
      if (near_surface) {
        // n~ = -B v / |B v| (4.87), B the inverse of the NFM matrix (4.86) (gamma cancels)
        Mat<D> Mn = S.M, Bn;
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) Mn.a[a][b] += Mw.a[a][b];
        Vec<D> n = invert(Mn, Bn, 1e-12) ? Bn * v : v;
        const double len = kmath::sqrt(norm2(n));
        if (len > 0) {
          n *= 1.0 / len;
          dx -= dot(dx, n) * n;  // the tangential part (the sign of n does not matter here)
        }
      }
    }
    const double len2 = norm2(dx);
    if (len2 > max_shift * max_shift) dx *= max_shift / kmath::sqrt(len2);
    Mat<D> B;
    if (!invert(S.M, B, 1e-12)) B = Mat<D>::identity();
    // vector gradient: (grad u) = G B (right multiplication); scalar: B^T g
    const Mat<D> grad_u = S.gradient(B);
    for (int a = 0; a < D; ++a) {
      double du = 0.0;
      for (int b = 0; b < D; ++b) du += grad_u.a[a][b] * dx[b];
      u_out(i, a) = ui[a] + du;
      x_out(i, a) = wrap_box.wrap(xi[a] + dx[a], a);
    }
    double drho = 0.0;
    for (int a = 0; a < D; ++a) {
      double g = 0.0;
      for (int b = 0; b < D; ++b) g += B.a[b][a] * grho[b];
      drho += g * dx[a];
    }
    rho_out(i) = rho_i + drho;
  }

  void run(int n) const { Kokkos::parallel_for("ondine::Shifting", Kokkos::RangePolicy<ExecSpace>(0, n), *this); }
};

}  // namespace ondine
