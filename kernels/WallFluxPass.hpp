#pragma once
// NFM wall terms (thesis 4.20-4.25) and the Shepard correction of the whole
// flux, run after FluxPass when a scene has walls. For particle i and each wall
// quadrature point q within R (element length s_q, normal n_out out of the fluid):
//   du_i   += -(1/rho_i) s_q (P_p + P_i) W_iq n_out                       (4.22)
//   drho_i += -rho_i s_q ((u_q - u_i) . n_out) W_iq                      (4.25)
//   du_i   += 2 nu s_q (u_i - u_q) / d_n W_iq,  d_n = (x_i - x_q).n_out   (4.85, no-slip walls, viscous scenes)
// (plus 2 P_min inside the bracket with the background-pressure correction 2.105),
// with the wall pressure of the normal flux (4.14), P_p = P_f + rho_f c_f (u_f - u_q).n_out,
// the fluid state reconstructed at the wall point (MUSCL, 4.30) with the renormalised
// density gradient and limited by (4.31)-(4.32): rho_f within 1 % of rho_i, the normal
// relative velocity within 0.1 c_i. P_f = P_i + c_i^2 (rho_f - rho_i) (first order in
// rho_f - rho_i <= 1 %, exact for the linear law). Then every sum is divided by gamma_i:
//   du_i = g + (fluid + wall sums) / gamma_i,  drho_i = (fluid + wall sums) / gamma_i.
#include "kernels/NeighbourLoops.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

template <int D, class Kernel, bool Viscous>
struct WallFluxPass {
  WallPoints<D> wall;
  CellList<D> wall_cells;  // cell list of the wall points, same grid as the particles
  Kernel W;
  double R2;
  Vec<D> body;
  double nu;
  double rho0, c0, eos_gamma;  // c^2 = c0^2 (rho/rho0)^(gamma-1); gamma = 1 for the linear law
  double min_dn;               // |d_n| floor of the viscous wall term (0.05 R)
  PeriodicBox<D> box;
  double P_min;                // background pressure (2.105); 0 when the scene does not use it
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::DensityGradient, D> grad_rho;
  field_view_t<field::ShepardGamma, D> gamma;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    const double rho_i = rho(i), P_i = P(i);
    const double c2 = c0 * c0 * kmath::pow(rho_i / rho0, eos_gamma - 1.0);
    const double c_i = kmath::sqrt(c2);
    const Vec<D> g_rho = load<D>(grad_rho, i);
    Vec<D> acc = Vec<D>::zero();
    double dr = 0.0;
    for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
      {
        const double Wq = W.value(r) * wall.s(q);
        const Vec<D> n = load<D>(wall.n_out, q);
        const Vec<D> uq = load<D>(wall.u, q);
        // (4.30)-(4.31): rho reconstructed at the wall point, within 1 %
        double rho_f = rho_i - dot(g_rho, xiq);
        rho_f = kmath::fmax(0.99 * rho_i, kmath::fmin(rho_f, 1.01 * rho_i));
        // (4.32) on the wall-normal relative velocity
        double un = dot(ui - uq, n);
        un = kmath::fmax(-0.1 * c_i, kmath::fmin(un, 0.1 * c_i));
        const double P_f = P_i + c2 * (rho_f - rho_i);
        const double P_p = P_f + rho_f * c_i * un;  // (4.14)
        // (2.105) shifts P_i + P_j by 2 P_min in the fluid sum; its wall counterpart keeps
        // the shift from pushing particles into the wall (sum_P w grad W + sum_S s W n = 0)
        acc += (-(P_p + P_i + 2.0 * P_min) * Wq / rho_i) * n;
        dr -= rho_i * dot(uq - ui, n) * Wq;
        if constexpr (Viscous) {
          if (wall.no_slip(q)) {
            double dn = dot(xiq, n);  // < 0 on the fluid side
            if (dn > -min_dn) dn = -min_dn;
            acc += (2.0 * nu * Wq / dn) * (ui - uq);
          }
        }
      }
    });
    const double inv_gamma = 1.0 / gamma(i);
    for (int k = 0; k < D; ++k) du(i, k) = body[k] + (du(i, k) - body[k] + acc[k]) * inv_gamma;
    drho(i) = (drho(i) + dr) * inv_gamma;
  }

  void run(int n) const { Kokkos::parallel_for("ondine::NFM::wall_flux", Kokkos::RangePolicy<ExecSpace>(0, n), *this); }
};

}  // namespace ondine

namespace ondine {

// Stiffness of the no-slip wall term of the NFM Laplacian (4.85) for particle i:
// kappa_i = (2 nu / gamma_i) sum_q s_q W_iq / |d_n|, the rate at which it damps
// u_i - u_wall. Near a wall (small d_n, gamma ~ 1/2) it exceeds the fluid
// Laplacian's ~ nu / R^2 many times, so the explicit step must respect it:
// dt <= 1 / max_i kappa_i (RK4 is stable up to kappa dt = 2.78; not in the seeds).
template <int D, class Kernel>
struct WallViscousStiffness {
  WallPoints<D> wall;
  CellList<D> wall_cells;
  Kernel W;
  double R2, nu, min_dn;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x;
  field_view_t<field::ShepardGamma, D> gamma;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& kmax) const {
    double k = 0.0;
    for_each_point_within<D>(wall_cells, box, wall.x, load<D>(x, i), R2, [&](const int q, const Vec<D>& xiq, const double r) {
      if (!wall.no_slip(q)) return;
      double dn = dot(xiq, load<D>(wall.n_out, q));
      if (dn > -min_dn) dn = -min_dn;
      k += wall.s(q) * W.value(r) / -dn;
    });
    k *= 2.0 * nu / gamma(i);
    if (k > kmax) kmax = k;
  }
};

}  // namespace ondine
