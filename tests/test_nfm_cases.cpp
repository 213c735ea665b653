// NFM wall cases at CI resolution (cases/*.yaml with coarser overrides where
// noted); the full-resolution runs belong to the validation suite.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "scene/CaseFile.hpp"
#include "reference/References.hpp"
#include "observers/ErrorNorms.hpp"
#include "solver/Simulation.hpp"
#include "solver/WallFluxDispatch.hpp"
#include "test_helpers.hpp"

using namespace ondine;

namespace {
const std::string src = ONDINE_SOURCE_DIR;

Simulation<2> run_case(const std::string& name, const std::vector<std::string>& sets) {
  Simulation<2> sim(load_case(src + "/cases/" + name, sets));
  const double T = sim.scene().duration;
  while (sim.time() < T * (1 - 1e-12)) sim.step(T);
  return sim;
}
}  // namespace

TEST_CASE("The fill leaves no particle inside a wall or closer than dx/2 to one", "[nfm][fill]") {
  for (const char* c : {"hydrostatic_tank_2d.yaml", "polygon_body_2d.yaml", "dam_break_2d.yaml", "poiseuille_2d.yaml"}) {
    Simulation<2> sim(load_case(src + "/cases/" + c));
    INFO(c << ": " << sim.size() << " particles");
    CHECK(sim.size() > 100);
    CHECK(wall_leaks(sim, 0.5 * sim.scene().dx * (1 - 1e-6)) == 0);
  }
  // the body's inside is empty: 1 m x 0.8 m of water less the 0.03 m^2 body, at dx = 0.02
  Simulation<2> body(load_case(src + "/cases/polygon_body_2d.yaml"));
  CHECK(body.size() == 2000 - 75);
}

TEST_CASE("A block's cuts keep the lattice points on their fluid side, with walls or without", "[nfm][fill]") {
  // brute force: the block's lattice (k + 1/2) dx from its corner, kept where (x - p).n <= 0 for
  // every cut; the fill must keep exactly those, wall clearance aside
  auto expected = [](const FluidBlock& b, double dx, double clearance_x) {
    long n = 0;
    const long nx = std::lround((b.box.max[0] - b.box.min[0]) / dx), ny = std::lround((b.box.max[1] - b.box.min[1]) / dx);
    for (long i = 0; i < nx; ++i)
      for (long j = 0; j < ny; ++j) {
        const double x = b.box.min[0] + (i + 0.5) * dx, y = b.box.min[1] + (j + 0.5) * dx;
        bool in = x >= clearance_x;
        for (const FluidBlock::Cut& c : b.cuts) in = in && (x - c.point[0]) * c.normal[0] + (y - c.point[1]) * c.normal[1] <= 0;
        n += in;
      }
    return n;
  };
  auto check_sides = [](const Simulation<2>& sim) {
    const FluidBlock& b = sim.scene().blocks.front();
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Position{}));
    int wrong = 0;
    for (int i = 0; i < static_cast<int>(sim.size()); ++i)
      for (const FluidBlock::Cut& c : b.cuts) wrong += (x(i, 0) - c.point[0]) * c.normal[0] + (x(i, 1) - c.point[1]) * c.normal[1] > 0;
    return wrong;
  };
  // the triangular water column (walls: the wall x = 0, 0.05 m from the wedge's tip, and the floor)
  Simulation<2> wedge(load_case(src + "/cases/wedge_impact_2d.yaml", {"discretisation.dx=0.25"}));
  const FluidBlock& b = wedge.scene().blocks.front();
  REQUIRE(b.cuts.size() == 1);
  CHECK(std::abs(b.cuts[0].normal[0] * b.cuts[0].normal[0] + b.cuts[0].normal[1] * b.cuts[0].normal[1] - 1.0) < 1e-12);
  CHECK(static_cast<long>(wedge.size()) == expected(b, 0.25, 0.125));
  CHECK(check_sides(wedge) == 0);
  // the wedge's area 20 x 15 less the triangle 15 x 15 tan(10 deg) / 2, within the staircase's dx / 2 per row
  const double area = 20.0 * 15.0 - 0.5 * 15.0 * 15.0 * std::tan(10.0 * M_PI / 180.0);
  CHECK(std::abs(wedge.size() * 0.25 * 0.25 - area) < 60 * 0.5 * 0.25 * 0.25);
  // no walls (every axis periodic): the cut alone, half of the Taylor-Green box
  Simulation<2> half(load_case(src + "/cases/taylor_green_2d.yaml",
                               {"discretisation.dx=0.05", "fluid_blocks.0.cut=[{point: [0.5, 0.51], normal: [1.0, 1.0]}]"}));
  CHECK(static_cast<long>(half.size()) == expected(half.scene().blocks.front(), 0.05, -1.0));
  CHECK(half.size() > 200);
  CHECK(half.size() < 230);
  CHECK(check_sides(half) == 0);
}

