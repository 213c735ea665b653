// Turbulence (V&I §4.1.1): the eddy viscosity of the mixing-length and Smagorinsky models on
// analytic velocity fields, the log law's inversion, and the wall function against the laminar
// no-slip term in the viscous sublayer.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernels/SmoothingKernels.hpp"
#include "kernels/turbulence/KEpsilon.hpp"
#include "kernels/turbulence/LogLaw.hpp"
#include "solver/Measures.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using namespace ondine::test;
using Catch::Matchers::Contains;

namespace {

// a free block of fluid 1 x 0.5 m (no wall, no gravity), spacing 0.025, with a turbulence section
Simulation<2> free_block(const std::string& turbulence) {
  const std::string y = R"(dimension: 2
domain: {min: [-0.2, -0.2], max: [1.2, 0.7]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0e-6}
discretisation: {dx: 0.025}
fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]
scheme: {viscous_term: morris, delta_sph: 0.1}
time: {duration: 1, output_interval: 1}
turbulence: )" + turbulence + "\n";
  return Simulation<2>(parse_case(y, "turbulence.yaml"));
}

// nu_T after one evaluation of the velocity field u(x, y) = (a0 x + a1 y, b0 x + b1 y), and the
// particles' heights
std::pair<std::vector<double>, std::vector<double>> eddy_viscosity_of(Simulation<2>& sim, double a0, double a1, double b0, double b1) {
  disorder(sim, 0.2, 0.0, 0.0, 7);
  auto& p = sim.particles();
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
    u(i, 0) = a0 * x(i, 0) + a1 * x(i, 1);
    u(i, 1) = b0 * x(i, 0) + b1 * x(i, 1);
  });
  sim.evaluate();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
  auto hn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::EddyViscosity{}));
  std::vector<double> nu(p.size()), z(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    nu[i] = hn(i);
    z[i] = hx(i, 1);
  }
  return {nu, z};
}

// du/dt and y+ of the shear layer u = (0.05 y / 0.2, 0) over a no-slip floor (a named function:
// nvcc takes no extended lambda inside a lambda)
std::pair<Kokkos::View<double* [2], Kokkos::LayoutLeft, Kokkos::HostSpace>, Kokkos::View<double*, Kokkos::HostSpace>> shear_layer(
  const std::string& extra, const std::string& scheme) {
  const std::string y = R"(dimension: 2
domain: {min: [0, -0.1], max: [0.4, 0.4], periodic: [true, false]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0e-2}
discretisation: {dx: 0.02}
walls:
- {name: floor, points: [[0.0, 0.0], [0.4, 0.0]], fluid_side: left, condition: no_slip}
fluid_blocks: [{min: [0, 0], max: [0.4, 0.2]}]
scheme: )" + scheme + "\ntime: {duration: 1, output_interval: 1}\n" + extra;
  Simulation<2> sim(parse_case(y, "layer.yaml"));
  auto& p = sim.particles();
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
    u(i, 0) = 0.05 * x(i, 1) / 0.2;
    u(i, 1) = 0.0;
  });
  sim.evaluate();
  return std::make_pair(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Acceleration{})),
                        p.has(field::YPlus{}) ? Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::YPlus{}))
                                              : Kokkos::View<double*, Kokkos::HostSpace>());
}

// The floor's viscous x-force by brute force over the code's own wall points: at each point q the
// Shepard mean sum_i w_i f_i W_iq / sum_i w_i W_iq of the particles' kinematic wall shear f_i
// (x periodic over `period`), times s_q and rho0
template <class Shear>
double floor_shear_by_hand(Simulation<2>& sim, double period, Shear&& f_i) {
  const auto& pts = sim.walls().points();
  auto xq = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pts.x);
  auto sq = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pts.s);
  auto& p = sim.particles();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Mass{}));
  auto rho = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Density{}));
  const Scene& scene = sim.scene();
  const WendlandC2<2> W(scene.R_over_dx * scene.dx);
  double F = 0;
  for (int q = 0; q < pts.count; ++q) {
    double sw = 0, sf = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      double ddx = x(i, 0) - xq(q, 0);
      ddx -= period * std::round(ddx / period);
      const double r = std::hypot(ddx, x(i, 1) - xq(q, 1));
      if (r >= W.R) continue;
      const double w = m(i) / rho(i) * W.value(r);
      sw += w;
      sf += w * f_i(i, x(i, 1) - xq(q, 1));
    }
    if (sw > 0) F += sq(q) * sf / sw;
  }
  return scene.rho0 * F;
}

}  // namespace

