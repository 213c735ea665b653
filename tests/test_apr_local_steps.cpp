// Local time stepping by level (refinement.local_time_stepping; docs/apr.md): the steps each
// level takes, a uniform flow through the levels, the time interpolation's kernels, and the
// consistency of the subcycled levels with one global step on a decaying Taylor-Green flow.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "kernels/apr/LevelTimeInterpolation.hpp"
#include "observers/ErrorNorms.hpp"
#include "test_helpers.hpp"

using namespace ondine;

namespace {

// test_apr.cpp's periodic channel (0.6 x 0.4 m, dx 0.02 m, linear EOS with a background
// pressure) moving at U along x through one static refinement box
Scene uniform_flow(double U, bool local) {
  return parse_case(
      "dimension: 2\n"
      "domain: {min: [0, 0], max: [0.6, 0.4], periodic: [true, true]}\n"
      "fluid: {rho0: 1000, sound_speed: 10, eos: {law: linear, background_pressure: 2000}}\n"
      "discretisation: {dx: 0.02, R_over_dx: 3}\n"
      "fluid_blocks: [{min: [0, 0], max: [0.6, 0.4], velocity: [" + std::to_string(U) + ", 0]}]\n"
      "scheme: {time_integrator: rk4, delta_sph: 0.1}\n"
      "time: {duration: 1, output_interval: 1}\n"
      "refinement: {local_time_stepping: " + std::string(local ? "true" : "false") +
          ", zones: [{name: box, min: [0.2, 0.12], max: [0.35, 0.28]}]}\n",
      "lts_test.yaml");
}

// A viscous Taylor-Green cell (1 m, U = 1 m/s, nu = 0.05 m^2/s: the amplitude decays by
// exp(-2 nu k^2 t), 18 % in 0.05 s) at dx = 0.04 m with a refinement box in its middle
Scene taylor_green(bool local, double cfl) {
  return parse_case(
      "dimension: 2\n"
      "domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}\n"
      "fluid: {rho0: 1, sound_speed: 10, viscosity: 0.05}\n"
      "discretisation: {dx: 0.04, kernel: wendland_c2, R_over_dx: 3}\n"
      "fluid_blocks: [{min: [0, 0], max: [1, 1], velocity: {taylor_green: {amplitude: 1.0, wavelength: 1.0}}, pressure: taylor_green}]\n"
      "scheme: {viscous_term: morris, delta_sph: 0.1, time_integrator: rk4, cfl: {acoustic: " + std::to_string(cfl) + "}}\n"
      "time: {duration: 1, output_interval: 1}\n"
      "refinement: {local_time_stepping: " + std::string(local ? "true" : "false") +
          ", zones: [{name: box, min: [0.3, 0.3], max: [0.7, 0.7]}]}\n",
      "lts_taylor_green.yaml");
}

// the SPH particles' velocities by global id, level by level, those with ids below n0
using Velocities = std::map<std::int64_t, std::array<double, 2>>;
std::array<Velocities, 2> sph_velocities(const Simulation<2>& sim, std::int64_t n0) {
  const test::AprHostState<2> h = test::apr_host_state(sim);
  const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::GlobalId{}));
  std::array<Velocities, 2> out;
  for (std::size_t i = 0; i < sim.size(); ++i)
    if (!h.guard(i) && id(i) < n0) out[h.birth(i)][id(i)] = {h.u(i, 0), h.u(i, 1)};
  return out;
}

double largest_difference(const Velocities& a, const Velocities& b) {
  double d = 0;
  for (const auto& [i, u] : a) {
    const auto it = b.find(i);
    if (it != b.end()) d = std::max(d, std::hypot(u[0] - it->second[0], u[1] - it->second[1]));
  }
  return d;
}

}  // namespace

TEST_CASE("Local time stepping: each coarse step takes 2^l steps of level l, and twice the global step", "[apr][lts]") {
  Simulation<2> global(uniform_flow(1.0, false)), local(uniform_flow(1.0, true));
  // the same state at t = 0: the global step is the fine level's, the coarse one the coarse level's
  const double dt_global = global.step(1.0), dt_local = local.step(1.0);
  std::printf("LTS: first step %.6e s, global %.6e s (ratio %.12f)\n", dt_local, dt_global, dt_local / dt_global);
  CHECK(std::abs(dt_local / dt_global - 2.0) < 1e-12);
  for (int k = 1; k < 20; ++k) local.step(1.0);
  REQUIRE(local.level_steps().size() == 2);
  CHECK(local.level_steps()[0] == 20);
  CHECK(local.level_steps()[1] == 40);
  CHECK(global.level_steps().empty());
}