TEST_CASE("The star's fill and crossing count: fluid beside an acute tip is fluid", "[nfm][fill]") {
  // cases/star_body_2d.yaml at dx = 0.02: its 46-degree tips are narrower than dx over their
  // last 0.025 m, so a point beside one face lies within dx behind the other. Only the exact
  // side test (crossing number) may decide for a closed wall.
  Simulation<2> sim(load_case(src + "/cases/star_body_2d.yaml", {"discretisation.dx=0.02"}));
  const Scene& scene = sim.scene();
  const auto& star = scene.walls[1].points;
  auto in_star = [&](double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = star.size() - 1; i < star.size(); j = i++)
      if ((star[i][1] > y) != (star[j][1] > y) &&
          x < (star[j][0] - star[i][0]) * (y - star[i][1]) / (star[j][1] - star[i][1]) + star[i][0])
        in = !in;
    return in;
  };
  auto distance = [&](double x, double y) {
    double d = 1e9;
    for (std::size_t i = 0; i < star.size(); ++i) {
      const auto& a = star[i];
      const auto& b = star[(i + 1) % star.size()];
      const double tx = b[0] - a[0], ty = b[1] - a[1];
      const double s = std::clamp(((x - a[0]) * tx + (y - a[1]) * ty) / (tx * tx + ty * ty), 0.0, 1.0);
      d = std::min(d, std::hypot(x - a[0] - s * tx, y - a[1] - s * ty));
    }
    return d;
  };
  // the fill against brute force: every lattice point of the tank outside the star, dx/2 from it
  const double dx = scene.dx;
  std::size_t expected = 0;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      if (!in_star(x, y) && distance(x, y) >= 0.5 * dx) ++expected;
    }
  CHECK(sim.size() == expected);
  CHECK(wall_leaks(sim, 0.0) == 0);
  // three particles moved next to the top tip (0.5, 0.65): beside its right face (fluid); on
  // the tip's axis inside it (crossed); 0.05 dx above it (fluid, within 0.1 dx of a wall)
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Position{}));
  // the right face runs from vertex 9 to the tip, vertex 0; an eighth of the way from the tip the
  // arm is 0.46 dx across, and the point 0.3 dx off the right face is 0.67 dx behind the left one
  const auto &tip = star[0], &base = star[9];
  const double L = std::hypot(base[0] - tip[0], base[1] - tip[1]);
  const double nx = (tip[1] - base[1]) / L, ny = (base[0] - tip[0]) / L;  // outward normal of the face
  const double px = tip[0] + 0.125 * (base[0] - tip[0]) + 0.3 * dx * nx, py = tip[1] + 0.125 * (base[1] - tip[1]) + 0.3 * dx * ny;
  REQUIRE(!in_star(px, py));
  REQUIRE(distance(px, py) == Approx(0.3 * dx));
  x(0, 0) = px, x(0, 1) = py;
  x(1, 0) = 0.5, x(1, 1) = 0.64;
  x(2, 0) = 0.5, x(2, 1) = 0.65 + 0.05 * dx;
  Kokkos::deep_copy(sim.particles().get(field::Position{}), x);
  CHECK(wall_leaks(sim, 0.0) == 1);
  CHECK(wall_leaks(sim) == 2);  // and the one 0.1 dx above the tip
}