TEST_CASE("Smagorinsky: nu_T = (C_s dx)^2 |a| in simple shear, 0 in solid rotation, on a disordered block", "[unit][turbulence]") {
  const double a = 3.0, Cs = 0.12, dx = 0.025;
  {
    Simulation<2> sim = free_block("{model: smagorinsky}");
    const auto [nu, z] = eddy_viscosity_of(sim, 0.0, a, 0.0, 0.0);  // u = (a y, 0): sqrt(2 S:S) = |a|
    double worst = 0;
    for (double v : nu) worst = std::max(worst, std::abs(v / (Cs * dx * Cs * dx * a) - 1.0));
    INFO("worst relative error " << worst);
    CHECK(worst < 1e-9);  // renormalised gradient: exact for a linear field, edges and corners included
  }
  {
    Simulation<2> sim = free_block("{model: smagorinsky, smagorinsky_constant: 0.2}");
    const auto [nu, z] = eddy_viscosity_of(sim, 0.0, -a, a, 0.0);  // u = (-a y, a x): no strain
    double worst = 0;
    for (double v : nu) worst = std::max(worst, std::abs(v));
    CHECK(worst < 1e-12 * 0.2 * dx * 0.2 * dx * a);
  }
  {
    Simulation<2> sim = free_block("{model: smagorinsky}");
    const auto [nu, z] = eddy_viscosity_of(sim, a, 0.0, 0.0, -a);  // pure strain (a x, -a y): sqrt(2 S:S) = 2|a|
    double worst = 0;
    for (double v : nu) worst = std::max(worst, std::abs(v / (Cs * dx * Cs * dx * 2 * a) - 1.0));
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("Mixing length: nu_T = (kappa z sqrt(1 - z/H))^2 |du/dz| in the channel form, L^2 |a| with a constant length", "[unit][turbulence]") {
  const double a = 2.0, H = 0.5, kappa = 0.41;
  {
    Simulation<2> sim = free_block("{model: mixing_length, mixing_length: {axis: 1, bed: 0.0, depth: 0.5}}");
    const auto [nu, z] = eddy_viscosity_of(sim, 0.0, a, 0.0, 0.0);
    double worst = 0;
    for (std::size_t i = 0; i < nu.size(); ++i) {
      const double zz = std::min(std::max(z[i], 0.0), H);
      const double L = kappa * zz * std::sqrt(1.0 - zz / H);
      worst = std::max(worst, std::abs(nu[i] - L * L * a));
    }
    CHECK(worst < 1e-12);
  }
  {
    Simulation<2> sim = free_block("{model: mixing_length, kappa: 0.4, mixing_length: {length: 0.01}}");
    const auto [nu, z] = eddy_viscosity_of(sim, 0.0, a, 0.0, 0.0);
    double worst = 0;
    for (double v : nu) worst = std::max(worst, std::abs(v / (1e-4 * a) - 1.0));
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("Log law: u_* from u_t and y inverts the law in the sublayer, the log layer and on a rough wall", "[unit][turbulence]") {
  const LogLaw smooth = LogLaw::make(0.41, 1e-6, 5.2, 0.0, 8.5);
  // y+_c: y+ = ln(y+)/kappa + B
  CHECK(smooth.yc == Approx(11.0).margin(0.2));
  CHECK(smooth.yc - std::log(smooth.yc) / 0.41 - 5.2 == Approx(0.0).margin(1e-12));
  for (const double us : {1e-3, 0.05, 2.0})
    for (const double yplus : {1.0, 5.0, 11.5, 30.0, 300.0, 3e4}) {
      const double y = yplus * 1e-6 / us;
      const double ut = smooth.speed(us, y);
      INFO("u* " << us << ", y+ " << yplus << ", u_t " << ut);
      CHECK(smooth.friction_velocity(ut, y) == Approx(us).epsilon(1e-12));
    }
  // the log layer's value, by hand: y+ = 100 gives u+ = ln(100)/0.41 + 5.2 = 16.432
  CHECK(smooth.speed(0.1, 100 * 1e-6 / 0.1) / 0.1 == Approx(std::log(100.0) / 0.41 + 5.2).epsilon(1e-14));
  const LogLaw rough = LogLaw::make(0.41, 1e-6, 5.2, 0.002, 8.5);
  for (const double y : {0.004, 0.02, 0.3}) {
    const double ut = rough.speed(0.03, y);
    CHECK(ut / 0.03 == Approx(std::log(y / 0.002) / 0.41 + 8.5).epsilon(1e-14));
    CHECK(rough.friction_velocity(ut, y) == Approx(0.03).epsilon(1e-14));
  }
  CHECK(smooth.friction_velocity(0.0, 0.01) == 0.0);
}

TEST_CASE("Wall function: in the viscous sublayer it gives the laminar no-slip wall term", "[turbulence]") {
  // a shear layer u = (U z / h, 0) over a no-slip floor, nu so large that every particle is in
  // the sublayer (y+ < 11), the eddy viscosity made negligible (a constant mixing length of 1e-9 m):
  // the accelerations of the wall-function scene equal those of the plain Morris scene with the
  // thesis' wall Laplacian (4.85), whose tangential part the wall function reproduces there
  const auto [a_wf, yplus] = shear_layer("turbulence: {model: mixing_length, mixing_length: {length: 1.0e-9}, wall_function: smooth}\n",
                                 "{viscous_term: morris, delta_sph: 0.1}");
  const auto [a_lam, none] = shear_layer("", "{viscous_term: morris, delta_sph: 0.1, consistent_laplacian: false}");
  REQUIRE(a_wf.extent(0) == a_lam.extent(0));
  double worst = 0, scale = 0, ymax = 0;
  int near = 0;
  for (std::size_t i = 0; i < a_wf.extent(0); ++i) {
    worst = std::max(worst, std::abs(a_wf(i, 0) - a_lam(i, 0)));
    scale = std::max(scale, std::abs(a_lam(i, 0)));
    if (yplus(i) > 0) ++near;
    ymax = std::max(ymax, yplus(i));
  }
  INFO("worst |du_x| difference " << worst << " against max |du_x| " << scale << ", largest y+ " << ymax);
  CHECK(near > 20);      // the rows within R of the floor
  CHECK(ymax < 11.0);    // all in the sublayer
  CHECK(scale > 1e-3);   // the wall term acts
  CHECK(worst < 1e-9 * scale);
}

TEST_CASE("Wall function: the wall's viscous force is the law's rho0 <u_*^2>, with an eddy viscosity rho0 <(nu + nu_T) u / y>", "[turbulence]") {
  // a plug flow of 1 m/s over a periodic no-slip floor, nu = 1e-6 (y+ of the rows within R: 1e3 to
  // 1e4, the log layer): the walls' traction (walls.csv, kernels/WallForces.hpp) reports the wall
  // shear that the wall function applies, rho0 u_*^2 interpolated at each wall point, checked
  // against the same interpolation by hand over the code's wall points; the molecular
  // rho0 nu u / y is 27 times smaller here
  const std::string y = R"(dimension: 2
domain: {min: [0, -0.1], max: [0.4, 0.4], periodic: [true, false]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0e-6}
discretisation: {dx: 0.02}
walls:
- {name: floor, points: [[0.0, 0.0], [0.4, 0.0]], fluid_side: left, condition: no_slip}
fluid_blocks: [{min: [0, 0], max: [0.4, 0.2], velocity: [1.0, 0.0]}]
scheme: {viscous_term: morris, delta_sph: 0.1}
time: {duration: 1, output_interval: 1}
)";
  {
    Simulation<2> sim(parse_case(y + "turbulence: {model: mixing_length, mixing_length: {length: 1.0e-9}, wall_function: smooth}\n", "plug.yaml"));
    sim.evaluate();
    auto us = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::FrictionVelocity{}));
    const double by_hand = floor_shear_by_hand(sim, 0.4, [&](std::size_t i, double) { return us(i) * us(i); });
    const double molecular = floor_shear_by_hand(sim, 0.4, [&](std::size_t, double dy) { return 1.0e-6 * 1.0 / std::max(dy, 0.05 * 0.06); });
    const auto f = wall_forces(sim);
    REQUIRE(f.size() == 1);
    INFO("reported " << f[0].viscous[0] << " N/m, by hand " << by_hand << ", molecular " << molecular);
    CHECK(by_hand > 20 * molecular);
    CHECK(std::abs(f[0].viscous[0] - by_hand) < 1e-10 * by_hand);
    CHECK(std::abs(f[0].viscous[1]) < 1e-10 * by_hand);
    // the law itself (1 m/s = u_* (ln(y u_*/nu)/0.41 + 5.2)): u_* = 0.0492 m/s at the first row,
    // y = dx/2, and 0.0419 at the third, y = 2.5 dx; the interpolated stress lies between
    CHECK(f[0].viscous[0] > 1000 * 0.4 * 0.0419 * 0.0419);
    CHECK(f[0].viscous[0] < 1000 * 0.4 * 0.0492 * 0.0492);
  }
  {
    // the mixing length without a wall function over the shear layer u = 0.25 y: the wall term
    // (4.85) carries nu + nu_T,i, and so does the reported force
    Simulation<2> sim(parse_case(y + "turbulence: {model: mixing_length, mixing_length: {length: 0.01}}\n", "layer.yaml"));
    auto& p = sim.particles();
    const auto x = p.get(field::Position{});
    const auto u = p.get(field::Velocity{});
    Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
      u(i, 0) = 0.25 * x(i, 1);
      u(i, 1) = 0.0;
    });
    sim.evaluate();
    auto nt = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::EddyViscosity{}));
    auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
    const auto tau = [&](std::size_t i, double dy, bool eddy) {
      return ((eddy ? nt(i) : 0.0) + 1.0e-6) * 0.25 * hx(i, 1) / std::max(dy, 0.05 * 0.06);
    };
    const double by_hand = floor_shear_by_hand(sim, 0.4, [&](std::size_t i, double dy) { return tau(i, dy, true); });
    const double molecular = floor_shear_by_hand(sim, 0.4, [&](std::size_t i, double dy) { return tau(i, dy, false); });
    const auto f = wall_forces(sim);
    INFO("reported " << f[0].viscous[0] << " N/m, by hand " << by_hand << ", molecular " << molecular);
    CHECK(by_hand > 10 * molecular);
    CHECK(std::abs(f[0].viscous[0] - by_hand) < 1e-10 * by_hand);
  }
}

