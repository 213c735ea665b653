// NFM walls in 3D at CI resolution (cases/*_3d.yaml with coarser overrides where noted; the
// full-resolution runs belong to the validation suite): the fill against a box tank, an
// obstacle and an STL tank, still water, the buoyancy of an immersed body and a laminar duct.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

#include "observers/ErrorNorms.hpp"
#include "reference/References.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Measures.hpp"
#include "solver/Simulation.hpp"
#include "test_helpers.hpp"

using namespace ondine;

namespace {
const std::string src = ONDINE_SOURCE_DIR;

Simulation<3> run_case(const std::string& name, const std::vector<std::string>& sets) {
  Simulation<3> sim(load_case(src + "/cases/" + name, sets));
  const double T = sim.scene().duration;
  while (sim.time() < T * (1 - 1e-12)) sim.step(T);
  return sim;
}
}  // namespace

TEST_CASE("3D fill: a box tank keeps its whole lattice, an obstacle box removes its own", "[nfm3d][fill]") {
  // 1 x 1 x 1 m of water at dx = 0.1 in the 1 x 1 x 2 tank: 10^3 points, none within dx/2 of a wall
  Simulation<3> tank(load_case(src + "/cases/hydrostatic_tank_3d.yaml", {"discretisation.dx=0.1"}));
  CHECK(tank.size() == 1000);
  CHECK(wall_leaks(tank, 0.5 * 0.1 * (1 - 1e-6)) == 0);
  // 1 x 1 x 0.8 m of water at dx = 0.05 (20 x 20 x 16) less the 0.2 m cube's 4 x 4 x 4 points
  Simulation<3> body(load_case(src + "/cases/immersed_box_3d.yaml"));
  CHECK(body.size() == 20 * 20 * 16 - 64);
  CHECK(wall_leaks(body, 0.5 * 0.05 * (1 - 1e-6)) == 0);
}

TEST_CASE("3D walls: the Shepard factor of a still tank's particles is the analytical one", "[nfm3d][gamma]") {
  // at rest on the lattice, a particle at distance d from one face (and farther than R from
  // the others) has gamma = 1 - (1 - q)^6 (1 + 3q + 3q^2) / 2, q = d / R (nfm.md §7)
  Simulation<3> sim(load_case(src + "/cases/hydrostatic_tank_3d.yaml", {"discretisation.dx=0.1"}));
  update_free_surface(sim);
  const auto& p = sim.particles();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::ShepardGamma{}));
  const double R = sim.R();
  int checked = 0;
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double d = x(i, 2);  // distance to the floor
    bool far = d < R;
    for (int k = 0; k < 2; ++k) far = far && x(i, k) > R && x(i, k) < 1 - R;
    if (!far) continue;
    const double q = d / R;
    worst = std::max(worst, std::abs(g(i) - (1 - 0.5 * std::pow(1 - q, 6) * (1 + 3 * q + 3 * q * q))));
    ++checked;
  }
  INFO(checked << " particles, worst " << worst);
  CHECK(checked > 0);
  CHECK(worst < 1e-9);
}

TEST_CASE("3D hydrostatic tank (coarse): pressure profile, rest and no leak", "[nfm3d][case][hydrostatic]") {
  // dx = 0.1 m: R = 0.25 m is a quarter of the tank, 10 layers of water. The worst particle is
  // measured 3.8 % off (the case file's hydrostatic delta-SPH form; 6.7 % with the thesis' form);
  // the thesis' resolution (dx = 0.04 m, 5 s undamped) is a validation case
  // (ondine validate --case hydrostatic_tank_3d). The bounds are regression guards.
  Simulation<3> sim = run_case("hydrostatic_tank_3d.yaml", {"discretisation.dx=0.1", "time.duration=1.0", "time.damping=0.5"});
  const auto e = reference_errors(sim);
  INFO("pressure_linf " << e.at("pressure_linf") << ", Ek/Ep " << e.at("kinetic_over_potential"));
  CHECK(e.at("pressure_linf") < 0.08);
  CHECK(e.at("kinetic_over_potential") < 1e-3);
  CHECK(wall_leaks(sim) == 0);
  // the force on the tank is the weight of the water (1000 x 9.81 x 1 m^3): measured 0.65 % low
  const auto f = wall_forces(sim);
  REQUIRE(f.size() == 1);
  INFO("force on the tank " << f[0].pressure[0] << ", " << f[0].pressure[1] << ", " << f[0].pressure[2]);
  CHECK(f[0].pressure[2] == Approx(-9810.0).epsilon(0.04));
  CHECK(std::abs(f[0].pressure[0]) < 2e-3 * 9810);
  CHECK(std::abs(f[0].pressure[1]) < 2e-3 * 9810);
  // its moment about the origin: the weight acts at (0.5, 0.5) and the side walls' pushes cancel,
  // M = (0.5 F_z, -0.5 F_z, 0)
  INFO("moment " << f[0].moment[0] << ", " << f[0].moment[1] << ", " << f[0].moment[2]);
  CHECK(f[0].moment[0] == Approx(0.5 * f[0].pressure[2]).epsilon(0.01));
  CHECK(f[0].moment[1] == Approx(-0.5 * f[0].pressure[2]).epsilon(0.01));
  CHECK(std::abs(f[0].moment[2]) < 2e-3 * 9810);
}