TEST_CASE("fluid_blocks[i].wall_clearance keeps lattice points 0.01 dx from the walls and in the corners", "[nfm][fill]") {
  const Scene scene = load_case(src + "/cases/near_wall_start_2d.yaml");
  Simulation<2> sim(scene);
  const double dx = scene.dx;
  // 20 x 10 lattice points, none dropped; the default clearance dx/2 drops the first row and both side columns
  CHECK(sim.size() == 200);
  CHECK(Simulation<2>(load_case(src + "/cases/near_wall_start_2d.yaml", {"fluid_blocks.0.wall_clearance=0.5"})).size() == 18 * 9);
  // closer than 0.02 dx to a wall: the bottom row (20), the side columns (2 x 10), the two corner points counted twice
  CHECK(wall_leaks(sim, 0.02 * dx) == 20 + 2 * 10 - 2);
  CHECK(wall_leaks(sim, 0.0099 * dx) == 0);
}

TEST_CASE("Free-surface detection flags the top row of a still tank and nothing along the walls", "[nfm][free_surface]") {
  Simulation<2> sim(load_case(src + "/cases/hydrostatic_tank_2d.yaml"));
  update_free_surface(sim);
  const auto& p = sim.particles();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto fs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::FreeSurface{}));
  const double dx = sim.scene().dx, H = 0.5;
  int top = 0, wrong = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool top_row = x(i, 1) > H - dx;
    if (top_row) top += fs(i) > 0;
    else wrong += fs(i) > 0;
  }
  CHECK(top == 50);
  CHECK(wrong == 0);
}

TEST_CASE("Hydrostatic tank: pressure profile, rest and impermeability after 2 s", "[nfm][case][hydrostatic]") {
  Simulation<2> sim = run_case("hydrostatic_tank_2d.yaml", {});
  const auto e = reference_errors(sim);
  INFO("pressure_linf " << e.at("pressure_linf") << ", Ek/Ep " << e.at("kinetic_over_potential"));
  CHECK(e.at("pressure_linf") < 0.02);            // issue threshold: 2 % of rho g H away from the surface layer
  CHECK(e.at("kinetic_over_potential") < 1e-3);
  CHECK(wall_leaks(sim) == 0);
  // the force on the tank is the weight of the water (1000 x 9.81 x 0.5 N/m) within 2 %
  const auto f = wall_forces(sim);
  REQUIRE(f.size() == 1);
  CHECK(f[0].pressure[1] == Approx(-4905.0).epsilon(0.02));
  CHECK(std::abs(f[0].pressure[0]) < 1e-6 * 4905);
}

TEST_CASE("Polygonal body in a still tank: the force on it is the buoyancy", "[nfm][case][body]") {
  Simulation<2> sim = run_case("polygon_body_2d.yaml", {});
  const auto f = wall_forces(sim);
  REQUIRE(f.size() == 2);
  const double buoyancy = 1000 * 9.81 * 0.03;
  INFO("body force " << f[1].pressure[0] << ", " << f[1].pressure[1] << " against " << buoyancy);
  CHECK(f[1].pressure[1] == Approx(buoyancy).epsilon(0.03));
  CHECK(std::abs(f[1].pressure[0]) < 0.01 * buoyancy);
  CHECK(wall_leaks(sim) == 0);
}

TEST_CASE("Poiseuille flow between no-slip NFM walls follows the start-up solution", "[nfm][case][poiseuille]") {
  Simulation<2> sim = run_case("poiseuille_2d.yaml", {});  // L/25, t = 3 s
  const double l2 = reference_errors(sim).at("velocity_l2");
  INFO("velocity L2 error " << l2);
  CHECK(l2 < 0.01);
  CHECK(wall_leaks(sim) == 0);
  // wall shear: rho nu du/dy at the wall times the wall length, from the start-up series
  double dudy = 0.8 * 1.0 / (2 * 0.1);
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    dudy -= 4 * 0.8 / (0.1 * M_PI * M_PI * k * k) * std::exp(-k * k * M_PI * M_PI * 0.1 * 3.0);
  }
  const double expected = 1000 * 0.1 * dudy * 0.4;
  const auto f = wall_forces(sim);
  INFO("viscous force on the walls " << f[0].viscous[0] << ", " << f[1].viscous[0] << " against " << expected);
  CHECK(f[0].viscous[0] == Approx(expected).epsilon(0.1));
  CHECK(f[1].viscous[0] == Approx(expected).epsilon(0.2));
}