TEST_CASE("Local time stepping: a uniform flow crossing a refinement box stays uniform, mass exact", "[apr][lts]") {
  const double U = 1.0, rho0 = 1000.0, P0 = 2000.0, q = 0.5 * rho0 * U * U;
  Simulation<2> sim(uniform_flow(U, true));
  const double m0 = diagnostics(sim).mass;
  double du_max = 0, dP_max = 0, mass = 0;
  while (sim.time() < 0.36) {  // the fluid crosses the box and its layers (0.27 m) and leaves it
    sim.step(1.0);
    mass = std::max(mass, std::abs(diagnostics(sim).mass - m0) / m0);
    if (sim.steps() % 5 != 0) continue;
    const OutputFrame<2> frame(sim);
    const test::AprHostState<2> h = test::apr_host_state(sim);
    for (std::size_t i = 0; i < sim.size(); ++i) {
      if (h.guard(i)) continue;
      du_max = std::max(du_max, std::hypot(h.u(i, 0) - U, h.u(i, 1)));
      dP_max = std::max(dP_max, std::abs(h.P(i) - P0));
    }
  }
  std::printf("LTS uniform flow: %lld coarse steps, max |u - U| rho0 U / q = %.2e, max |P - P0| / q = %.2e, mass %.1e\n",
              static_cast<long long>(sim.steps()), du_max * rho0 * U / q, dP_max / q, mass);
  CHECK(sim.refinement().refined() > 100);
  CHECK(sim.refinement().deleted() > 400);
  CHECK(du_max * rho0 * U < 1e-3 * q);  // test_apr.cpp's bound for the global step
  CHECK(dP_max < 1e-3 * q);
  CHECK(mass <= 1e-12);
}

TEST_CASE("Local time stepping: the coarse state in time between a step's ends, the fine velocity and density extrapolated", "[unit][apr][lts]") {
  PeriodicBox<2> box{{0.0, 0.0}, {1.0, 1.0}, {true, false}};
  field_view_t<field::Position, 2> x("x", 1), x0("x0", 1), x1("x1", 1);
  field_view_t<field::Velocity, 2> u("u", 1), u0("u0", 1), u1("u1", 1);
  field_view_t<field::Density, 2> r("r", 1), r0("r0", 1), r1("r1", 1);
  field_view_t<field::Acceleration, 2> du("du", 1);
  field_view_t<field::DensityRate, 2> dr("dr", 1);
  // across the periodic face in x: from 0.98 to 0.02 (a step of +0.04)
  auto set = [](auto v, double a, double b) {
    auto h = Kokkos::create_mirror_view(v);
    h(0, 0) = a;
    h(0, 1) = b;
    Kokkos::deep_copy(v, h);
  };
  set(x0, 0.98, 0.5);
  set(x1, 0.02, 0.6);
  set(u0, 1.0, 2.0);
  set(u1, 3.0, -2.0);
  set(du, 4.0, -8.0);
  Kokkos::deep_copy(r0, 1000.0);
  Kokkos::deep_copy(r1, 1010.0);
  Kokkos::deep_copy(dr, 50.0);
  auto at = [&](double theta) {
    apr::LevelTimeInterpolation<2>{box, x, x0, x1, u, u0, u1, r, r0, r1, theta}.run(0, 1);
    const auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
    const auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), u);
    const auto hr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r);
    return std::array<double, 5>{hx(0, 0), hx(0, 1), hu(0, 0), hu(0, 1), hr(0)};
  };
  const auto a = at(0.25), b = at(0.75), c = at(1.0);
  CHECK(a[0] == Approx(0.99).margin(1e-14));  // 0.98 + 0.25 * 0.04, not a trip through the box
  CHECK(b[0] == Approx(0.01).margin(1e-14));  // 1.01 wrapped
  CHECK(a[1] == Approx(0.525).margin(1e-14));
  CHECK(a[2] == Approx(1.5).margin(1e-14));
  CHECK(a[3] == Approx(1.0).margin(1e-14));
  CHECK(a[4] == Approx(1002.5).margin(1e-11));
  CHECK(c[0] == Approx(0.02).margin(1e-14));
  CHECK(c[4] == Approx(1010.0).margin(1e-11));
  // the extrapolation from y1 by its rates: u + s du, rho + s drho (positions stay)
  apr::LevelTimeExtrapolation<2>{u, u1, r, r1, du, dr, 0.01}.run(0, 1);
  const auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), u);
  const auto hr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r);
  CHECK(hu(0, 0) == Approx(3.04).margin(1e-14));
  CHECK(hu(0, 1) == Approx(-2.08).margin(1e-14));
  CHECK(hr(0) == Approx(1010.5).margin(1e-11));
}

