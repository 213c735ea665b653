#pragma once
// The k-epsilon model (Launder & Spalding 1974; in SPH: Violeau & Issa 2007), standard constants
// (C_mu 0.09, C1 1.44, C2 1.92, sigma_k 1.0, sigma_epsilon 1.3):
//   nu_T = C_mu k^2 / epsilon,   P_k = nu_T 2 S:S,
//   dk/dt       = P_k - epsilon + div((nu + nu_T / sigma_k) grad k),
//   depsilon/dt = (epsilon / k) (C1 P_k - C2 epsilon) + div((nu + nu_T / sigma_epsilon) grad epsilon),
// the strain from the renormalised velocity gradient (2.42)-(2.44), the diffusion in the Morris
// form with the pair's diffusivities summed, as the viscous term has it:
//   div(G grad f)_i = sum_j w_j (G_i + G_j) (f_i - f_j) W'(r)/r.
// KEpsilonRates gathers the production and diffusion (the explicit part); KEpsilonUpdate advances
// k and epsilon over the step with the destruction terms implicit (linearised: positive for any
// step), and on the particles in the log layer of a wall function sets the law's
// k = u_*^2 / sqrt(C_mu), epsilon = u_*^3 / (kappa y).
#include "kernels/Fields.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/turbulence/EddyViscosityPass.hpp"

namespace ondine {

struct KEpsilonConstants {
  double c_mu = 0.09, c1 = 1.44, c2 = 1.92, sigma_k = 1.0, sigma_e = 1.3;
  double k_min = 0, e_min = 0;  // floors (1e-10 of the initial state)
};

template <int D, class Kernel>
struct KEpsilonRates {
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
  field_view_t<field::TurbulentKineticEnergyRate, D> dk;
  field_view_t<field::DissipationRateRate, D> deps;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    const double ki = k(i), ei = eps(i), Gk = nu + nu_T(i) / c.sigma_k, Ge = nu + nu_T(i) / c.sigma_e;
    VelocityGradientSum<D> S;
    double Dk = 0, De = 0;
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double w = m(j) / rho(j), f = w * W.derivative(r) / r;
      S.add(w, xij, f / w * xij, load<D>(u, j) - ui);
      Dk += f * (Gk + nu + nu_T(j) / c.sigma_k) * (ki - k(j));
      De += f * (Ge + nu + nu_T(j) / c.sigma_e) * (ei - eps(j));
    });
    const double s = strain_rate_magnitude<D>(S.gradient());
    const double P = nu_T(i) * s * s;
    dk(i) = P + Dk;
    deps(i) = c.c1 * ei / ki * P + De;
  }
};

template <int D>
struct KEpsilonUpdate {
  double dt;
  KEpsilonConstants c;
  double kappa, nu, y_plus_log;  // the law's kappa, nu and y+_c (the log layer starts above it)
  field_view_t<field::TurbulentKineticEnergy, D> k;
  field_view_t<field::DissipationRate, D> eps;
  field_view_t<field::TurbulentKineticEnergyRate, D> dk;
  field_view_t<field::DissipationRateRate, D> deps;
  field_view_t<field::FrictionVelocity, D> u_star = {};  // allocated with a wall function
  field_view_t<field::YPlus, D> y_plus = {};

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const double ki = k(i), ei = eps(i);
    double kn = (ki + dt * dk(i)) / (1.0 + dt * ei / ki);
    double en = (ei + dt * deps(i)) / (1.0 + dt * c.c2 * ei / ki);
    if (u_star.data() != nullptr && y_plus(i) > y_plus_log) {
      const double us = u_star(i), y = y_plus(i) * nu / us;
      kn = us * us / kmath::sqrt(c.c_mu);
      en = us * us * us / (kappa * y);
    }
    k(i) = kn > c.k_min ? kn : c.k_min;
    eps(i) = en > c.e_min ? en : c.e_min;
  }
};

}  // namespace ondine