// Issue 4's convergence criterion (Poiseuille and start-up Couette at L/25 and L/50, order >= 1.5)
// is checked on the runs of `ondine validate --level quick` (CTest cli:validate_quick).

// scheme.consistent_laplacian: false gives the thesis' operator (4.84)-(4.85) back; its
// wall error is first order: 4.46e-3 at L/25 against 5.68e-4 (measured)
TEST_CASE("Poiseuille: scheme.consistent_laplacian false selects the thesis' wall Laplacian", "[nfm][case][poiseuille]") {
  const double consistent = reference_errors(run_case("poiseuille_2d.yaml", {})).at("velocity_l2");
  const double thesis = reference_errors(run_case("poiseuille_2d.yaml", {"scheme.consistent_laplacian=false"})).at("velocity_l2");
  INFO("velocity L2 error " << consistent << " (consistent), " << thesis << " (thesis)");
  CHECK(thesis > 3 * consistent);
  CHECK(thesis < 0.01);  // still within the issue's 1 %
}

// The start-up Couette series (reference/References): the wall values, the steady limit, the
// fluid at rest at t = 0, and the diffusion equation u_t = nu u_yy it solves (central differences)
TEST_CASE("Start-up Couette reference: wall values, limits and the diffusion equation", "[unit][reference]") {
  const double L = 1, V0 = 1, nu = 0.1;
  for (double t : {0.01, 0.3, 1.0}) {
    CHECK(reference::couette_startup(0, t, L, V0, nu) == Approx(0).margin(1e-14));
    CHECK(reference::couette_startup(L, t, L, V0, nu) == Approx(V0).margin(1e-14));
  }
  for (double y : {0.1, 0.37, 0.5, 0.9}) {
    CHECK(reference::couette_startup(y, 100.0, L, V0, nu) == Approx(V0 * y / L).margin(1e-14));  // steady
    CHECK(std::abs(reference::couette_startup(y, 0.0, L, V0, nu)) < 1e-3);  // at rest (series truncated)
    const double t = 0.3, ht = 1e-4, hy = 1e-3;
    const double ut = (reference::couette_startup(y, t + ht, L, V0, nu) - reference::couette_startup(y, t - ht, L, V0, nu)) / (2 * ht);
    const double uyy = (reference::couette_startup(y + hy, t, L, V0, nu) - 2 * reference::couette_startup(y, t, L, V0, nu) +
                        reference::couette_startup(y - hy, t, L, V0, nu)) / (hy * hy);
    INFO("y = " << y << ": u_t " << ut << ", nu u_yy " << nu * uyy);
    CHECK(ut == Approx(nu * uyy).epsilon(1e-4));  // central differences: O(h^2) truncation, 1.4e-5 at y = 0.1
    CHECK(std::abs(ut) > 1e-3);  // the transient is still alive at t = 0.3 s
  }
}

