// The impermeability guard of the NFM walls (kernels/WallImpermeability.hpp): paths
// that cross a wall over a step are mirrored back, with the velocity into the wall
// removed; paths that do not cross are left bit for bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "kernels/WallImpermeability.hpp"
#include "solver/WallModel.hpp"

using namespace ondine;

namespace {

// The floor y = 0 (x from 0 to 1) and the left wall x = 0 (y from 0 to 1) of a tank:
// n_in = (0, 1) and (1, 0). Wall 0 moves with `floor_velocity`.
struct Guard {
  WallFacets<2> seg;
  Kokkos::View<double* [2], Kokkos::LayoutLeft, MemSpace> wall_velocity{"wv", 2};
  field_view_t<field::Position, 2> x0{"x0", 1}, x{"x", 1};
  field_view_t<field::Velocity, 2> u{"u", 1};
  explicit Guard(double floor_vy = 0.0, double floor_vx = 0.0) {
    seg.a = decltype(seg.a)("a", 2);
    seg.b = decltype(seg.b)("b", 2);
    seg.n_in = decltype(seg.n_in)("n", 2);
    seg.wall = decltype(seg.wall)("w", 2);
    seg.count = 2;
    auto a = Kokkos::create_mirror_view(seg.a), b = Kokkos::create_mirror_view(seg.b), n = Kokkos::create_mirror_view(seg.n_in);
    auto w = Kokkos::create_mirror_view(seg.wall);
    auto wv = Kokkos::create_mirror_view(wall_velocity);
    a(0, 0) = 0; a(0, 1) = 0; b(0, 0) = 1; b(0, 1) = 0; n(0, 0) = 0; n(0, 1) = 1; w(0) = 0;
    a(1, 0) = 0; a(1, 1) = 1; b(1, 0) = 0; b(1, 1) = 0; n(1, 0) = 1; n(1, 1) = 0; w(1) = 1;
    wv(0, 0) = floor_vx; wv(0, 1) = floor_vy; wv(1, 0) = 0; wv(1, 1) = 0;
    Kokkos::deep_copy(seg.a, a); Kokkos::deep_copy(seg.b, b); Kokkos::deep_copy(seg.n_in, n);
    Kokkos::deep_copy(seg.wall, w); Kokkos::deep_copy(wall_velocity, wv);
  }
  // one particle from p0 to p1 with velocity v over dt; returns the count and the result
  long step(std::vector<double> p0, std::vector<double> p1, std::vector<double> v, double dt,
            std::vector<double>& p_out, std::vector<double>& v_out) {
    auto h0 = Kokkos::create_mirror_view(x0), h1 = Kokkos::create_mirror_view(x), hu = Kokkos::create_mirror_view(u);
    for (int k = 0; k < 2; ++k) { h0(0, k) = p0[k]; h1(0, k) = p1[k]; hu(0, k) = v[k]; }
    Kokkos::deep_copy(x0, h0); Kokkos::deep_copy(x, h1); Kokkos::deep_copy(u, hu);
    PeriodicBox<2> box{{0, 0}, {2, 2}, {false, false}};
    const long c = WallImpermeability<2>{seg, make_facet_cells<2>(box, 0.5, seg), wall_velocity, dt, box, x0, x, u}.run(1);
    Kokkos::deep_copy(h1, x); Kokkos::deep_copy(hu, u);
    p_out = {h1(0, 0), h1(0, 1)};
    v_out = {hu(0, 0), hu(0, 1)};
    return c;
  }
};

}  // namespace

TEST_CASE("Impermeability guard: a path through the floor is mirrored back", "[unit][nfm]") {
  Guard g;
  std::vector<double> p, v;
  CHECK(g.step({0.5, 0.01}, {0.52, -0.03}, {0.2, -0.4}, 0.1, p, v) == 1);
  CHECK(p[0] == Approx(0.52).margin(1e-15));
  CHECK(p[1] == Approx(0.03).margin(1e-15));
  CHECK(v[0] == Approx(0.2).margin(1e-15));  // the tangential velocity is kept
  CHECK(v[1] == Approx(0.0).margin(1e-15));  // the velocity into the wall is removed
}

TEST_CASE("Impermeability guard: a path through a corner is mirrored across both walls", "[unit][nfm]") {
  Guard g;
  std::vector<double> p, v;
  // the corner particle of the near-wall start: diagonally out of the corner
  CHECK(g.step({0.001, 0.001}, {-0.002, -0.003}, {-0.03, -0.04}, 0.1, p, v) == 1);
  CHECK(p[0] == Approx(0.002).margin(1e-12));
  CHECK(p[1] == Approx(0.003).margin(1e-12));
  CHECK(v[0] == Approx(0.0).margin(1e-15));
  CHECK(v[1] == Approx(0.0).margin(1e-15));
}

TEST_CASE("Impermeability guard: paths that stay in the fluid are untouched", "[unit][nfm]") {
  Guard g;
  std::vector<double> p, v;
  CHECK(g.step({0.5, 0.01}, {0.6, 0.001}, {1.0, -0.09}, 0.1, p, v) == 0);
  CHECK(p[0] == 0.6);
  CHECK(p[1] == 0.001);
  CHECK(v[1] == -0.09);
  // beyond the end of the floor segment (x > 1): no wall there
  CHECK(g.step({1.1, 0.01}, {1.1, -0.01}, {0.0, -0.2}, 0.1, p, v) == 0);
  // a particle already behind the wall at the start of the step is not the guard's to move
  CHECK(g.step({0.5, -0.01}, {0.5, -0.02}, {0.0, -0.1}, 0.1, p, v) == 0);
}

TEST_CASE("Impermeability guard: a rising floor pushes a resting particle up", "[unit][nfm]") {
  Guard g(0.5);  // the floor (given at its end-of-step position y = 0) rose 0.05 over dt = 0.1
  std::vector<double> p, v;
  // a particle 0.01 above the floor at the start of the step (0.06 above the floor's start
  // position moved by u_w dt) ends 0.02 below it: mirrored, it takes the floor's velocity
  CHECK(g.step({0.5, 0.01}, {0.5, -0.02}, {0.0, 0.0}, 0.1, p, v) == 1);
  CHECK(p[1] == Approx(0.02).margin(1e-15));
  CHECK(v[1] == Approx(0.5).margin(1e-15));
}

TEST_CASE("Impermeability guard: a sliding wall still closes its corner", "[unit][nfm]") {
  // the floor slides along itself at -1 m/s (a cavity lid): its segment stays in place, so
  // a path out through the corner must be caught (shifting the start by the sliding
  // velocity, -0.1 m over the step, put the crossing past the floor's end: a lid-corner leak)
  Guard g(0.0, -1.0);
  std::vector<double> p, v;
  CHECK(g.step({0.001, 0.001}, {-0.002, -0.003}, {-0.03, -0.04}, 0.1, p, v) == 1);
  CHECK(p[0] == Approx(0.002).margin(1e-12));
  CHECK(p[1] == Approx(0.003).margin(1e-12));
  CHECK(v[0] == Approx(0.0).margin(1e-15));
  CHECK(v[1] == Approx(0.0).margin(1e-15));  // the velocity into each wall, relative to it, is removed
}
