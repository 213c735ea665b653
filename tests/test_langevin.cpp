// The Generalised Langevin Model (V&I §4.1.2; kernels/turbulence/Langevin.hpp): its random stream,
// the consistency of C0 with the energy budget, its pass on a sheared block, and the case file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/SmoothingKernels.hpp"
#include "kernels/turbulence/Langevin.hpp"
#include "solver/Measures.hpp"
#include "solver/hooks/EddyViscosity.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using namespace ondine::test;
using Catch::Matchers::Contains;

TEST_CASE("Langevin: the random stream is standard normal, uncorrelated across components, particles and steps", "[unit][turbulence]") {
  const int N = 200000;
  double s1 = 0, s2 = 0, s4 = 0, c01 = 0, cstep = 0, cid = 0;
  for (int n = 0; n < N; ++n) {
    const std::int64_t id = n % 1000, step = n / 1000;
    const double a = langevin_normal(7, id, step, 0), b = langevin_normal(7, id, step, 1);
    const double c = langevin_normal(7, id, step, 2), later = langevin_normal(7, id, step + 1, 0);
    const double other = langevin_normal(7, id + 1000, step, 0);
    s1 += a + c, s2 += a * a + c * c, s4 += a * a * a * a + c * c * c * c;
    c01 += a * b, cstep += a * later, cid += a * other;
  }
  const double M = 2.0 * N;
  // 4 standard deviations of each estimate: mean 1/sqrt(M), variance sqrt(2/M), 4th moment sqrt(96/M)
  CHECK(std::abs(s1 / M) < 4 / std::sqrt(M));
  CHECK(std::abs(s2 / M - 1) < 4 * std::sqrt(2 / M));
  CHECK(std::abs(s4 / M - 3) < 4 * std::sqrt(96 / M));
  CHECK(std::abs(c01 / N) < 4 / std::sqrt(N * 1.0));
  CHECK(std::abs(cstep / N) < 4 / std::sqrt(N * 1.0));
  CHECK(std::abs(cid / N) < 4 / std::sqrt(N * 1.0));
  // a function of (seed, id, step, component) alone
  CHECK(langevin_normal(7, 12, 34, 1) == langevin_normal(7, 12, 34, 1));
  CHECK(langevin_normal(7, 12, 34, 1) != langevin_normal(8, 12, 34, 1));
}

// the expected change of k = |u'|^2 / 2 over one update for fluctuations of covariance R = L L^T
// (L lower triangular), the normals averaged analytically: sum_k |f(L e_k, 0)|^2 + sum_a |f(0, e_a)|^2
template <int D>
double energy_change(const Mat<D>& L, const Mat<D>& g, double eps_over_k, double eps, const LangevinConstants& c) {
  double after = 0, before = 0;
  for (int k = 0; k < D; ++k) {
    Vec<D> up = Vec<D>::zero(), e = Vec<D>::zero();
    for (int a = 0; a < D; ++a) up[a] = L.a[a][k];
    const Vec<D> f = langevin_fluctuation<D>(up, g, eps_over_k, eps, Vec<D>::zero(), c);
    e[k] = 1.0;
    const Vec<D> n = langevin_fluctuation<D>(Vec<D>::zero(), g, eps_over_k, eps, e, c);
    after += norm2(f) + norm2(n), before += norm2(up);
  }
  return 0.5 * (after - before);
}

template <int D>
void check_energy_budget() {
  // a shear dU_0/dx_1 = S with R_01 < 0: P = -R_01 S; epsilon = P (the mixing length's equilibrium)
  const double S = 2.0;
  Mat<D> R = Mat<D>::zero(), g = Mat<D>::zero();
  for (int a = 0; a < D; ++a) R.a[a][a] = a == 0 ? 0.5 : a == 1 ? 0.2 : 0.3;
  R.a[0][1] = R.a[1][0] = -0.12;
  g.a[0][1] = S;
  double trace = 0;
  for (int a = 0; a < D; ++a) trace += R.a[a][a];
  const double k = 0.5 * trace, P = 0.12 * S, eps = P;
  Mat<D> L = Mat<D>::zero();  // Cholesky
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = R.a[i][j];
      for (int m = 0; m < j; ++m) s -= L.a[i][m] * L.a[j][m];
      L.a[i][j] = i == j ? std::sqrt(s) : s / L.a[j][j];
    }
  LangevinConstants c;
  c.c0 = LangevinConstants::consistent_c0(c.c1, c.c2, D);
  c.dt = 1e-5;
  // the update's drift and diffusion remove epsilon dt from k; the flow's motion through the mean
  // gradient supplies P = epsilon: dk/dt = P - epsilon (Pope 2000 §12.6, trace over d components)
  const double dk = energy_change<D>(L, g, eps / k, eps, c);
  INFO("d = " << D << ", C0 = " << c.c0 << ", dk / (epsilon dt) = " << dk / (eps * c.dt));
  CHECK(std::abs(dk / (-eps * c.dt) - 1.0) < 1e-3);  // O(dt) of the implicit relaxation
  // another C0 breaks the budget
  c.c0 *= 1.2;
  CHECK(std::abs(energy_change<D>(L, g, eps / k, eps, c) / (-eps * c.dt) - 1.0) > 0.1);
}

