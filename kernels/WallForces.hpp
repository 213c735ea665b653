#pragma once
// Force of the fluid on the walls: the wall pressure of the normal flux (4.14),
// with the MUSCL state and limiters of (4.30)-(4.32) (with scheme.wall_velocity_reconstruction
// the velocity's as in the wall flux, kernels/WallVelocityState.hpp, from the velocity gradient
// the density-gradient pass stored), and the viscous traction of
// the NFM Laplacian's wall term (4.85), each Shepard-interpolated (2.40-2.41) at
// every wall quadrature point q from the particles around it, then integrated:
//   F_w = sum_{q in w} s_q [ <P_p>_q n_out + rho0 nu <(u_i - u_q) / |d_n|>_q ].
// With a turbulence model the shear is the one the wall term applies (WallShear): nu + nu_T,i
// in place of nu, or with the log-law wall function rho0 <u_*,i^2 t_i>_q, t_i the direction of
// the tangential slip (kernels/wall/WallFunction.hpp).
// With state_only (the wall sensors) P_p is replaced by the MUSCL state's pressure
// P_f = P_i + c_i^2 (rho_f - rho_i) of (4.30)-(4.32): (4.14) with u_n = 0.
// (The reaction of the particles' wall terms is not used: with the 1/gamma_i
// Shepard factors the fluid-fluid terms do not cancel pairwise, so it would not
// be the force on the wall.)
// With refinement zones (Levels = true; docs/apr.md) the sums run over the SPH
// particles only, each with its own level's radius R_l (and d_n bounded at 0.05 R_l),
// as the probes do: a guard or a mother guard would count the same fluid twice, and
// a fine wall region is then sampled at the fine radius, not at the coarse one.
#include "kernels/NeighbourLoops.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/WallVelocityState.hpp"
#include "kernels/apr/RefinementZones.hpp"
#include "kernels/wall/WallShear.hpp"

namespace ondine {

template <int D, class Kernel, bool Levels = false>
struct WallTraction {
  WallPoints<D> wall;
  CellList<D> cells;  // particle cell list
  Kernel W;
  double R2, nu, rho0;
  double min_dn;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction;  // (q, 2D): pressure force, viscous force
  // Levels only: Kernel is the scene's kernel at R = 1, R2 the coarsest level's R^2
  RefinementZones<D> zones = {};
  field_view_t<field::AprBirthLevel, D> birth = {};
  field_view_t<field::AprGuard, D> guard = {};
  bool velocity_muscl = false;  // scheme.wall_velocity_reconstruction
  Kokkos::View<double*, MemSpace> c2;  // c_i^2 = eos.c2(rho_i) of each particle (ParticleSoundSpeed2), once per call
  bool state_only = false;  // the MUSCL state's pressure P_f alone, without (4.14)'s rho c u_n (wall sensors)
  VelocityGradientRows<D> grad_u = {};  // <grad u>_i of the velocity's MUSCL state (velocity_muscl only)
  Kokkos::View<double*, MemSpace> contact = {};  // scheme.wall_contact: theta_q, as the wall flux reads it; empty: 1
  WallShear shear = WallShear::Molecular;
  field_view_t<field::EddyViscosity, D> nu_T = {};       // WallShear::Eddy
  field_view_t<field::FrictionVelocity, D> u_star = {};  // WallShear::LogLaw

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    const Vec<D> xq = load<D>(wall.x, q), n = load<D>(wall.n_out, q), uq = load<D>(wall.u, q);
    double sw = 0.0, sp = 0.0;
    Vec<D> sv = Vec<D>::zero();
    for_each_point_within<D>(cells, box, x, xq, R2, [&](const int i, const Vec<D>& xqi, const double r) {
      const Vec<D> xiq = -1.0 * xqi;  // x_i - x_q
      const double rho_i = rho(i);
      double Wr, dn_min = min_dn;
      if constexpr (Levels) {
        if (guard(i) || r >= zones.R[birth(i)]) return;
        Wr = level_kernel<D>(zones, W, birth(i), r);
        dn_min = 0.05 * zones.R[birth(i)];
      } else {
        Wr = W.value(r);
      }
      const double w = m(i) / rho_i * Wr;
      const double c2_i = c2(i);
      const Vec<D> ui = load<D>(u, i);
      double un = state_only       ? 0.0
                  : velocity_muscl ? wall_normal_velocity<D>(grad_u.load(i), xiq, ui, uq, n)
                                   : dot(ui - uq, n);
      if (contact.extent(0) > 0) un *= contact(q);
      sp += w * normal_flux_pressure<D>(rho_i, P(i), c2_i, kmath::sqrt(c2_i), load<D>(grad_rho, i), xiq, un);
      if (shear == WallShear::LogLaw) {  // kinematic: u_*^2 along the slip
        const Vec<D> rel = ui - uq, ut = rel - dot(rel, n) * n;
        const double mag = kmath::sqrt(norm2(ut)), us = u_star(i);
        if (mag > 0.0) sv += (w * us * us / mag) * ut;
      } else if (shear == WallShear::Eddy) {  // kinematic: (nu + nu_T,i) (u_i - u_q) / |d_n|
        sv += (-w * (nu + nu_T(i)) / fluid_side_dn<D>(xiq, n, dn_min)) * (ui - uq);
      } else {  // kinematic over nu
        sv += (-w / fluid_side_dn<D>(xiq, n, dn_min)) * (ui - uq);
      }
      sw += w;
    });
    const double s = wall.s(q);
    for (int k = 0; k < D; ++k) {
      traction(q, k) = sw > 0 ? s * sp / sw * n[k] : 0.0;
      const double tau = shear == WallShear::Molecular ? s * rho0 * nu * sv[k] / sw : s * rho0 * sv[k] / sw;
      traction(q, D + k) = (sw > 0 && wall.no_slip(q)) ? tau : 0.0;
    }
  }
};

// c_i^2 of every particle for WallTraction: the equation of state's power law once per
// particle, not once per wall point around it
template <int D>
struct ParticleSoundSpeed2 {
  WallEos eos;
  field_view_t<field::Density, D> rho;
  Kokkos::View<double*, MemSpace> c2;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { c2(i) = eos.c2(rho(i)); }
};

// sum over the points of one wall of one traction component
struct WallTractionSum {
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction;
  Kokkos::View<int*, MemSpace> wall;
  Kokkos::View<int*, MemSpace> counted;  // 1 where this rank counts the point
  int which, component;
  KOKKOS_INLINE_FUNCTION void operator()(const int q, double& F) const {
    if (wall(q) == which && counted(q)) F += traction(q, component);
  }
};

// component k of the moment about c of the traction of wall `which`'s points:
// sum_q (x_q - c) x (F_pressure + F_viscous)_q (2D: the z component only, k = 2)
template <int D>
struct WallMomentSum {
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction;
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> x;
  Kokkos::View<int*, MemSpace> wall;
  Kokkos::View<int*, MemSpace> counted;
  int which, component;
  double c[3];
  KOKKOS_INLINE_FUNCTION void operator()(const int q, double& M) const {
    if (wall(q) != which || !counted(q)) return;
    double r[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) {
      r[k] = x(q, k) - c[k];
      f[k] = traction(q, k) + traction(q, D + k);
    }
    const int a = (component + 1) % 3, b = (component + 2) % 3;
    M += r[a] * f[b] - r[b] * f[a];
  }
};

}  // namespace ondine