TEST_CASE("Local time stepping: on a decaying Taylor-Green flow the levels converge to the global step's solution", "[apr][lts]") {
  // to t = 0.01 s (the amplitude decays by 3.9 %): the particles move by a quarter of dx, so every
  // run has the same particles; the reference is the global step at an eighth of the case's CFL
  const double t_end = 0.01, cfl = 0.375;
  std::int64_t n0 = 0;  // the particles of the set-up
  auto run = [&](bool local, double c) {
    Simulation<2> sim(taylor_green(local, c));
    n0 = sim.next_id();
    while (sim.time() < t_end * (1 - 1e-12)) sim.step(t_end);
    const OutputFrame<2> frame(sim);
    return std::make_pair(sph_velocities(sim, n0), reference_errors(sim).at("velocity_l2"));
  };
  const auto [ref, e_ref] = run(false, cfl / 8);
  const auto [g, e_g] = run(false, cfl);
  const auto [l, e_l] = run(true, cfl);
  const auto [l8, e_l8] = run(true, cfl / 8);
  std::printf("LTS Taylor-Green: velocity_l2 global %.4e, local %.4e (CFL %.3f); global %.4e, local %.4e (CFL %.4f)\n", e_g, e_l, cfl,
              e_ref, e_l8, cfl / 8);
  for (int k = 0; k < 2; ++k) {
    const double dg = largest_difference(g[k], ref[k]), dl = largest_difference(l[k], ref[k]), dl8 = largest_difference(l8[k], ref[k]);
    std::printf("  level %d (%zu particles): largest |u - u_ref| global %.3e, local %.3e, local at CFL/8 %.3e (U = 1)\n", k, ref[k].size(),
                dg, dl, dl8);
    CHECK(ref[k].size() > 300);
    CHECK(l[k].size() == ref[k].size());
    // the subcycled levels' time error at the case's CFL is the global step's size (measured 0.9 and 1.3 times it) ...
    CHECK(dl < 2.0 * dg);
    // ... and it falls with the step (measured to 0.24 and 0.19 of it at CFL/8)
    CHECK(dl8 < 0.5 * dl);
  }
  // the error against the analytic solution: the global step's to 1e-2 of it (measured 1.2e-3)
  CHECK(std::abs(e_l - e_g) < 1e-2 * e_g);
}

TEST_CASE("Local time stepping: bad input names the file, line and key", "[unit][case][apr][lts]") {
  auto error_of = [](const std::string& scheme, const std::string& value) {
    try {
      parse_case("dimension: 2\n"
                 "domain: {min: [0, 0], max: [1, 1]}\n"
                 "fluid: {rho0: 1000, sound_speed: 10}\n"
                 "discretisation: {dx: 0.02}\n"
                 "fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]\n"
                 "scheme: {" + scheme + "}\n"
                 "time: {duration: 1, output_interval: 1}\n"
                 "refinement:\n"
                 "  local_time_stepping: " + value + "\n"
                 "  zones: [{name: z, min: [0.2, 0.1], max: [0.8, 0.45]}]\n",
                 "lts.yaml");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error_of("delta_sph: 0.1", "true").empty());
  CHECK(error_of("delta_sph: 0.1, transport: shifting", "true").empty());
  CHECK_THAT(error_of("delta_sph: 0.1", "often"), Catch::Contains("lts.yaml:9:") && Catch::Contains("refinement.local_time_stepping") &&
                                                  Catch::Contains("expected true or false"));
}