TEST_CASE("Langevin: C0 of Pope's relation closes the energy budget dk/dt = P - epsilon in 2D and 3D", "[unit][turbulence]") {
  CHECK(LangevinConstants::consistent_c0(1.8, 0.6, 3) == Approx(2.8 / 3.0));
  CHECK(LangevinConstants::consistent_c0(1.8, 0.6, 2) == Approx(1.4));
  check_energy_budget<2>();
  check_energy_budget<3>();
}

namespace {

// a free block 1 x 0.5 m on a regular lattice in simple shear u = (a y, 0), one step of the
// Langevin model with a constant mixing length L
struct ShearStep {
  double dt = 0;
  Kokkos::View<double* [2], Kokkos::LayoutLeft, Kokkos::HostSpace> x, u, mean;
  Kokkos::View<double*, Kokkos::HostSpace> k, eps, nu_T;
};

// the block's case with a constant mixing length L and the keys of turbulence.langevin
Scene sheared_block(double L, const std::string& langevin) {
  const std::string y = R"(dimension: 2
domain: {min: [-0.2, -0.2], max: [1.2, 0.7]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0e-6}
discretisation: {dx: 0.025}
fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]
scheme: {viscous_term: morris}
time: {duration: 1, output_interval: 1}
turbulence: {model: langevin, mixing_length: {length: )" + std::to_string(L) + "}, langevin: {" + langevin + "}}\n";
  return parse_case(y, "langevin.yaml");
}

// u = (a y, 0) on every particle
void set_shear(ParticleSet<2>& p, double a) {
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
    u(i, 0) = a * x(i, 1);
    u(i, 1) = 0.0;
  });
}

ShearStep shear_step(double a, double L, const std::string& langevin = "seed: 3", double disorder_amp = 0) {
  Simulation<2> sim(sheared_block(L, langevin));
  if (disorder_amp > 0) disorder(sim, disorder_amp, 0.0, 0.0, 11);
  auto& p = sim.particles();
  set_shear(p, a);
  ShearStep s;
  s.dt = sim.step(1.0);  // the step may reorder the particles: the views are taken again
  s.x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  s.u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Velocity{}));
  s.mean = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::MeanVelocity{}));
  s.k = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::TurbulentKineticEnergy{}));
  s.eps = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::DissipationRate{}));
  s.nu_T = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::EddyViscosity{}));
  return s;
}

}  // namespace

TEST_CASE("Langevin: on a sheared block nu_T, epsilon, k and <u> of the linear field, then the increment's noise", "[turbulence]") {
  const double a = 3.0, L = 0.05, c_mu = 0.09, c0 = 1.4, c1 = 1.8;
  const ShearStep s = shear_step(a, L);
  // expected: nu_T = L^2 a, epsilon = nu_T a^2, k = sqrt(epsilon nu_T / C_mu) = L^2 a^2 / sqrt(C_mu)
  const double nt = L * L * a, e = nt * a * a, k = std::sqrt(e * nt / c_mu);
  const double R = 0.125;  // 5 dx from the edges: beyond a support and the one-step reach of their pressure waves
  double worst_model = 0, worst_mean = 0, var = 0;
  int n = 0;
  const double amp = std::sqrt(c0 * e * s.dt) / (1.0 + s.dt * 0.5 * c1 * std::sqrt(c_mu) * a);
  for (std::size_t i = 0; i < s.k.extent(0); ++i) {
    // the step moved the particles by a y dt along x: compare in the block's interior
    if (s.x(i, 0) < R + 0.01 || s.x(i, 0) > 1 - R - 0.01 || s.x(i, 1) < R || s.x(i, 1) > 0.5 - R) continue;
    worst_model = std::max({worst_model, std::abs(s.nu_T(i) / nt - 1), std::abs(s.eps(i) / e - 1), std::abs(s.k(i) / k - 1)});
    worst_mean = std::max(worst_mean, std::abs(s.mean(i, 0) - a * s.x(i, 1)) / (a * 0.5));
    for (int c = 0; c < 2; ++c) {
      const double d = (s.u(i, c) - s.mean(i, c)) / amp;  // u' = 0 before the increment: its noise alone
      var += d * d;
      ++n;
    }
  }
  INFO("dt " << s.dt << ", interior samples " << n << ", worst nu_T/epsilon/k " << worst_model << ", worst <u> " << worst_mean
             << ", normalised variance " << var / n);
  REQUIRE(n > 300);
  // the step's flux leaves the interior's shear linear to about 2e-6 (measured: 6.9e-6 on epsilon, ~ s^3)
  CHECK(worst_model < 1e-4);
  CHECK(worst_mean < 1e-6);
  CHECK(std::abs(var / n - 1.0) < 4 * std::sqrt(2.0 / n));
}