TEST_CASE("Wall sensors of still water read rho g (H - z) on the floor and a side wall, 0 where dry", "[nfm3d][case][wall_sensor]") {
  // The 3D tank at dx = 0.1 m (H = 1 m, c0 = 30 m/s), damped to rest as above, with wall sensors
  // added: the floor's centre (a point and a 0.2 m face), a side wall at mid-depth (z = 0.5 m, 2.5 R
  // from the floor and the surface) and the dry wall above the water (z = 1.5 m).
  const std::string path = "/tmp/ondine_wall_sensors_" + std::to_string(::getpid()) + ".yaml";
  {
    std::ifstream in(src + "/cases/hydrostatic_tank_3d.yaml");
    std::ofstream out(path);
    for (std::string line; std::getline(in, line);) out << line << "\n";
    out << "wall_sensors:\n"
           "  - {name: floor, position: [0.5, 0.5, 0.0], normal: [0, 0, -1]}\n"
           "  - {name: floor_face, position: [0.5, 0.5, 0.0], normal: [0, 0, -1], size: 0.2}\n"
           "  - {name: side, position: [0.0, 0.5, 0.5], normal: [-2, 0, 0], size: 0.01}\n"
           "  - {name: dry, position: [1.0, 0.5, 1.5], normal: [1, 0, 0], size: 0.01}\n";
  }
  Simulation<3> sim(load_case(path, {"discretisation.dx=0.1", "time.duration=1.0", "time.damping=0.5"}));
  std::remove(path.c_str());
  while (sim.time() < 1.0 - 1e-12) sim.step(1.0);
  const std::vector<double> p = wall_sensor_pressures(sim);
  REQUIRE(p.size() == 4);
  const double rg = 1000.0 * 9.81;
  INFO("floor " << p[0] << ", floor face " << p[1] << ", side " << p[2] << ", dry " << p[3] << " Pa");
  // the floor at depth H: within 3 % (the tank's total force is 0.65 % low at this resolution;
  // measured 0.6 % high; 1.2 % low with the thesis' delta-SPH form)
  CHECK(p[0] == Approx(rg * 1.0).epsilon(0.03));
  // a 0.2 m face on a uniform load reads its centre's value
  CHECK(p[1] == Approx(p[0]).epsilon(0.01));
  // mid-depth on a side wall (the normal given unnormalised): rho g H / 2 within 8 %, the bound of
  // the pressure field itself at this resolution (above; its worst particles are the walls' and
  // edges'); measured 3.4 % low (5.9 % with the thesis' delta-SPH form)
  CHECK(p[2] == Approx(rg * 0.5).epsilon(0.08));
  CHECK(p[3] == 0.0);
}

TEST_CASE("3D walls from an STL file: the same Shepard factor as the box primitive", "[nfm3d][stl]") {
  // cases/meshes/tank_1x1x2.stl is the 1 x 1 x 2 box with its faces cut along the other
  // diagonals: the analytical gamma must not depend on the triangulation (to round-off)
  Simulation<3> box(load_case(src + "/cases/hydrostatic_tank_3d.yaml", {"discretisation.dx=0.1"}));
  Simulation<3> stl(load_case(src + "/cases/hydrostatic_tank_stl_3d.yaml", {"discretisation.dx=0.1"}));
  REQUIRE(box.size() == stl.size());
  update_free_surface(box);
  update_free_surface(stl);
  auto gb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), box.particles().get(field::ShepardGamma{}));
  auto gs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), stl.particles().get(field::ShepardGamma{}));
  double worst = 0, lowest = 1;
  for (std::size_t i = 0; i < box.size(); ++i) {
    worst = std::max(worst, std::abs(gb(i) - gs(i)));
    lowest = std::min(lowest, gb(i));
  }
  INFO("worst difference " << worst << ", lowest gamma " << lowest);
  CHECK(worst < 1e-12);
  CHECK(lowest < 0.5);  // the corner particles, 0.2 R from three faces, see the edges and corners of the mesh
}

TEST_CASE("3D free surface: the top layer of a still tank is flagged, nothing along the walls", "[nfm3d][free_surface]") {
  Simulation<3> sim(load_case(src + "/cases/hydrostatic_tank_3d.yaml", {"discretisation.dx=0.1"}));
  update_free_surface(sim);
  const auto& p = sim.particles();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto fs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::FreeSurface{}));
  int top = 0, wrong = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool top_layer = x(i, 2) > 1.0 - 0.1;
    if (top_layer && fs(i) > 0.5) ++top;
    if (!top_layer && x(i, 2) < 1.0 - 0.25 && fs(i) > 0.5) ++wrong;  // below the surface's support
  }
  INFO(top << " of 100 top-layer particles flagged, " << wrong << " flagged deeper");
  CHECK(top == 100);
  CHECK(wrong == 0);
}

