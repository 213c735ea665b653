#pragma once
// The Generalised Langevin Model (V&I §4.1.2, [V&I 16]) on the particles' instantaneous velocity:
//   du_i = G_ij u'_j dt + sqrt(C0 epsilon dt) xi_i,   u' = u - <u>,
//   G_ij = -C1/2 (epsilon / k) delta_ij + C2 d<u_i>/dx_j        (C1 = 1.8, C2 = 0.6: LRR-IP),
// the pressure and body-force parts of [V&I 16] being the flow's own step. The means are
// kernel-filtered [V&I 17], Shepard-normalised with the particle itself (LangevinMean):
//   u~_i = sum_j w_j u_j W_ij / sum_j w_j W_ij,   d_i = sum_j w_j (x_j - x_i) W_ij / sum_j w_j W_ij,
// grad<u>_i the renormalised gradient (2.42)-(2.44) of the means, from u~_j - u~_i as V&I's
// [V&I 15] takes <u>_ab, and the mean corrected to first order (LangevinStep):
//   <u>_i = u~_i - grad<u>_i d_i,
// exact for a linear field on a support cut by a wall, where u~_i is the value at the support's
// centroid d_i: the drift G u' would otherwise pull the first rows towards the faster fluid
// above them, a momentum source (measured in the plane channel at h/20: +8 N/m on the first
// rows against the driving 20 N/m). The strain of the means, not of the instantaneous
// velocities: epsilon grows as s^3 and the increment's noise as sqrt(epsilon), so a strain read
// from the fluctuations themselves feeds them back (measured: epsilon 1e7 times the log law's
// at mid-channel within 4 s, then a blow-up);
//   epsilon_i = 2 nu_T,i S:S = nu_T,i s^2 (nu_T of the mixing length, V&I §4.1.1),
//   k_i = sqrt(epsilon_i nu_T,i / C_mu)    (the seed's relation read as nu_T = C_mu k^2 / epsilon:
//                                           printed k = epsilon nu_T / C_mu is m^4/s^4),
// so epsilon / k = sqrt(C_mu) s, finite where s -> 0. C0 follows from C1, C2 (Pope 2000 §12.6):
// the trace of the model's Reynolds-stress equation over the d velocity components carried,
//   dk/dt = P + G_ij R_ij + (d/2) C0 epsilon = P - epsilon,
// gives C0 = (2/d) (C1 - 1 + C2 P / epsilon), and epsilon is the mixing length's production
// (P / epsilon = 1): C0 = (2/d) (C1 - 1 + C2) (0.933 in 3D, 1.4 in 2D).
// With turbulence.langevin.mean_gradient: averaged the model reads, in place of grad<u>, its
// average along the particle's path over the model's turnover time k / epsilon (the Reynolds
// average as a time average; the time-averaging of the means in particle PDF methods, Muradoglu,
// Jenny, Pope & Caughey 1999), exponential in time:
//   gbar <- gbar + w (grad<u> - gbar),  w = max(dt / (t + dt), 1 - exp(-dt sqrt(C_mu) sbar)),
// sbar = sqrt(2 S:S) of gbar before the update (epsilon / k = sqrt(C_mu) sbar), and the running
// mean since t = 0 where that is the longer memory (w = 1 at the first step: gbar = grad<u>; a
// layer started uniform has sbar = 0). epsilon, k, nu_T and the drift's C2 term then read gbar;
// the first-order mean correction keeps the instantaneous grad<u> (it interpolates the step's
// field). The fluctuations' own strain, which the filtered means carry and epsilon ~ s^3 feeds
// back, averages out over the turnover time; the mean shear does not.
// LangevinStep advances u' over the step dt from the step's end state, the isotropic relaxation
// implicit (stable for any step), into a scratch field:
//   u'_1 = (u' + dt C2 grad<u> u' + sqrt(C0 epsilon dt) xi) / (1 + dt C1 epsilon / (2 k)),
//   u_1 = <u> + u'_1;
// xi_i: independent standard normal numbers, a function of (seed, particle id, step, component)
// (a counter-based stream: the same on any rank count, after a restart, on any backend).
#include <cstdint>

#include "kernels/Fields.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/turbulence/EddyViscosityPass.hpp"

