#pragma once
// The k-epsilon model (Launder & Spalding 1974; in SPH: Violeau & Issa 2007), standard constants
// (C_mu 0.09, C1 1.44, C2 1.92, sigma_k 1.0, sigma_epsilon 1.3):
//   nu_T = C_mu k^2 / epsilon,   P_k = nu_T 2 S:S,
//   dk/dt       = P_k - epsilon + div((nu + nu_T / sigma_k) grad k),
//   depsilon/dt = (epsilon / k) (C1 P_k - C2 epsilon) + div((nu + nu_T / sigma_epsilon) grad epsilon),
// the strain from the renormalised velocity gradient (2.42)-(2.44), the diffusion in the Morris
// form with the pair's diffusivities summed, as the viscous term has it:
//   div(G grad f)_i = sum_j |F_ij| G_ij (f_j - f_i),  |F_ij| = -w_j W'(r)/r,  G_ij = G_i + G_j.
// The production is bounded by Menter's limiter (Menter 1994), P_k = min(nu_T 2 S:S, 10 epsilon):
// where a strain far above the local turbulence's (an impact's front, a particle squeezed
// against a wall) meets a large k/epsilon, P_k = C_mu (k^2/epsilon) s^2 outgrows the destruction
// and k runs away within a few steps (measured on SPHERIC Test 2 at dx = 0.03 m: k from 4.8 to
// 63 m^2/s^2 in 5 ms on a particle 0.01 m above the floor, then a NaN); in equilibrium (P = epsilon,
// the log layer) it never acts.
// KEpsilonStep advances k and epsilon over the step dt from the step's end state, the production
// and the neighbours' part of the diffusion explicit, the destruction and the diagonal of the
// diffusion implicit (linearised), so that both stay positive for any step:
//   k1 = (k + dt (P_k + sum |F| G k_j)) / (1 + dt (epsilon / k + sum |F| G)),
//   epsilon1 = (epsilon + dt (C1 (epsilon / k) P_k + sum |F| G epsilon_j)) / (1 + dt (C2 epsilon / k + sum |F| G)),
// into scratch fields; KEpsilonUpdate takes them, and on the particles in the log layer of a wall
// function sets the law's k = u_*^2 / sqrt(C_mu), epsilon = u_*^3 / (kappa y).
#include "kernels/Fields.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/turbulence/EddyViscosityPass.hpp"

namespace ondine {

struct KEpsilonConstants {
  double c_mu = 0.09, c1 = 1.44, c2 = 1.92, sigma_k = 1.0, sigma_e = 1.3;
  double k_min = 0, e_min = 0;  // floors (1e-10 of the initial state)
  double production_limit = 10;  // P_k <= production_limit epsilon (Menter's limiter)
  double dt = 0;                // the step KEpsilonStep advances over (set by the hook)
};

template <int D, class Kernel>
struct KEpsilonStep {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::TurbulentKineticEnergy, D> k;
  field_view_t<field::DissipationRate, D> eps;
  field_view_t<field::EddyViscosity, D> nu_T;
  double nu;
  KEpsilonConstants c;
  field_view_t<field::TurbulentKineticEnergyNext, D> k_next;
  field_view_t<field::DissipationRateNext, D> eps_next;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    const double ki = k(i), ei = eps(i), Gk = nu + nu_T(i) / c.sigma_k, Ge = nu + nu_T(i) / c.sigma_e;
    VelocityGradientSum<D> S;
    double Ak = 0, Bk = 0, Ae = 0, Be = 0;  // sum |F| G f_j and sum |F| G, for k and epsilon
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double w = m(j) / rho(j), dWr = W.derivative(r) / r;
      S.add(w, xij, dWr * xij, load<D>(u, j) - ui);
      const double F = -w * dWr;  // >= 0
      const double gk = F * (Gk + nu + nu_T(j) / c.sigma_k), ge = F * (Ge + nu + nu_T(j) / c.sigma_e);
      Ak += gk * k(j);
      Bk += gk;
      Ae += ge * eps(j);
      Be += ge;
    });
    const double s = strain_rate_magnitude<D>(S.gradient());
    const double P = kmath::fmin(nu_T(i) * s * s, c.production_limit * ei), dt = c.dt;  // Menter's limiter
    k_next(i) = (ki + dt * (P + Ak)) / (1.0 + dt * (ei / ki + Bk));
    eps_next(i) = (ei + dt * (c.c1 * ei / ki * P + Ae)) / (1.0 + dt * (c.c2 * ei / ki + Be));
  }
};

template <int D>
struct KEpsilonUpdate {
  KEpsilonConstants c;
  double kappa, nu;
  double y_plus_log;  // the log layer starts above this y+ (the smooth law's y+_c; 0 on a rough wall)
  double y_min;       // a rough wall's k_s: closer particles read the law at k_s (0 on a smooth wall)
  field_view_t<field::TurbulentKineticEnergy, D> k;
  field_view_t<field::DissipationRate, D> eps;
  field_view_t<field::TurbulentKineticEnergyNext, D> k_next;
  field_view_t<field::DissipationRateNext, D> eps_next;
  field_view_t<field::FrictionVelocity, D> u_star = {};  // allocated with a wall function
  field_view_t<field::YPlus, D> y_plus = {};

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    double kn = k_next(i), en = eps_next(i);
    if (u_star.data() != nullptr && u_star(i) > 0.0 && y_plus(i) > y_plus_log) {
      const double us = u_star(i);
      double y = y_plus(i) * nu / us;
      y = y > y_min ? y : y_min;
      kn = us * us / kmath::sqrt(c.c_mu);
      en = us * us * us / (kappa * y);
    }
    k(i) = kn > c.k_min ? kn : c.k_min;
    eps(i) = en > c.e_min ? en : c.e_min;
  }
};

}  // namespace ondine
