// The reference solutions (src/reference/References.cpp) against their limits, and each
// error norm of src/observers/ErrorNorms*.{hpp,cpp} against a state whose error is known.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "observers/ChannelReference.hpp"
#include "observers/ErrorNorms.hpp"
#include "reference/References.hpp"
#include "reference/SensorSeries.hpp"
#include "reference/WedgeImpact.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using Catch::Matchers::Contains;

namespace {

Scene case_file(const std::string& name, const std::vector<std::string>& sets = {}) {
  return load_case(std::string(ONDINE_SOURCE_DIR) + "/cases/" + name, sets);
}

// sets the owned particles' velocity to f(x, y) (host mirror; tests only)
template <class F>
void set_velocity(Simulation<2>& sim, F&& f) {
  auto& p = sim.particles();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Velocity{}));
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const auto v = f(hx(i, 0), hx(i, 1));
    hu(i, 0) = v[0];
    hu(i, 1) = v[1];
  }
  Kokkos::deep_copy(p.get(field::Velocity{}), hu);
}

}  // namespace

TEST_CASE("Start-up Poiseuille: zero at t = 0 and on the walls, the parabola F y (L - y) / (2 nu) at large t", "[unit][reference]") {
  const double L = 1.0, F = 2e-3, nu = 1e-2;
  for (double y : {0.1, 0.3, 0.5, 0.9}) {
    CHECK(std::abs(reference::poiseuille_startup(y, 0.0, L, F, nu)) < 1e-6 * F * L * L / nu);
    CHECK(reference::poiseuille_startup(y, 1e4, L, F, nu) == Approx(F / (2 * nu) * y * (L - y)).epsilon(1e-12));
  }
  CHECK(reference::poiseuille_startup(0.0, 3.0, L, F, nu) == Approx(0.0).margin(1e-15));
  CHECK(reference::poiseuille_startup(0.25, 3.0, L, F, nu) == Approx(reference::poiseuille_startup(0.75, 3.0, L, F, nu)).epsilon(1e-12));
}

TEST_CASE("polygon_area: the shoelace area in either orientation", "[unit][reference]") {
  const std::vector<std::array<double, 2>> square = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const std::vector<std::array<double, 2>> reversed(square.rbegin(), square.rend());
  CHECK(reference::polygon_area(square) == Approx(2.0));
  CHECK(reference::polygon_area(reversed) == Approx(2.0));
  CHECK(reference::polygon_area({{0, 0}, {1, 0}, {0, 3}}) == Approx(1.5));
}

TEST_CASE("interpolate: linear between samples, held at the ends", "[unit][reference]") {
  const std::vector<std::pair<double, double>> s = {{0, 1}, {1, 3}, {3, 4}};
  CHECK(reference::interpolate(s, 0.5) == Approx(2.0));
  CHECK(reference::interpolate(s, 2.0) == Approx(3.5));
  CHECK(reference::interpolate(s, -1.0) == Approx(1.0));
  CHECK(reference::interpolate(s, 9.0) == Approx(4.0));
}

TEST_CASE("read_table: numeric rows, comments and the header skipped", "[unit][reference]") {
  const std::string path = "read_table_test.csv";
  {
    std::ofstream f(path);
    f << "# a comment\nx,y\n1,2.5\n# another\n3,-4e-3\n";
  }
  const auto rows = reference::read_table(path);
  std::remove(path.c_str());
  REQUIRE(rows.size() == 2);
  CHECK(rows[0] == std::vector<double>{1.0, 2.5});
  CHECK(rows[1] == std::vector<double>{3.0, -4e-3});
}

TEST_CASE("Martin & Moyce's front: Z = 1 at T = 0 and increasing", "[unit][reference]") {
  const auto& f = reference::martin_moyce_front();
  REQUIRE(f.size() > 10);
  for (std::size_t k = 1; k < f.size(); ++k) {
    CHECK(f[k].first > f[k - 1].first);
    CHECK(f[k].second >= f[k - 1].second);
  }
  CHECK(reference::interpolate(f, 0.0) == Approx(1.0).margin(0.02));
}