// The NFM Morris Laplacian with its wall term (thesis 4.84-4.85), evaluated by
// the solver's own kernels: with rho = rho0 (P = 0), a tangential velocity
// u_x = f(y) and a no-slip floor at rest (f(0) = 0), the pressure and wall-flux
// terms vanish and du_x/dt = nu L(f). The continuous operator is exact for
// fields varying only normal to the wall (nfm.md §8: L(y) = 0, L(y^2) = 2);
// the discrete one approaches it as R/dx grows (thesis Fig. 4.10).
TEST_CASE("NFM Laplacian is exact for linear and quadratic fields near a no-slip wall", "[nfm][laplacian]") {
  // the operator of viscous scenes with no-slip walls (kernels/ConsistentLaplacian.hpp), through
  // the solver's kernels: du/dt = nu L(u) with nu = 1, no gravity, u = f(x, y) along x
  // (the wall is at rest: the fields are those that vanish on it, y, y^2 and xy;
  // an int, not a local enum, because nvcc refuses a function-local type in a device lambda)
  constexpr int kY = 0, kY2 = 1, kXY = 2;
  auto worst_error = [](double R_over_dx, int field) {
    const std::string y = R"(dimension: 2
domain: {min: [0, -0.1], max: [1, 1], periodic: [true, false]}
fluid: {rho0: 1000, sound_speed: 10, viscosity: 1.0}
discretisation: {dx: 0.02, R_over_dx: )" + std::to_string(R_over_dx) + R"(, neighbour_skin: 0}
walls: [{points: [[0, 0], [1, 0]], fluid_side: left, condition: no_slip}]
fluid_blocks: [{min: [0, 0], max: [1, 0.6]}]
scheme: {viscous_term: morris}
time: {duration: 1, output_interval: 1})";
    Simulation<2> sim(parse_case(y, "laplacian.yaml"));
    auto& p = sim.particles();
    const auto x = p.get(field::Position{});
    const auto u = p.get(field::Velocity{});
    // xy is centred in the periodic box so that the field is smooth where it is tested
    Kokkos::parallel_for(static_cast<int>(p.size()), KOKKOS_LAMBDA(int i) {
      const double X = x(i, 0) - 0.5, Y = x(i, 1);
      u(i, 0) = field == 0 ? Y : field == 1 ? Y * Y : X * Y;  // kY, kY2, kXY
      u(i, 1) = 0.0;
    });
    sim.evaluate();
    auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
    auto ha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Acceleration{}));
    const double exact = field == kY2 ? 2.0 : 0.0, R = sim.scene().R();
    double worst = 0;
    for (std::size_t i = 0; i < p.size(); ++i)  // particles within R of the wall, away from the seam of xy
      if (hx(i, 1) < R && std::abs(hx(i, 0) - 0.5) < 0.3) worst = std::max(worst, std::abs(ha(i, 0) - exact));
    return worst;
  };
  // Without the consistent weights (the plain NFM operator 4.85, as in the thesis): L(y) 1.93, 1.28,
  // 0.54 and L(y^2) 0.068, 0.034, < 0.01 at R/dx = 3, 4, 6; the continuous operator itself gives
  // L(x^2) = 5.07 at d = 0.1 R (nfm.md section 8). Now exact to round-off at every R/dx.
  for (int f : {kY, kY2, kXY})
    for (double rdx : {3.0, 4.0, 6.0}) {
      const double e = worst_error(rdx, f);
      INFO("field " << f << ", R/dx = " << rdx << ": max error " << e);
      CHECK(e < 1e-9);
    }
}

// The bound over all directions that lets the density-gradient pass skip its pair-by-pair check
// of the consistent Laplacian's weights (kernels/ConsistentLaplacian.hpp, within_bounds): where it
// holds, every weight s(x) = (x.A.x + b.x) / |x|^2 at |x| >= r_min lies within [0, s_max]
// (sampled densely, with the nearest distance itself); it holds for the plain operator's weights
template <int D>
static void check_weight_bound() {
  using Basis = LaplacianBasis<D>;
  constexpr int K = Basis::K;
  struct Weights {
    double v[K];
    double operator()(int, int p) const { return v[p]; }
  };
  std::mt19937_64 rng(17 + D);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double s_max = Basis::max_weight;
  Weights plain{};
  for (int p = 0; p < D; ++p) plain.v[p] = 1.0;
  CHECK(Basis::within_bounds(plain, 0, 0.5, s_max));
  CHECK_FALSE(Basis::within_bounds(plain, 0, 0.0, s_max));  // a coincident point: no bound
  int held = 0, failed = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Weights w{};
    for (int p = 0; p < K; ++p) w.v[p] = p < D ? 1.0 + 0.8 * U(rng) : 0.3 * U(rng);
    const double r_min = 0.05 + 0.5 * (U(rng) + 1.0);
    if (!Basis::within_bounds(w, 0, r_min, s_max)) continue;
    ++held;
    for (int k = 0; k < 200; ++k) {
      Vec<D> x;
      double n2 = 0;
      for (int a = 0; a < D; ++a) n2 += (x[a] = U(rng)) * x[a];
      const double r = r_min * (k < 50 ? 1.0 : 1.0 + 3.0 * (U(rng) + 1.0));
      for (int a = 0; a < D; ++a) x[a] *= r / std::sqrt(n2);
      const double s = Basis::weight(w, 0, x);
      if (!(s >= 0.0 && s <= s_max)) ++failed;
    }
  }
  INFO("D = " << D << ": the bound held in " << held << " of 4000 random weight sets");
  CHECK(held > 400);  // the test is not vacuous
  CHECK(failed == 0);
}