TEST_CASE("Langevin: the path average's weight: the step's gradient at t = 0, the running mean, then the turnover time's memory", "[unit][turbulence]") {
  const double c_mu = 0.09, dt = 1e-3;
  CHECK(langevin_average_weight(dt, 0.0, 0.0, c_mu) == 1.0);
  CHECK(langevin_average_weight(dt, 9 * dt, 0.0, c_mu) == Approx(0.1));  // the mean of the first 10 steps
  // once t exceeds the turnover time k / epsilon = 1 / (sqrt(C_mu) s), the exponential's weight
  const double s = 2.0, w = 1.0 - std::exp(-dt * 0.3 * s);
  CHECK(langevin_average_weight(dt, 100.0, s, c_mu) == Approx(w).epsilon(1e-12));
  // a step change from 0 to 1 at a held rate: 1 - e^-1 of it after one turnover time (w = 1, no
  // memory, would give 1); a gradient swinging +-1 each step: the average swings by w / (2 - w)
  // about zero (3e-4 here), where the step's gradient swings by 1
  const int turnover = static_cast<int>(std::lround(1.0 / (dt * 0.3 * s)));
  double change = 0, swing = 0, largest = 0;
  for (int n = 0; n < 10 * turnover; ++n) {
    if (n < turnover) change += langevin_average_weight(dt, 100.0, s, c_mu) * (1.0 - change);
    swing += w * ((n % 2 ? -1.0 : 1.0) - swing);
    if (n > 9 * turnover) largest = std::max(largest, std::abs(swing));  // the start's offset decays as (1 - w)^n
  }
  CHECK(change == Approx(1.0 - std::exp(-1.0)).epsilon(1e-3));
  CHECK(largest == Approx(w / (2.0 - w)).epsilon(1e-3));
}