TEST_CASE("Turbulence: the case file refuses what is not built, naming the key", "[unit][turbulence][case]") {
  const std::string base = R"(dimension: 2
domain: {min: [0, -0.1], max: [0.4, 0.4], periodic: [true, false]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0e-6}
discretisation: {dx: 0.02}
fluid_blocks: [{min: [0, 0], max: [0.4, 0.2]}]
time: {duration: 1, output_interval: 1}
)";
  auto refusal = [&](const std::string& rest) {
    try {
      parse_case(base + rest, "t.yaml");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(refusal("scheme: {viscous_term: morris, delta_sph: 0.1}\nturbulence: {model: smagorinsky}\n") == "accepted");
  CHECK_THAT(refusal("scheme: {viscous_term: monaghan_gingold}\nturbulence: {model: smagorinsky}\n"),
             Contains("scheme.viscous_term") && Contains("must be morris"));
  CHECK_THAT(refusal("scheme: {viscous_term: morris}\nturbulence: {model: mixing_length}\n"),
             Contains("turbulence.mixing_length") && Contains("is required"));
  CHECK_THAT(refusal("scheme: {viscous_term: morris}\nturbulence: {model: smagorinsky, wall_function: smooth}\n"),
             Contains("turbulence.wall_function") && Contains("no-slip walls"));
  CHECK_THAT(refusal("scheme: {viscous_term: morris}\nturbulence: {model: k_omega}\n"), Contains("turbulence.model") && Contains("k_epsilon"));
  CHECK_THAT(refusal("scheme: {viscous_term: morris}\nturbulence: {model: k_epsilon}\n"),
             Contains("turbulence.k_epsilon") && Contains("initial_k"));
  CHECK_THAT(refusal("scheme: {viscous_term: morris}\nturbulence: {model: mixing_length, mixing_length: {length: 0.1, depth: 1}}\n"),
             Contains("not both"));
  CHECK_THAT(refusal("scheme: {viscous_term: morris, flux: riemann}\nturbulence: {model: smagorinsky}\n"),
             Contains("not built") && Contains("turbulence.model"));
  CHECK_THAT(refusal("walls:\n  - {name: floor, points: [[0.0, 0.0], [0.4, 0.0]], fluid_side: left, condition: no_slip}\n"
                     "scheme: {viscous_term: morris}\nturbulence: {model: smagorinsky, wall_function: rough}\n"),
             Contains("turbulence.roughness") && Contains("is required"));
}

namespace {

// u = (a y, 0) on a free block, k and epsilon uniform: no net diffusion, P_k = C_mu k^2 / epsilon a^2
// exactly (the renormalised gradient), bounded by Menter's limiter at 10 epsilon; one step's
// update, with the diffusion's diagonal implicit (its off-diagonal part cancels it for a
// uniform field), is
//   k1 = (k0 + dt (P + B_k k0)) / (1 + dt (eps0 / k0 + B_k)),
//   eps1 = (eps0 + dt (C1 (eps0 / k0) P + B_e eps0)) / (1 + dt (C2 eps0 / k0 + B_e)),
// B = 2 G sum_j dx^2 |W'(r)| / r over the lattice, G = nu + nu_T / sigma
void check_homogeneous_shear(const double a) {
  const double k0 = 0.01, e0 = 0.002;
  Simulation<2> sim = free_block("{model: k_epsilon, k_epsilon: {initial_k: 0.01, initial_epsilon: 0.002}}");
  auto& p = sim.particles();
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
    u(i, 0) = a * (x(i, 1) - 0.25);
    u(i, 1) = 0.0;
  });
  const double t0 = sim.time();
  sim.step(1.0);
  const double dt = sim.time() - t0;
  const double nuT = 0.09 * k0 * k0 / e0, P = std::min(nuT * a * a, 10 * e0), dx = sim.scene().dx;
  const WendlandC2<2> W(sim.scene().R());
  double lattice = 0;  // sum_j dx^2 |W'(r)| / r over a full support
  for (int p1 = -5; p1 <= 5; ++p1)
    for (int p2 = -5; p2 <= 5; ++p2) {
      const double r = dx * std::sqrt(double(p1 * p1 + p2 * p2));
      if (r > 0 && r < sim.scene().R()) lattice += dx * dx * -W.derivative(r) / r;
    }
  const double Bk = 2 * (1e-6 + nuT / 1.0) * lattice, Be = 2 * (1e-6 + nuT / 1.3) * lattice;
  const double k1 = (k0 + dt * (P + Bk * k0)) / (1 + dt * (e0 / k0 + Bk));
  const double e1 = (e0 + dt * (1.44 * e0 / k0 * P + Be * e0)) / (1 + dt * (1.92 * e0 / k0 + Be));
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
  auto hk = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::TurbulentKineticEnergy{}));
  auto he = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::DissipationRate{}));
  auto hn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::EddyViscosity{}));
  const double R = sim.scene().R();
  int interior = 0;
  double wk = 0, we = 0, wn = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (hx(i, 0) < 4 * R || hx(i, 0) > 1 - 4 * R || hx(i, 1) < 2 * R || hx(i, 1) > 0.5 - 2 * R) continue;
    ++interior;
    wk = std::max(wk, std::abs(hk(i) / k1 - 1));
    we = std::max(we, std::abs(he(i) / e1 - 1));
    wn = std::max(wn, std::abs(hn(i) / (0.09 * k0 * k0 / e0) - 1));  // the step's nu_T: of k0, eps0
  }
  INFO("dt " << dt << ", k1 " << k1 << ", eps1 " << e1 << "; worst relative: k " << wk << ", eps " << we << ", nu_T " << wn);
  CHECK(interior > 50);
  CHECK(k1 > k0 * (1 + 1e-6));  // it grows: P / eps = C_mu (k a / eps)^2 = 9 a^2 / 4
  // the free edges' pressure and viscous terms reach the middle through the step's four stages
  // and the update's own support (5 R in all, more than the block's half height); at 4 R from the
  // ends and 2 R from the free surfaces: 2e-8 measured (at 3 R from the ends, 6e-5)
  CHECK(wk < 1e-6);
  CHECK(we < 1e-6);
  CHECK(wn < 1e-12);
}

}  // namespace

