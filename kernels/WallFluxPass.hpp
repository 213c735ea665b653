#pragma once
// The generic wall loop: the NFM wall terms (thesis 4.20-4.25) and the Shepard correction
// of the whole flux, run after FluxPass when a scene has walls. It owns the iteration over
// the wall quadrature points q within R of particle i (element length s_q, normal n_out out
// of the fluid) and folds a compile-time pack of wall terms (kernels/wall/*.hpp, chosen in
// src/solver/WallFluxDispatch.hpp), as FluxPass folds the pair terms:
//   du_i   += -(1/rho_i) s_q (P_p + P_i) W_iq n_out                       (4.22)
//   drho_i += -rho_i s_q ((u_q - u_i) . n_out) W_iq                      (4.25)
//   du_i   += 2 nu s_q (u_i - u_q) / d_n W_iq,  d_n = (x_i - x_q).n_out   (4.85, no-slip walls, viscous scenes)
// (plus 2 P_min inside the bracket with the background-pressure correction 2.105),
// (wall::PressureFlux, wall::Continuity, wall::NoSlipViscosity),
// with the wall pressure P_p of the normal flux (4.14) and its MUSCL state of rho
// (4.30)-(4.32, kernels/WallPressure.hpp); with scheme.wall_velocity_reconstruction also of u
// (kernels/WallVelocityState.hpp), from the renormalised velocity gradient the density-gradient
// pass gathers in its own neighbour loop (held through the step with scheme.density_gradient: step,
// as the density's); with scheme.wall_contact u_n times the fluid's contact theta_q at the wall
// point (kernels/wall/WallContact.hpp).
// With Morris viscosity and no-slip walls (Consistent), the wall term carries the
// weight s_i(x_iq) of the Laplacian exact for linear and quadratic fields
// (kernels/ConsistentLaplacian.hpp), as the fluid pairs do.
// Then every sum is divided by gamma_i:
//   du_i = g + (fluid + wall sums) / gamma_i,  drho_i = (fluid + wall sums) / gamma_i.
//
// Wall-ward consistency correction (not in the seed): for a uniform pressure P the two
// sums give -(2P/rho_i) E_i with E_i = sum_P w_j grad_i W_ij + sum_S s_q W_iq n_out,
// zero in the continuum but not on a particle closer to a wall than the lattice's
// dx/2: at 0.01 dx from both walls of a corner E = (+0.062, +0.062)/dx (Wendland C2,
// R = 3 dx), so a uniform pressure presses the particle into the corner and (4.25)
// drains its density until its neighbours collapse onto it (docs/validation.md,
// near-wall start). For a particle whose nearest wall point is closer than dx/2 the
// part of -(2(P_i + P_min)/rho_i) E_i along G = sum_S s_q W_iq n_out (the direction
// out of the fluid) is removed when it points into the wall, blended in linearly
// from 0 at dx/2 to 1 at dx/4. The part pointing away from the wall (a flat wall's
// first row at 0.01 dx: E = -0.074/dx along n_out) is kept: it restores the clearance.
// The extra neighbour loop runs only for those particles.
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/WallVelocityState.hpp"
#include "kernels/wall/WallContact.hpp"
#include "kernels/wall/WallPointData.hpp"

namespace ondine {

template <int D, class Kernel, class Pack>
struct WallFluxPass {
  WallPoints<D> wall;
  CellList<D> wall_cells;  // cell list of the wall points, same grid as the particles
  Kernel W;
  double R2;
  Vec<D> body;
  WallEos eos;
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
  NeighbourList<D> list;           // the flux pass's list (the wall-ward correction's sum_P)
  field_view_t<field::Mass, D> m;
  double clearance;                // dx / 2 of the level: the wall-ward correction acts closer than this
  bool velocity_muscl = false;     // scheme.wall_velocity_reconstruction: the MUSCL state of u (4.30)
  VelocityGradientRows<D> grad_u;  // <grad u>_i of that state (velocity_muscl only)
  Pack terms;
  Kokkos::View<double*, MemSpace> contact;  // scheme.wall_contact: theta_q of each wall point (kernels/wall/WallContact.hpp); empty: 1

  WallFluxPass(const PassContext<D>& c, const Pack& pack)
      : wall(c.wall), wall_cells(c.wall_cells), W(c.R), R2(c.R * c.R), body(c.body), eos(c.eos), box(c.box), P_min(c.P_min),
        x(c.x), u(c.u), rho(c.rho), P(c.P), grad_rho(c.grad_rho), gamma(c.gamma), du(c.du), drho(c.drho), list(c.list), m(c.m),
        clearance(c.clearance), velocity_muscl(c.velocity_muscl), grad_u(c.grad_u), terms(pack) {}

  // E_i's fluid part sum_P w_j grad_i W_ij (only for particles next to a wall).
  KOKKOS_INLINE_FUNCTION Vec<D> fluid_gradient_sum(const int i, const Vec<D>& xi) const {
    Vec<D> S = Vec<D>::zero();
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      S += (m(j) / rho(j) * W.derivative(r) / r) * xij;
    });
    return S;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    const Mat<D> grad_u_i = velocity_muscl ? grad_u.load(i) : Mat<D>::zero();
    const double rho_i = rho(i), P_i = P(i);
    const double c2 = eos.c2(rho_i);
    const WallParticle<D> p{i, xi, ui, rho_i, P_i, c2, kmath::sqrt(c2), load<D>(grad_rho, i)};
    WallSum<D> s{Vec<D>::zero(), 0.0};
    Vec<D> G = Vec<D>::zero();
    double r_min = clearance;
    for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
      const double Wq = W.value(r) * wall.s(q);
      const Vec<D> n = load<D>(wall.n_out, q);
      G += Wq * n;
      if (r < r_min) r_min = r;
      const Vec<D> uq = load<D>(wall.u, q);
      double un = dot(ui - uq, n);
      if (velocity_muscl) un = wall_normal_velocity<D>(grad_u_i, xiq, ui, uq, n);
      if (contact.extent(0) > 0) un *= contact(q);
      terms.point(p, WallPoint<D>{q, xiq, Wq, n, uq, un}, s);
    });
    Vec<D>& acc = s.du;
    if (r_min < clearance) {  // wall-ward consistency correction (see the head of this file)
      const double G2 = norm2(G);
      if (G2 > 0.0) {
        const Vec<D> E = fluid_gradient_sum(i, xi) + G;
        const double f = -2.0 * (P_i + P_min) / rho_i * dot(E, G) / kmath::sqrt(G2);  // along G/|G|
        if (f > 0.0) {
          const double blend = kmath::fmin(1.0, 2.0 * (clearance - r_min) / clearance);
          acc -= (blend * f / kmath::sqrt(G2)) * G;
        }
      }
    }
    const double inv_gamma = 1.0 / gamma(i);
    for (int k = 0; k < D; ++k) du(i, k) = body[k] + (du(i, k) - body[k] + acc[k]) * inv_gamma;
    drho(i) = (drho(i) + s.drho) * inv_gamma;
  }
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
      if (wall.no_slip(q)) k += wall.s(q) * W.value(r) / -fluid_side_dn<D>(xiq, load<D>(wall.n_out, q), min_dn);
    });
    k *= 2.0 * nu / gamma(i);
    if (k > kmax) kmax = k;
  }
};

}  // namespace ondine