TEST_CASE("Langevin: with mean_gradient: averaged the first step reads the step's gradient, then the path average", "[turbulence]") {
  const double a = 3.0;
  Simulation<2> sim(sheared_block(0.05, "seed: 3, mean_gradient: averaged"));
  auto& p = sim.particles();
  set_shear(p, a);
  const double R = 0.125, dt1 = sim.step(1.0);
  // over the interior: the mean of gbar_xy / a, and the largest difference of gbar / a from
  // ((0, expect_xy), (0, 0))
  struct Rows {
    double mean_xy = 0, worst = 0;
  };
  const auto interior = [&](double expect_xy) {
    const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
    const auto g0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::LangevinGradientX{}));
    const auto g1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::LangevinGradientY{}));
    Rows r;
    int n = 0;
    for (std::size_t i = 0; i < sim.size(); ++i) {
      if (x(i, 0) < R + 0.02 || x(i, 0) > 1 - R - 0.02 || x(i, 1) < R || x(i, 1) > 0.5 - R) continue;
      r.worst = std::max({r.worst, std::abs(g0(i, 1) / a - expect_xy), std::abs(g0(i, 0)) / a, std::abs(g1(i, 0)) / a, std::abs(g1(i, 1)) / a});
      r.mean_xy += g0(i, 1) / a;
      ++n;
    }
    REQUIRE(n > 200);
    r.mean_xy /= n;
    UNSCOPED_INFO("expected gbar_xy / a " << expect_xy << ": interior mean " << r.mean_xy << ", worst difference " << r.worst);
    return r;
  };
  CHECK(interior(1.0).worst < 1e-4);
  // gbar wiped: the second step (t = dt1) takes the running mean's weight dt2 / (dt1 + dt2) of
  // the step's gradient. That gradient carries the first step's increments (their noise
  // sqrt(C0 epsilon dt) = 0.01 m/s: measured, a scatter of 1.4 % of a in every component)
  Kokkos::deep_copy(p.get(field::LangevinGradientX{}), 0.0);
  Kokkos::deep_copy(p.get(field::LangevinGradientY{}), 0.0);
  const double dt2 = sim.step(1.0), w = dt2 / (dt1 + dt2);
  const Rows r = interior(w);
  // the interior's 280 particles, each off by the 1.4 % scatter: their mean within 0.005 (about
  // 6 standard errors of independent samples; neighbours share their noise), each within 5 of it
  CHECK(std::abs(r.mean_xy - w) < 0.005);
  CHECK(r.worst < 0.07);
  // nu_T and epsilon read the average: nu_T = L^2 s with s = |gbar_xy| (w a), epsilon = nu_T s^2;
  // with the step's gradient they would be 1 / w and 1 / w^3 times these
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  const auto nu_T = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::EddyViscosity{}));
  const auto eps = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::DissipationRate{}));
  const double L = 0.05, sbar = w * a;
  double nu_ratio = 0, eps_ratio = 0;
  int n = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (x(i, 0) < R + 0.02 || x(i, 0) > 1 - R - 0.02 || x(i, 1) < R || x(i, 1) > 0.5 - R) continue;
    nu_ratio += nu_T(i) / (L * L * sbar);
    eps_ratio += eps(i) / (L * L * sbar * sbar * sbar);
    ++n;
  }
  INFO("interior means: nu_T " << nu_ratio / n << ", epsilon " << eps_ratio / n << " of the averaged gradient's");
  CHECK(std::abs(nu_ratio / n - 1.0) < 0.02);
  CHECK(std::abs(eps_ratio / n - 1.0) < 0.06);  // ~ s^3: three times the strain's scatter
}

TEST_CASE("Langevin: the increments' momentum, as langevin.csv sums it, is the block's momentum change", "[turbulence]") {
  // a free block in shear, no gravity, no wall: the pair terms conserve momentum, so over five
  // steps the block's momentum changes by the Langevin increments' alone; the hook's sum of
  // m (u_1 - u) must equal it to round-off, and be non-zero (the noise and the filtered means)
  Simulation<2> sim(sheared_block(0.05, "seed: 3"));
  set_shear(sim.particles(), 1.0);
  const Diagnostics d0 = diagnostics(sim);
  for (int n = 0; n < 5; ++n) sim.step(1.0);
  const Diagnostics d1 = diagnostics(sim);
  const auto* hook = sim.find_hook<EddyViscosity<2>>();
  REQUIRE(hook != nullptr);
  const std::vector<double> impulse = hook->langevin_impulse(sim.comm());
  const double scale = d0.mass * 0.5;  // M times the block's largest speed, a y at y = 0.5 m
  for (int k = 0; k < 2; ++k) {
    INFO("component " << k << ": momentum change " << d1.momentum[k] - d0.momentum[k] << ", increments' sum " << impulse[k]);
    CHECK(std::abs(impulse[k]) > 1e-6 * scale);
    CHECK(std::abs(d1.momentum[k] - d0.momentum[k] - impulse[k]) < 1e-12 * scale);
  }
}