TEST_CASE("Error norms: Taylor-Green is exact at t = 0 and measures a known perturbation", "[unit][reference]") {
  Simulation<2> sim(case_file("taylor_green_2d.yaml", {"discretisation.dx=0.05"}));
  auto e = reference_errors(sim);
  CHECK(e.at("velocity_l2") < 1e-14);
  CHECK(e.at("velocity_linf") < 1e-14);
  CHECK(e.at("mass_drift") == 0.0);
  CHECK(e.at("momentum_balance_error") < 1e-14);
  // u + eps U along x everywhere: L2 = eps U sqrt(N) / sqrt(sum |u_exact|^2) = eps / rms(|u|/U) = eps sqrt(2)
  // (the rms of |u| over a whole period is U / sqrt(2)), Linf = eps
  const double U = sim.scene().blocks.front().tg_amplitude, k = 2 * M_PI / sim.scene().blocks.front().tg_wavelength, eps = 1e-3;
  set_velocity(sim, [&](double x, double y) {
    return std::array<double, 2>{-U * std::cos(k * x) * std::sin(k * y) + eps * U, U * std::sin(k * x) * std::cos(k * y)};
  });
  e = reference_errors(sim);
  CHECK(e.at("velocity_l2") == Approx(eps * std::sqrt(2.0)).epsilon(1e-6));
  CHECK(e.at("velocity_linf") == Approx(eps).epsilon(1e-9));
}

TEST_CASE("Error norms: the hydrostatic tank at rest is the hydrostatic pressure", "[unit][reference]") {
  Simulation<2> sim(case_file("hydrostatic_tank_2d.yaml"));
  const OutputFrame<2> frame(sim);
  const auto e = reference_errors(sim);
  CHECK(e.at("pressure_linf") < 1e-9);
  CHECK(e.at("pressure_layer_mean") < 1e-9);
  CHECK(e.at("kinetic_over_potential") == 0.0);
  CHECK(e.at("wall_leaks") == 0.0);
  CHECK(e.at("wall_crossings") == 0.0);
}

TEST_CASE("Error norms: a layer's mean pressure against the pointwise error", "[unit][reference]") {
  // every particle of the layer 0.2 <= y < 0.2 + dx alternately +3 % and -1 % of rho g H off the
  // hydrostatic pressure: pointwise 3 %; that layer's mean off by 1 % (equal counts of each sign)
  Simulation<2> sim(case_file("hydrostatic_tank_2d.yaml"));
  const Scene& sc = sim.scene();
  const double rgh = sc.rho0 * std::abs(sc.gravity[1]) * sc.reference.length;
  auto& p = sim.particles();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hP = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Pressure{}));
  int in_layer = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const double y = hx(i, 1) - sc.reference.origin[1];
    hP(i) = sc.rho0 * std::abs(sc.gravity[1]) * (sc.reference.length - y);
    if (y >= 0.2 && y < 0.2 + sc.dx) hP(i) += (in_layer++ % 2 == 0 ? 0.03 : -0.01) * rgh;
  }
  REQUIRE(in_layer % 2 == 0);
  Kokkos::deep_copy(p.get(field::Pressure{}), hP);
  const auto e = reference_errors(sim);
  CHECK(e.at("pressure_linf") == Approx(0.03).epsilon(1e-9));
  CHECK(e.at("pressure_layer_mean") == Approx(0.01).epsilon(1e-9));
}

TEST_CASE("Error norms: a channel whose velocity is the start-up profile has no error", "[unit][reference]") {
  Simulation<2> sim(case_file("poiseuille_2d.yaml"));
  for (int s = 0; s < 5; ++s) sim.step(1e30);
  const Scene& sc = sim.scene();
  const double t = sim.time();
  set_velocity(sim, [&](double, double y) {
    return std::array<double, 2>{channel_startup(sc, y - sc.reference.origin[1], t), 0.0};
  });
  auto e = reference_errors(sim);
  CHECK(e.at("velocity_l2") < 1e-6);  // the quadratic interpolation of the 1001-point table
  // 1 % more everywhere: an L2 of 1 %
  set_velocity(sim, [&](double, double y) {
    return std::array<double, 2>{1.01 * channel_startup(sc, y - sc.reference.origin[1], t), 0.0};
  });
  e = reference_errors(sim);
  CHECK(e.at("velocity_l2") == Approx(0.01).epsilon(1e-3));
  CHECK(e.at("velocity_l2_near_wall") == Approx(0.01).epsilon(1e-3));
}