namespace ondine {

struct LangevinConstants {
  double c1 = 1.8, c2 = 0.6, c0 = 1.4, c_mu = 0.09;
  std::uint64_t seed = 0;
  std::int64_t step = 0;  // the step advanced (set by the hook)
  double dt = 0;
  bool averaged = false;  // turbulence.langevin.mean_gradient: averaged
  bool drift_mean_removed = false;  // turbulence.langevin.drift_mean: removed
  bool solenoidal = false;          // turbulence.langevin.noise: solenoidal
  double time = 0;        // the step's start (set by the hook): the running mean's age

  // C0 of Pope's consistency relation with P / epsilon = 1, in d dimensions
  static double consistent_c0(double c1, double c2, int d) { return 2.0 / d * (c1 - 1.0 + c2); }
};

// SplitMix64's finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix
KOKKOS_INLINE_FUNCTION std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// the standard normal xi_c of particle `id` at step `step` (c = 0 .. 2: the increment's, 4 .. 6: the
// solenoidal noise's psi): a Box-Muller pair from
// two uniforms in (0, 1] of the counter (seed, id, step, pair)
KOKKOS_INLINE_FUNCTION double langevin_normal(const std::uint64_t seed, const std::int64_t id, const std::int64_t step, const int c) {
  const std::uint64_t key = splitmix64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(id)) ^ static_cast<std::uint64_t>(step));
  const std::uint64_t a = splitmix64(key ^ (2ull * static_cast<std::uint64_t>(c / 2) + 1ull));
  const std::uint64_t b = splitmix64(a);
  const double u1 = (static_cast<double>(a >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
  const double u2 = static_cast<double>(b >> 11) * 0x1.0p-53;          // [0, 1)
  const double rad = kmath::sqrt(-2.0 * kmath::log(u1)), ang = 6.283185307179586 * u2;
  return (c % 2 == 0) ? rad * kmath::cos(ang) : rad * kmath::sin(ang);
}

// u'_1 of one particle: its fluctuation u', grad<u>, epsilon / k, epsilon and the normals xi
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> langevin_fluctuation(const Vec<D>& up, const Mat<D>& g, const double eps_over_k, const double eps,
                                                   const Vec<D>& xi, const LangevinConstants& c) {
  const double noise = kmath::sqrt(c.c0 * eps * c.dt), relax = 1.0 / (1.0 + c.dt * 0.5 * c.c1 * eps_over_k);
  Vec<D> out;
  for (int a = 0; a < D; ++a) {
    double gu = 0;
    for (int b = 0; b < D; ++b) gu += g.a[a][b] * up[b];
    out[a] = (up[a] + c.dt * c.c2 * gu + noise * xi[a]) * relax;
  }
  return out;
}

// the weight w of the step's gradient in the path average gbar (above)
KOKKOS_INLINE_FUNCTION double langevin_average_weight(const double dt, const double t, const double s_bar, const double c_mu) {
  const double running = dt / (t + dt), turnover = 1.0 - kmath::exp(-dt * kmath::sqrt(c_mu) * s_bar);
  return running > turnover ? running : turnover;
}

// turbulence.langevin.noise: solenoidal: the normals xi_i of the increment replaced by the SPH
// curl of a field psi of independent standard normals on the particles (psi_j a scalar in 2D, a
// vector in 3D, a function of (seed, id, step) like xi), each component divided by its standard
// deviation over psi:
//   c_i = curl psi = sum_j w_j grad_i W_ij x (psi_j - psi_i)  (2D: (d psi/dy, -d psi/dx)),
//   xi_i,a = c_i,a / sd_i,a,  sd_i,a^2 = sum_j w_j^2 sum_b (g_ij,ab)^2 + sum_b (sum_j w_j g_ij,ab)^2,
// g_ij,ab the weight of psi_j,b in c_i,a (the second sum: psi_i's own weight). The increments are then
// divergence-free on a regular lattice (the SPH divergence of the SPH curl: 2.6e-4 of the white noise's there, 0.31 on
// particles disordered by 0.2 dx): less of them goes to the weakly compressible fluid's
// pressure (per particle a unit normal, as the white noise).
template <int D>
struct SolenoidalNoise {
  Vec<D> c = Vec<D>::zero(), var = Vec<D>::zero(), sum = Vec<D>::zero();  // curl, sum (w g)^2, sum w g
  // psi components of a particle: D == 2 one (index 4), D == 3 three (4, 5, 6)
  KOKKOS_INLINE_FUNCTION static double psi(std::uint64_t seed, std::int64_t id, std::int64_t step, int k) {
    return langevin_normal(seed, id, step, 4 + k);
  }
  // neighbour j: w_j, grad_i W_ij, psi_j - psi_i for each psi component
  KOKKOS_INLINE_FUNCTION void add(const double w, const Vec<D>& g, const double (&dpsi)[3]) {
    if constexpr (D == 2) {
      const double gx = w * g[1], gy = -w * g[0];  // (d/dy, -d/dx)
      c[0] += gx * dpsi[0];
      c[1] += gy * dpsi[0];
      var[0] += gx * gx;
      var[1] += gy * gy;
      sum[0] += gx;
      sum[1] += gy;
    } else {
      for (int a = 0; a < 3; ++a) {  // (curl psi)_a = d_b psi_c - d_c psi_b, (a, b, c) cyclic
        const int b = (a + 1) % 3, e = (a + 2) % 3;
        c[a] += w * (g[b] * dpsi[e] - g[e] * dpsi[b]);
        var[a] += w * w * (g[b] * g[b] + g[e] * g[e]);
      }
      for (int a = 0; a < 3; ++a) sum[a] += w * g[a];  // psi_i's own weight: d_b and d_c sums
    }
  }
  KOKKOS_INLINE_FUNCTION Vec<D> normals() const {
    Vec<D> xi;
    for (int a = 0; a < D; ++a) {
      double v = var[a];
      if constexpr (D == 2) v += sum[a] * sum[a];
      else {
        const int b = (a + 1) % 3, e = (a + 2) % 3;
        v += sum[b] * sum[b] + sum[e] * sum[e];
      }
      xi[a] = v > 0 ? c[a] / kmath::sqrt(v) : 0.0;
    }
    return xi;
  }
};

template <int D>
using LangevinGradientRows = GradientRows<D, field::LangevinGradientX, field::LangevinGradientY, field::LangevinGradientZ>;

// The kernel mean of a vector field f over particle i's support, Shepard-normalised with the
// particle itself [V&I 17]: sum_j w_j f_j W_ij / sum_j w_j W_ij; with `centroid`, also the
// support's centroid offset d_i = sum_j w_j (x_j - x_i) W_ij / sum_j w_j W_ij (summed only then)
template <int D, bool Centroid = false, class Kernel, class Field>
KOKKOS_INLINE_FUNCTION Vec<D> kernel_mean(const NeighbourList<D>& list, const PeriodicBox<D>& box, const Kernel& W, double R2,
                                          const field_view_t<field::Position, D>& x, const field_view_t<field::Density, D>& rho,
                                          const field_view_t<field::Mass, D>& m, const Field& f, const int i,
                                          Vec<D>* centroid = nullptr) {
  const double wi = m(i) / rho(i) * W.value(0.0);
  Vec<D> sum = wi * load<D>(f, i), d = Vec<D>::zero();
  double shepard = wi;
  for_each_neighbour_within<D>(list, box, x, i, load<D>(x, i), R2, [&](const int j, const Vec<D>& xij, const double r) {
    const double wW = m(j) / rho(j) * W.value(r);
    sum = sum + wW * load<D>(f, j);
    if constexpr (Centroid) d = d + (-wW) * xij;
    shepard += wW;
  });
  for (int a = 0; a < D; ++a) sum[a] /= shepard;
  if constexpr (Centroid) {
    for (int a = 0; a < D; ++a) d[a] /= shepard;
    *centroid = d;
  }
  return sum;
}

template <int D, class Kernel>
struct LangevinMean {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::MeanVelocity, D> mean;        // u~
  field_view_t<field::LangevinOffset, D> offset;    // d

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    Vec<D> d;
    const Vec<D> ut = kernel_mean<D, true>(list, box, W, R2, x, rho, m, u, i, &d);
    for (int a = 0; a < D; ++a) {
      mean(i, a) = ut[a];
      offset(i, a) = d[a];
    }
  }
};