// The laminar square duct at L/10 (velocity L2 < 1e-2 after 3 s, measured 6.9e-3, no leak) is
// checked on the run of `ondine validate --level quick` (CTest cli:validate_quick).

TEST_CASE("A rotating 3D wall: points, normals, velocities and the Shepard factor turn with it", "[nfm3d][motion]") {
  // the 1 x 1 x 2 tank turning about the vertical axis through (0.5, 0.3, 0) at 0.7 rad/s
  const std::string path = "/tmp/ondine_rotating_tank_" + std::to_string(::getpid()) + ".yaml";
  {
    std::ifstream in(src + "/cases/hydrostatic_tank_3d.yaml");
    std::ofstream out(path);
    for (std::string line; std::getline(in, line);) {
      out << line << "\n";
      if (line.find("condition: slip") != std::string::npos)
        out << "    motion: {type: rotation, centre: [0.5, 0.3, 0.0], axis: [0, 0, 2], angular_velocity: 0.7}\n";
    }
  }
  const Scene scene = load_case(path, {"discretisation.dx=0.1"});
  std::remove(path.c_str());
  REQUIRE(scene.walls[0].motion == WallMotion::Rotation);
  PeriodicBox<3> box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = scene.domain.min[k];
    box.len[k] = scene.domain.max[k] - scene.domain.min[k];
    box.periodic[k] = false;
  }
  const double R = 0.25, t = 0.9, th = 0.7 * t, c = std::cos(th), s = std::sin(th);
  const double hq = wall_quadrature_spacing<3>(scene, scene.dx);
  WallModel<3> still(scene, box, R, hq), turned(scene, box, R, hq);
  turned.move_to(t);
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), still.points().x);
  auto n0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), still.points().n_out);
  auto x1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), turned.points().x);
  auto n1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), turned.points().n_out);
  auto u1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), turned.points().u);
  double worst = 0;
  for (int q = 0; q < still.points().count; ++q) {
    const double rx = x0(q, 0) - 0.5, ry = x0(q, 1) - 0.3;
    const double ex = 0.5 + c * rx - s * ry, ey = 0.3 + s * rx + c * ry;
    worst = std::max({worst, std::abs(x1(q, 0) - ex), std::abs(x1(q, 1) - ey), std::abs(x1(q, 2) - x0(q, 2)),
                      std::abs(n1(q, 0) - (c * n0(q, 0) - s * n0(q, 1))), std::abs(n1(q, 1) - (s * n0(q, 0) + c * n0(q, 1))),
                      std::abs(u1(q, 0) + 0.7 * (ey - 0.3)), std::abs(u1(q, 1) - 0.7 * (ex - 0.5)), std::abs(u1(q, 2))});
  }
  INFO("worst deviation of points, normals, velocities " << worst);
  CHECK(worst < 1e-12);
  // gamma at points fixed to the tank: the same before and after the turn (facets and facet cells)
  const int n = 5;
  const double pts[n][3] = {{0.05, 0.05, 0.05}, {0.2, 0.9, 0.1}, {0.5, 0.5, 0.02}, {0.97, 0.4, 1.0}, {0.3, 0.3, 1.98}};
  field_view_t<field::Position, 3> xa("xa", n), xb("xb", n);
  Kokkos::View<double*, MemSpace> ga("ga", n), gb("gb", n);
  auto ha = Kokkos::create_mirror_view(xa), hb = Kokkos::create_mirror_view(xb);
  for (int i = 0; i < n; ++i) {
    const double rx = pts[i][0] - 0.5, ry = pts[i][1] - 0.3;
    ha(i, 0) = pts[i][0], ha(i, 1) = pts[i][1], ha(i, 2) = pts[i][2];
    hb(i, 0) = 0.5 + c * rx - s * ry, hb(i, 1) = 0.3 + s * rx + c * ry, hb(i, 2) = pts[i][2];
  }
  Kokkos::deep_copy(xa, ha);
  Kokkos::deep_copy(xb, hb);
  Kokkos::parallel_for(Kokkos::RangePolicy<ExecSpace>(0, n), ShepardGammaPass<3>{still.facets(), still.facet_cells(), R, box, xa, ga});
  Kokkos::parallel_for(Kokkos::RangePolicy<ExecSpace>(0, n), ShepardGammaPass<3>{turned.facets(), turned.facet_cells(), R, box, xb, gb});
  auto hga = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ga);
  auto hgb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), gb);
  for (int i = 0; i < n; ++i) {
    INFO("point " << i << ": gamma " << hga(i) << " still, " << hgb(i) << " turned");
    CHECK(hga(i) < 1.0);
    CHECK(std::abs(hga(i) - hgb(i)) < 1e-12);
  }
}