TEST_CASE("Langevin: drift_mean: removed takes the kernel mean of the step's drift off each increment", "[turbulence]") {
  // the same disordered sheared block and noise with the drift's mean kept and removed: after
  // one step the two velocities differ by the Shepard mean of the deterministic increments D
  // over each support (by hand over all pairs), and the removed run's drift carries less net
  // momentum than the kept run's
  const auto run = [](const char* drift_mean) {
    Simulation<2> sim(sheared_block(0.05, std::string("seed: 3, drift_mean: ") + drift_mean));
    disorder(sim, 0.2, 0.0, 0.0, 11);
    set_shear(sim.particles(), 1.0);
    sim.step(1.0);
    return sim;
  };
  Simulation<2> kept = run("kept"), removed = run("removed");
  const auto& p = removed.particles();
  auto id_k = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), kept.particles().get(field::GlobalId{}));
  auto u_k = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), kept.particles().get(field::Velocity{}));
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::GlobalId{}));
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Velocity{}));
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Mass{}));
  auto rho = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Density{}));
  auto D = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::LangevinDrift{}));
  const std::size_t n = p.size();
  REQUIRE(kept.particles().size() == n);
  std::vector<std::size_t> at(n);  // kept's row of each id
  for (std::size_t i = 0; i < n; ++i) at[static_cast<std::size_t>(id_k(i))] = i;
  const WendlandC2<2> W(removed.scene().R_over_dx * removed.scene().dx);
  double worst = 0, scale = 0, drift_kept = 0, drift_removed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double sw = 0, s0 = 0, s1 = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const double r = std::hypot(x(i, 0) - x(j, 0), x(i, 1) - x(j, 1));
      if (r >= W.R) continue;
      const double w = m(j) / rho(j) * W.value(r);
      sw += w;
      s0 += w * D(j, 0);
      s1 += w * D(j, 1);
    }
    const std::size_t k = at[static_cast<std::size_t>(id(i))];
    worst = std::max({worst, std::abs(u(i, 0) - u_k(k, 0) + s0 / sw), std::abs(u(i, 1) - u_k(k, 1) + s1 / sw)});
    scale = std::max({scale, std::abs(D(i, 0)), std::abs(D(i, 1))});
    drift_kept += m(i) * D(i, 0);
    drift_removed += m(i) * (D(i, 0) - s0 / sw);
  }
  INFO("largest drift " << scale << " m/s, worst difference " << worst << "; the drift's x-momentum kept " << drift_kept << ", removed "
                        << drift_removed);
  CHECK(scale > 1e-6);
  CHECK(worst < 1e-12 * scale + 1e-15);
  CHECK(std::abs(drift_removed) < 0.1 * std::abs(drift_kept));  // 1/44 here
}

TEST_CASE("Langevin: noise: solenoidal gives unit normals with a fraction of the white noise's divergence", "[turbulence]") {
  // the sheared block's first step (u' = 0 before it: the increment is its noise alone) with the
  // white and the solenoidal noise, on the lattice and on the lattice disordered by 0.2 dx: in the
  // interior each component's variance over the particles is 1, and the SPH divergence
  // sum_j w_j (xi_j - xi_i).grad_i W_ij of the solenoidal field is a small part of the white one's
  const double a = 3.0, L = 0.05, c_mu = 0.09, c0 = 1.4, c1 = 1.8, R = 0.075, edge = 0.125;
  double amp_disorder = 0;
  const auto stats = [&](const std::string& keys) {
    const ShearStep s = shear_step(a, L, keys, amp_disorder);
    const double nt = L * L * a, e = nt * a * a;
    const double amp = std::sqrt(c0 * e * s.dt) / (1.0 + s.dt * 0.5 * c1 * std::sqrt(c_mu) * a);
    const std::size_t n = s.x.extent(0);
    std::vector<double> xi(2 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 2; ++c) xi[2 * i + c] = (s.u(i, c) - s.mean(i, c)) / amp;
    const WendlandC2<2> W(R);
    double var = 0, div2 = 0;
    int m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (s.x(i, 0) < edge + 0.01 || s.x(i, 0) > 1 - edge - 0.01 || s.x(i, 1) < edge || s.x(i, 1) > 0.5 - edge) continue;
      double div = 0;
      for (std::size_t j = 0; j < n; ++j) {
        const double dx = s.x(i, 0) - s.x(j, 0), dy = s.x(i, 1) - s.x(j, 1), r = std::hypot(dx, dy);
        if (j == i || r >= R) continue;
        const double f = 0.025 * 0.025 * W.derivative(r) / r;  // the lattice's volume, grad_i W = W'/r (x_i - x_j)
        div += f * ((xi[2 * j] - xi[2 * i]) * dx + (xi[2 * j + 1] - xi[2 * i + 1]) * dy);
      }
      var += xi[2 * i] * xi[2 * i] + xi[2 * i + 1] * xi[2 * i + 1];
      div2 += div * div;
      m += 2;
    }
    return std::make_pair(var / m, std::sqrt(div2 / (m / 2)));
  };
  // eight seeds: 8 x 600 samples, independent for the white noise (4 standard errors: 0.08)
  double var_white = 0, div_white = 0, var_sol = 0, div_sol = 0;
  for (int seed = 1; seed <= 8; ++seed) {
    const auto w = stats("seed: " + std::to_string(seed));
    const auto c = stats("seed: " + std::to_string(seed) + ", noise: solenoidal");
    var_white += w.first / 8;
    div_white += w.second / 8;
    var_sol += c.first / 8;
    div_sol += c.second / 8;
  }
  INFO("variance white " << var_white << ", solenoidal " << var_sol << "; rms divergence white " << div_white << ", solenoidal " << div_sol);
  CHECK(std::abs(var_white - 1.0) < 0.08);
  CHECK(std::abs(var_sol - 1.0) < 0.08);
  CHECK(div_sol < 1e-3 * div_white);  // 2.6e-4 on the lattice
  amp_disorder = 0.2;  // the same on disordered particles (one seed each)
  const auto w = stats("seed: 5");
  const auto c = stats("seed: 5, noise: solenoidal");
  INFO("disordered: variance white " << w.first << ", solenoidal " << c.first << "; rms divergence white " << w.second
                                     << ", solenoidal " << c.second);
  CHECK(std::abs(c.first - 1.0) < 0.2);
  CHECK(c.second < 0.5 * w.second);  // 0.31 here: the SPH divergence of an SPH curl vanishes only on the lattice
}