template <int D, class Kernel>
struct LangevinStep {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::GlobalId, D> id;
  MixingLength<D> length;
  LangevinConstants c;
  field_view_t<field::MeanVelocity, D> mean;        // u~ of every particle, halo copies included
  field_view_t<field::LangevinOffset, D> offset;    // d_i, overwritten by <u>_i
  // written: nu_T, k and epsilon of the end state, the velocity after the increment
  field_view_t<field::EddyViscosity, D> nu_T;
  field_view_t<field::TurbulentKineticEnergy, D> k;
  field_view_t<field::DissipationRate, D> eps;
  field_view_t<field::LangevinVelocity, D> u_next;
  LangevinGradientRows<D> mean_gradient;            // gbar (c.averaged only): read and advanced
  field_view_t<field::LangevinDrift, D> drift = {};  // c.drift_mean_removed only: the deterministic increment

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i), ut = load<D>(mean, i);
    VelocityGradientSum<D> S;
    SolenoidalNoise<D> curl;
    double psi_i[3] = {0, 0, 0};
    if (c.solenoidal)
      for (int k = 0; k < (D == 2 ? 1 : 3); ++k) psi_i[k] = SolenoidalNoise<D>::psi(c.seed, id(i), c.step, k);
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const Vec<D> g = (W.derivative(r) / r) * xij;
      S.add(m(j) / rho(j), xij, g, load<D>(mean, j) - ut);
      if (c.solenoidal) {
        double dpsi[3] = {0, 0, 0};
        for (int k = 0; k < (D == 2 ? 1 : 3); ++k) dpsi[k] = SolenoidalNoise<D>::psi(c.seed, id(j), c.step, k) - psi_i[k];
        curl.add(m(j) / rho(j), g, dpsi);
      }
    });
    const Mat<D> g_step = S.gradient();
    const Vec<D> um = ut + (-1.0) * (g_step * load<D>(offset, i));
    Mat<D> g = g_step;
    if (c.averaged) {
      const Mat<D> before = mean_gradient.load(i);
      const double w = langevin_average_weight(c.dt, c.time, strain_rate_magnitude<D>(before), c.c_mu);
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) g.a[a][b] = before.a[a][b] + w * (g_step.a[a][b] - before.a[a][b]);
      mean_gradient.store(i, g);
    }
    const double s = strain_rate_magnitude<D>(g), L = length(xi);
    const double nt = L * L * s, e = nt * s * s;  // nu_T (V&I §4.1.1), epsilon = nu_T s^2
    Vec<D> noise;
    if (c.solenoidal) noise = curl.normals();
    else
      for (int a = 0; a < D; ++a) noise[a] = langevin_normal(c.seed, id(i), c.step, a);
    const Vec<D> up = langevin_fluctuation<D>(ui - um, g, kmath::sqrt(c.c_mu) * s, e, noise, c);
    if (c.drift_mean_removed) {  // the increment without its noise: <u> + u'_1(xi = 0) - u
      const Vec<D> up0 = langevin_fluctuation<D>(ui - um, g, kmath::sqrt(c.c_mu) * s, e, Vec<D>::zero(), c);
      for (int a = 0; a < D; ++a) drift(i, a) = um[a] + up0[a] - ui[a];
    }
    nu_T(i) = nt;
    eps(i) = e;
    k(i) = kmath::sqrt(e * nt / c.c_mu);
    for (int a = 0; a < D; ++a) {
      u_next(i, a) = um[a] + up[a];
      offset(i, a) = um[a];
    }
  }
};

// turbulence.langevin.drift_mean: removed: the kernel mean of the step's deterministic
// increments, Shepard-normalised with the particle itself as the means are, taken from each
// particle's velocity after the increment:
//   u_1,i -= sum_j w_j D_j W_ij / sum_j w_j W_ij,   D = <u> + u'_1(xi = 0) - u,
// so that the drift's mean over a support is reduced to the filter's residual, as the model's
// consistency asks of it (the
// drift moves u' about the mean, the mean velocity's equation has no drift term: Pope 2000
// §12.3); G read from a particle's own path (mean_gradient: averaged) or from supports cut by
// a wall otherwise leaves a mean force (langevin.csv).
template <int D, class Kernel>
struct LangevinDriftMean {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::LangevinDrift, D> drift;  // every particle's, halo copies included
  field_view_t<field::LangevinVelocity, D> u_next;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> mean = kernel_mean<D>(list, box, W, R2, x, rho, m, drift, i);
    for (int a = 0; a < D; ++a) u_next(i, a) -= mean[a];
  }
};

}  // namespace ondine