TEST_CASE("SPHERIC Test 2 errors: peaks, their times and level RMS against a known offset", "[unit][reference]") {
  using reference::Series;
  // a measured impact: a triangle peak of 10 kPa at 0.41 s on P1, 5 kPa at 0.42 s on P3;
  // levels H2 = 0.1 t, H4 = 0.55 - 0.1 t
  std::map<std::string, Series> measured, sim;
  for (int k = 0; k <= 2000; ++k) {
    const double t = k * 1e-3;
    measured["P1"].emplace_back(t, std::max(0.0, 1e4 * (1 - std::abs(t - 0.41) / 0.02)));
    measured["P3"].emplace_back(t, std::max(0.0, 5e3 * (1 - std::abs(t - 0.42) / 0.02)));
    measured["H2"].emplace_back(t, 0.1 * t);
    measured["H4"].emplace_back(t, 0.55 - 0.1 * t);
  }
  // the run: P1 12 kPa at 0.43 s (a later impact at 1.3 s, beyond the first-impact window, is
  // not the peak), P3 as measured, H2 0.011 m high throughout, H4 exact; sampled every 2 ms
  for (int k = 0; k <= 1000; ++k) {
    const double t = k * 2e-3;
    sim["P1"].emplace_back(t, std::max(0.0, 1.2e4 * (1 - std::abs(t - 0.43) / 0.02)) + (std::abs(t - 1.3) < 1e-9 ? 5e4 : 0.0));
    sim["P3"].emplace_back(t, std::max(0.0, 5e3 * (1 - std::abs(t - 0.42) / 0.02)));
    sim["H2"].emplace_back(t, 0.1 * t + 0.011);
    sim["H4"].emplace_back(t, 0.55 - 0.1 * t);
  }
  const auto e = reference::spheric_test2_errors(measured, sim, 0.55, 2.0);
  CHECK(e.at("P1_peak_relative_error") == Approx(0.2).margin(1e-12));
  CHECK(e.at("P1_peak_time_error") == Approx(0.02).margin(1e-12));
  CHECK(e.at("P3_peak_relative_error") == Approx(0.0).margin(1e-12));
  CHECK(e.at("P3_peak_time_error") == Approx(0.0).margin(1e-12));
  CHECK(e.at("H2_rms_error") == Approx(0.011 / 0.55).epsilon(1e-9));
  CHECK(e.at("H4_rms_error") == Approx(0.0).margin(1e-12));
  // impulses over 0.35-0.60 s: the triangles' areas, 200 and 240 Pa s on P1, equal on P3
  CHECK(e.at("P1_impulse_relative_error") == Approx(0.2).epsilon(1e-9));
  CHECK(e.at("P3_impulse_relative_error") == Approx(0.0).margin(1e-12));
  // RMS over 0.3-2 s at the run's 851 samples, over the measured 10 kPa peak: the shifted,
  // taller triangle and the 50 kPa sample at 1.3 s (computed independently: 0.20960485458)
  CHECK(e.at("P1_rms_error") == Approx(0.2096048545826881).epsilon(1e-9));
  CHECK(e.at("P3_rms_error") == Approx(0.0).margin(1e-12));
  // a run that stops before 0.60 s gets no impulse
  CHECK(reference::spheric_test2_errors(measured, sim, 0.55, 0.5).count("P1_impulse_relative_error") == 0);
}