TEST_CASE("Langevin: the case file refuses what is not built, naming the key", "[unit][turbulence][case]") {
  const auto with = [](const std::string& turbulence, const std::string& reference = "") {
    return R"(dimension: 2
domain: {min: [0, -0.1], max: [1, 1.1], periodic: [true, false]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0e-5}
discretisation: {dx: 0.05}
walls:
- {name: bottom, points: [[0, 0], [1, 0]], fluid_side: left, condition: no_slip}
fluid_blocks: [{min: [0, 0], max: [1, 1]}]
forces: {body_force: [0.01, 0]}
scheme: {viscous_term: morris}
time: {duration: 1, output_interval: 1}
turbulence: )" + turbulence + "\n" + reference;
  };
  CHECK_THROWS_WITH(parse_case(with("{model: langevin}"), "l.yaml"), Contains("turbulence.mixing_length"));
  CHECK_THROWS_WITH(parse_case(with("{model: mixing_length, mixing_length: {length: 0.1}, langevin: {c1: 1.8}}"), "l.yaml"),
                    Contains("turbulence.langevin"));
  CHECK_THROWS_WITH(parse_case(with("{model: langevin, mixing_length: {axis: 1, bed: 0, depth: 1, half_width: 0.5}}"), "l.yaml"),
                    Contains("turbulence.mixing_length.half_width"));
  CHECK_THROWS_WITH(parse_case(with("{model: langevin, mixing_length: {length: 0.1}, langevin: {c1: 0.2, c2: 0.1}}"), "l.yaml"),
                    Contains("turbulence.langevin"));
  CHECK_THROWS_WITH(parse_case(with("{model: langevin, mixing_length: {length: 0.1}, langevin: {seed: -1}}"), "l.yaml"),
                    Contains("turbulence.langevin.seed"));
  CHECK_THROWS_WITH(parse_case(with("{model: langevin, mixing_length: {length: 0.1}, langevin: {mean_gradient: time}}"), "l.yaml"),
                    Contains("turbulence.langevin.mean_gradient"));
  CHECK_THROWS_WITH(parse_case(with("{model: langevin, mixing_length: {length: 0.1}, langevin: {drift_mean: zero}}"), "l.yaml"),
                    Contains("turbulence.langevin.drift_mean"));
  CHECK_THROWS_WITH(parse_case(with("{model: langevin, mixing_length: {length: 0.1}, langevin: {noise: red}}"), "l.yaml"),
                    Contains("turbulence.langevin.noise"));
  CHECK_THROWS_WITH(
      parse_case(with("{model: langevin, mixing_length: {length: 0.1}}", "reference: {type: hydrostatic, length: 1, plane: true}\n"), "l.yaml"),
      Contains("reference.plane"));
  const Scene s = parse_case(with("{model: langevin, mixing_length: {axis: 1, bed: 0, half_width: 0.5}, wall_function: smooth}",
                                  "reference: {type: log_law, length: 0.5, plane: true}\n"),
                             "l.yaml");
  CHECK(s.turbulence.plane);
  CHECK(s.turbulence.depth == 0.5);
  CHECK(s.turbulence.langevin_c0 == Approx(1.4));
  CHECK(s.reference.plane);
  CHECK(!s.turbulence.eddy_viscous());
}