TEST_CASE("k-epsilon: in homogeneous shear k and epsilon grow by their production and destruction alone", "[turbulence]") {
  check_homogeneous_shear(2.0);  // P = 9 epsilon: below Menter's limit
}

TEST_CASE("k-epsilon: Menter's limiter caps the production at 10 epsilon in a strong shear", "[turbulence]") {
  check_homogeneous_shear(4.0);  // C_mu k^2 / epsilon a^2 = 36 epsilon, limited to 10 epsilon
}

TEST_CASE("k-epsilon: the wall function's k and epsilon give the law's eddy viscosity kappa u_* y", "[unit][turbulence]") {
  // k = u_*^2 / sqrt(C_mu), epsilon = u_*^3 / (kappa y) in the log layer: C_mu k^2 / epsilon = kappa u_* y
  KEpsilonConstants c;
  Kokkos::View<double*, MemSpace> k("k", 1), e("e", 1), dk("dk", 1), de("de", 1), us("us", 1), yp("yp", 1);
  Kokkos::deep_copy(k, 1.0);
  Kokkos::deep_copy(e, 1.0);
  Kokkos::deep_copy(us, 0.05);
  Kokkos::deep_copy(yp, 0.02 * 0.05 / 1e-6);  // y = 0.02 m
  KEpsilonUpdate<2> update{c, 0.41, 1e-6, 11.06, 0.0, k, e, dk, de, us, yp};
  Kokkos::parallel_for(1, update);
  auto hk = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), k);
  auto he = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), e);
  CHECK(0.09 * hk(0) * hk(0) / he(0) == Approx(0.41 * 0.05 * 0.02).epsilon(1e-12));
}