TEST_CASE("The wedge impact's reference: profile means, force coefficient and the errors of a known run", "[unit][reference]") {
  using reference::Series;
  // P(eta) = eta up to 2, 4 - eta up to 4, 0 beyond: C_F = 4
  const Series profile = {{0.0, 0.0}, {2.0, 2.0}, {4.0, 0.0}, {6.0, 0.0}};
  CHECK(reference::profile_force_coefficient(profile) == Approx(4.0).epsilon(1e-14));
  CHECK(reference::profile_mean(profile, 1.0, 3.0) == Approx(1.5).epsilon(1e-14));
  CHECK(reference::profile_mean(profile, 0.0, 1.0) == Approx(0.5).epsilon(1e-14));
  CHECK(reference::profile_mean(profile, 5.0, 7.0) == Approx(0.0).margin(1e-14));  // beyond the last row: 0
  CHECK(reference::profile_mean(profile, 3.0, 3.0) == Approx(1.0).epsilon(1e-14));   // a point sensor: P(3)
  // six faces of 1 m centred at 0.5 ... 5.5 m; U = 1 m/s, rho = 1, t0 = 0, compared over s = 0.5-1 m.
  // The run: the reference's face means, except face 3, which reads twice the reference's peak;
  // the force 1.2 C_F rho U^2 s; before the contact, 7 N/m
  std::vector<reference::WedgeSensorFace> faces;
  for (int j = 0; j < 6; ++j) faces.push_back({j + 0.5, 1.0});
  const std::vector<double> at_1 = {0.5, 1.5, 1.5, 3.0, 0.0, 0.0};   // s = 1: face means 0.5 1.5 1.5 0.5 0 0
  const std::vector<double> at_05 = {1.0, 1.0, 0.0, 2.0, 0.0, 0.0};  // s = 0.5: face means 1 1 0 0 0 0
  const std::vector<reference::WedgeInstant> run = {{-0.1, 7.0, {0, 0, 0, 0, 0, 0}}, {0.25, 1.0, at_05 /* s < 0.5: left out */},
                                                     {0.5, 1.2 * 4.0 * 0.5, at_05}, {1.0, 1.2 * 4.0, at_1}};
  const auto e = reference::wedge_impact_errors(profile, faces, run, 1.0, 1.0, 0.0, 1.0);
  CHECK(e.at("force_before_contact") == Approx(7.0).epsilon(1e-14));
  CHECK(e.at("pressure_peak_ratio") == Approx(2.0).epsilon(1e-14));  // 3 / 1.5 and 2 / 1
  CHECK(e.at("pressure_peak_relative_error") == Approx(1.0).epsilon(1e-14));
  // the run's peak on face 3 (3.5 m), the reference's on face 1 (1.5 m, the first of two equal) at
  // s = 1 and on face 0 (0.5 m) at s = 0.5: (2 / 1 + 3 / 0.5) / 2
  CHECK(e.at("pressure_peak_position_error") == Approx(4.0).epsilon(1e-14));
  // face 3 only: (3 - 0.5)^2 + (2 - 0)^2 over 12 samples, over the mean peak (1.5 + 1) / 2
  CHECK(e.at("pressure_profile_error") == Approx(std::sqrt(10.25 / 12) / 1.25).epsilon(1e-12));
  CHECK(e.at("force_coefficient") == Approx(4.8).epsilon(1e-14));
  CHECK(e.at("force_coefficient_error") == Approx(0.2).epsilon(1e-12));
}

TEST_CASE("The wedge impact's profile file: read, and refused with its path when it is not one", "[unit][reference]") {
  const std::string good = "wedge_profile_good.csv", bad = "wedge_profile_bad.csv";
  std::ofstream(good) << "# a comment\neta,pressure\n0.0,1.0\n0.5,2.0\n";
  std::ofstream(bad) << "eta,pressure\n0.0,1.0\n0.5,2.0\n0.5,3.0\n";
  const reference::Series p = reference::read_wedge_profile(good);
  REQUIRE(p.size() == 2);
  CHECK(p[1].second == 2.0);
  CHECK_THROWS_WITH(reference::read_wedge_profile(bad), Contains(bad) && Contains("eta increasing"));
  CHECK_THROWS_WITH(reference::read_wedge_profile("no_such_profile.csv"), Contains("no_such_profile.csv"));
  std::remove(good.c_str());
  std::remove(bad.c_str());
  // the shipped case refuses a run too short to reach s = length, and a missing profile
  CHECK_THROWS_WITH(case_file("wedge_impact_2d.yaml", {"time.duration=0.1"}), Contains("reference.length") && Contains("s = length"));
  CHECK_THROWS_WITH(case_file("wedge_impact_2d.yaml", {"reference.file=nowhere.csv"}),
                    Contains("--set reference.file") && Contains("cannot open") && Contains("nowhere.csv"));
}