TEST_CASE("The consistent Laplacian's bound over all directions holds every pair's weight within bounds", "[nfm][laplacian][unit]") {
  check_weight_bound<2>();
  check_weight_bound<3>();
}

// Regression for the background-pressure correction (2.105) next to NFM walls:
// without its wall term the cavity lost 248 particles through the lid corners
// within 1 s; with it none leaves the domain and the density stays within 1 %.
// Still open: 4 of the 2500 particles are found less than dx behind the moving lid
// at t = 1 (docs/validation.md); the bound below guards against a regression.
TEST_CASE("Lid-driven cavity with the background-pressure correction keeps its particles", "[nfm][case][cavity]") {
  Simulation<2> sim = run_case("lid_driven_cavity_2d.yaml", {"time.duration=1"});
  const Diagnostics d = diagnostics(sim);
  CHECK(d.finite);
  CHECK(d.outside_domain == 0);
  CHECK(wall_leaks(sim, 0.0) <= 4);
  CHECK(d.rho_max < 1.01);
  CHECK(d.rho_min > 0.99);
}

TEST_CASE("The wall contact theta_q: 1 under water in contact, 0 across a gap wider than R", "[nfm][wall_contact]") {
  // a still tank: every wall point under the water sees a lattice in contact
  {
    Simulation<2> sim(load_case(src + "/cases/hydrostatic_tank_2d.yaml"));
    sim.evaluate();  // the lists
    const PassContext<2> c = sim.context(sim.levels().front());
    auto theta = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), wall_contact<2, WendlandC2<2>>(c));
    auto xq = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), c.wall.x);
    const FluidBlock& b = sim.scene().blocks.front();
    double lo = 2, hi = 0;
    int n = 0;
    for (int q = 0; q < static_cast<int>(theta.extent(0)); ++q)
      if (xq(q, 1) < b.box.max[1] - sim.R()) {  // below the surface by more than R
        lo = std::min(lo, theta(q)), hi = std::max(hi, theta(q));
        ++n;
      }
    INFO(n << " wall points under water: theta in [" << lo << ", " << hi << "]");
    CHECK(n > 20);
    CHECK(lo > 0.95);  // the lattice's Shepard sum at the wall against the geometry's gamma, corners included
    CHECK(hi <= 1.0);
  }
  // the triangular column before the impact: the wall x = 0 faces a gap 0.05 + y tan(10 deg)
  {
    Simulation<2> sim(load_case(src + "/cases/wedge_impact_2d.yaml", {"discretisation.dx=0.25"}));
    sim.evaluate();
    const PassContext<2> c = sim.context(sim.levels().front());
    auto theta = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), wall_contact<2, WendlandC2<2>>(c));
    auto xq = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), c.wall.x);
    const double R = sim.R(), tb = std::tan(10.0 * M_PI / 180.0);
    int beyond = 0, half = 0, near = 0;
    for (int q = 0; q < static_cast<int>(theta.extent(0)); ++q) {
      if (std::abs(xq(q, 0)) > 1e-9 || xq(q, 1) > 15.0) continue;  // the wall x = 0 beside the column
      const double gap = 0.05 + xq(q, 1) * tb;                     // to the free surface (the particles are dx/2 further)
      INFO("y = " << xq(q, 1) << ", gap " << gap << ", theta " << theta(q));
      if (gap > R) {
        CHECK(theta(q) == 0.0);
        ++beyond;
      } else if (gap > 0.5 * R) {
        CHECK(theta(q) < 0.5);
        ++half;
      } else if (gap < 0.25 * R) {
        CHECK(theta(q) > 0.0);
        ++near;
      }
    }
    CHECK(beyond > 10);
    CHECK(half > 5);
    CHECK(near >= 2);
  }
}
