// The transport-velocity law of Oger et al. (thesis 2.112-2.115, scheme.transport: ale) and
// Vila's Riemann-SPH in ALE form with mass fluxes (2.84-2.89, scheme.riemann.variant: vila):
// the law against a brute-force evaluation, zero on a regular lattice, tangential at a flat free
// surface; Vila's mass and momentum rates conserved to round-off; the dam break with both.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>

#include "observers/ErrorNorms.hpp"
#include "reference/References.hpp"
#include "scene/CaseFile.hpp"
#include "solver/KernelDispatch.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using namespace ondine::test;
using Catch::Matchers::Contains;

namespace {
const std::string src = ONDINE_SOURCE_DIR;

template <class Tag, int D>
auto host(const Simulation<D>& sim, Tag t) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(t));
}

// du of (2.113) for every particle of a periodic box, by brute force over all pairs
template <int D>
std::vector<Vec<D>> brute_force_correction(const Simulation<D>& sim, double L, int& capped, int& free_law) {
  const Scene& s = sim.scene();
  const auto x = host(sim, field::Position{});
  const auto u = host(sim, field::Velocity{});
  const auto m = host(sim, field::Mass{});
  const auto rho = host(sim, field::Density{});
  const int n = static_cast<int>(sim.size());
  const double R = s.R(), R_d = 2.0 * s.dx, U = s.ale_mach * s.c0;
  std::vector<Vec<D>> out(n, Vec<D>::zero());
  const auto min_image = [&](int i, int j) {  // x_i - x_j in the periodic box of side L
    Vec<D> xij;
    for (int k = 0; k < D; ++k) xij[k] = x(i, k) - x(j, k) - L * std::round((x(i, k) - x(j, k)) / L);
    return xij;
  };
  with_kernel<D>(s.kernel, R_d, [&](auto W) {
    for (int i = 0; i < n; ++i) {
      Vec<D> nh = Vec<D>::zero();
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        const Vec<D> xij = min_image(i, j);
        const double r = std::sqrt(norm2(xij));
        if (r >= R_d) continue;
        nh += (m(j) / s.rho0 * W.derivative(r) / r) * xij;
      }
      nh *= R;
      double speed = 0;
      for (int k = 0; k < D; ++k) speed += u(i, k) * u(i, k);
      speed = std::sqrt(speed);
      const double len = std::sqrt(norm2(nh));
      if (len > 0) out[i] = U * len < 0.25 * speed ? (-U) * nh : (-0.25 * speed / len) * nh;
      if (U * len < 0.25 * speed) ++free_law;
      else ++capped;
    }
  });
  // the part along the truncation vector g = sum_j w_j grad W(x_ij, R), with eps = 0.1 / R
  with_kernel<D>(s.kernel, R, [&](auto W) {
    for (int i = 0; i < n; ++i) {
      Vec<D> g = Vec<D>::zero();
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        const Vec<D> xij = min_image(i, j);
        const double r = std::sqrt(norm2(xij));
        if (r >= R) continue;
        g += (m(j) / rho(j) * W.derivative(r) / r) * xij;
      }
      out[i] -= (dot(out[i], g) / (norm2(g) + 0.01 / (R * R))) * g;
    }
  });
  return out;
}

template <int D>
void check_law_against_brute_force(const std::string& scheme) {
  const double L = D == 2 ? 0.4 : 0.2, dx = D == 2 ? 0.02 : 0.025;
  Simulation<D> sim(periodic_box(D, L, dx, scheme));
  disorder(sim, 0.15, 0.5, 0.01, 7);
  sim.evaluate();
  const auto du0 = host(sim, field::TransportCorrection{});
  const auto u = host(sim, field::Velocity{});
  int capped = 0, free_law = 0;
  const std::vector<Vec<D>> ref = brute_force_correction(sim, L, capped, free_law);
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    double e2 = 0, a2 = 0, u2 = 0;
    for (int k = 0; k < D; ++k) {
      e2 += (du0(i, k) - ref[i][k]) * (du0(i, k) - ref[i][k]);
      a2 += du0(i, k) * du0(i, k);
      u2 += u(i, k) * u(i, k);
    }
    worst = std::max(worst, std::sqrt(e2));
    largest = std::max(largest, std::sqrt(a2));
    REQUIRE(std::sqrt(a2) <= 0.25 * std::sqrt(u2) * (1 + 1e-12));  // the cap of (2.113)
  }
  INFO(D << "D: largest |du| " << largest << ", worst difference from brute force " << worst << ", capped " << capped
         << ", uncapped " << free_law);
  CHECK(largest > 1e-3);  // the disorder gives a correction
  CHECK(worst < 1e-12 * largest);
  CHECK(capped > 0);      // both branches of (2.113) are exercised
  CHECK(free_law > 0);
}

}  // namespace

TEST_CASE("Oger's transport velocity (2.113)-(2.114) with its truncation projection equals a brute-force evaluation, capped at |u| / 4", "[unit][ale]") {
  check_law_against_brute_force<2>("{flux: riemann, transport: ale}");
  check_law_against_brute_force<3>("{flux: riemann, transport: ale, riemann: {variant: vila}}");
}

TEST_CASE("Oger's transport velocity vanishes on a regular lattice", "[unit][ale]") {
  Simulation<2> sim(periodic_box(2, 0.4, 0.02, "{flux: riemann, transport: ale}"));
  disorder(sim, 0.0, 0.5, 0.0, 3);  // velocities only: the lattice stays regular
  sim.evaluate();
  const auto du0 = host(sim, field::TransportCorrection{});
  double worst = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) worst = std::max(worst, std::hypot(du0(i, 0), du0(i, 1)));
  INFO("largest |du| on the lattice: " << worst << " m/s (speeds up to 0.5 m/s)");
  CHECK(worst < 1e-13);
}

TEST_CASE("Oger's transport velocity is tangential at a flat free surface", "[unit][ale]") {
  // a layer periodic in x, free above and below, moving at 1 m/s along x, slightly disordered
  const std::string y =
      "dimension: 2\ndomain: {min: [0, 0], max: [0.4, 1.0], periodic: [true, false]}\n"
      "fluid: {rho0: 1000, sound_speed: 10}\ndiscretisation: {dx: 0.01}\n"
      "fluid_blocks: [{min: [0, 0.3], max: [0.4, 0.6], velocity: [1, 0]}]\n"
      "scheme: {flux: riemann, transport: ale}\ntime: {duration: 1, output_interval: 1}\n";
  Simulation<2> sim(parse_case(y, "layer.yaml"));
  {
    auto& p = sim.particles();
    auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> s(-1, 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
      hx(i, 0) += 0.1 * 0.01 * s(rng);
      hx(i, 1) += 0.1 * 0.01 * s(rng);
    }
    Kokkos::deep_copy(p.get(field::Position{}), hx);
    sim.invalidate_neighbours();
  }
  sim.evaluate();
  const auto du0 = host(sim, field::TransportCorrection{});
  const auto x = host(sim, field::Position{});
  const auto fs = host(sim, field::FreeSurface{});
  double surf_n = 0, surf_t = 0, in_n = 0, in_t = 0;
  int flagged = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    const double y_i = x(i, 1);
    if (y_i > 0.58 || y_i < 0.32) {  // the first two rows of each surface
      if (fs(i) > 0.5) ++flagged;
      surf_n += std::abs(du0(i, 1));
      surf_t += std::abs(du0(i, 0));
    } else if (y_i > 0.38 && y_i < 0.52) {
      in_n += std::abs(du0(i, 1));
      in_t += std::abs(du0(i, 0));
    }
  }
  INFO("surface rows: sum |du_n| " << surf_n << ", sum |du_t| " << surf_t << " (" << flagged << " flagged); interior: " << in_n
                                   << ", " << in_t);
  CHECK(flagged >= 60);            // both surfaces, 40 particles each, are found
  CHECK(surf_t > 0);               // the surface particles are still regularised along the surface,
  CHECK(surf_n < 0.1 * surf_t);    // not pushed through it (0.07 measured; 1 without the projection)
  CHECK(in_n > 0.3 * in_t);        // while inside the correction has both components
}

TEST_CASE("Vila's ALE fluxes (2.84)-(2.89) conserve mass and momentum to round-off", "[scheme][conservation][ale]") {
  for (const std::string scheme : {"{flux: riemann, transport: ale, riemann: {variant: vila}, viscous_term: morris}",
                                   "{flux: riemann, riemann: {variant: vila, reconstruction: none}, viscous_term: monaghan_gingold}"}) {
    for (int D : {2, 3}) {
      auto run = [&](auto sim) {
        disorder(*sim, 0.2, 0.5, 0.01, 42);
        sim->evaluate();
        const auto& p = sim->particles();
        const auto m = host(*sim, field::Mass{});
        const auto dm = host(*sim, field::MassRate{});
        const auto u = host(*sim, field::Velocity{});
        const auto du = host(*sim, field::Acceleration{});
        double net_m = 0, scale_m = 0;
        Vec3 net_q{0, 0, 0};
        double scale_q = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
          net_m += dm(i);
          scale_m += std::abs(dm(i));
          for (int k = 0; k < D; ++k) {
            const double q = m(i) * du(i, k) + u(i, k) * dm(i);  // d(m u)/dt
            net_q[k] += q;
            scale_q += std::abs(q);
          }
        }
        INFO(D << "D " << scheme << ": sum dm " << net_m << " of " << scale_m << "; sum d(mu) " << net_q[0] << ", " << net_q[1]
               << " of " << scale_q);
        REQUIRE(scale_m > 0);
        CHECK(std::abs(net_m) < 1e-14 * scale_m);
        for (int k = 0; k < D; ++k) CHECK(std::abs(net_q[k]) < 1e-14 * scale_q);
        // over steps: the masses change, their sum only by round-off
        const Diagnostics d0 = diagnostics(*sim);
        for (int s = 0; s < 10; ++s) sim->step(1.0);
        const Diagnostics d1 = diagnostics(*sim);
        CHECK(std::abs(d1.mass - d0.mass) < 1e-13 * d0.mass);
      };
      const double L = D == 2 ? 0.5 : 0.25, dx = D == 2 ? 0.02 : 0.025;
      if (D == 2) run(std::make_unique<Simulation<2>>(periodic_box(2, L, dx, scheme, ", viscosity: 1.0e-2")));
      else run(std::make_unique<Simulation<3>>(periodic_box(3, L, dx, scheme, ", viscosity: 1.0e-2")));
    }
  }
}

TEST_CASE("Riemann-SPH with the ALE transport: dam break (a/25) within Martin & Moyce's bounds, no leak", "[ale][case][dam_break]") {
  for (const std::vector<std::string>& sets :
       {std::vector<std::string>{"scheme.transport=ale"}, std::vector<std::string>{"scheme.transport=ale", "scheme.riemann.variant=vila"}}) {
    std::vector<std::string> all = {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage", "scheme.cfl.acoustic=0.5",
                                    "discretisation.dx=0.002286"};
    all.insert(all.end(), sets.begin(), sets.end());
    Scene s = load_case(src + "/cases/dam_break_2d.yaml", all);
    Simulation<2> sim(s);
    const auto front = dam_break_front(sim);
    const auto e = reference::martin_moyce_errors(front);
    INFO(sets.back() << ": front max relative error " << e.at("front_max_relative_error"));
    CHECK(e.at("front_max_relative_error") < 0.20);
    CHECK(wall_leaks(sim, 0.0) == 0);
  }
}

TEST_CASE("scheme.transport: ale and scheme.riemann.variant: vila are read, and the unsupported combinations are refused", "[unit][case]") {
  const Scene s = load_case(src + "/cases/dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage",
                                                                "scheme.transport=ale", "scheme.ale.mach=0.05", "scheme.riemann.variant=vila"});
  CHECK(s.ale);
  CHECK_FALSE(s.shifting);
  CHECK(s.ale_mach == 0.05);
  CHECK(s.riemann_variant == RiemannVariant::Vila);
  CHECK_THAT(case_refusal("dam_break_2d.yaml", {"scheme.transport=ale"}), Contains("scheme.transport") && Contains("scheme.flux: riemann"));
  CHECK_THAT(case_refusal("dam_break_2d.yaml", {"scheme.ale.mach=0.1"}), Contains("scheme.ale") && Contains("transport: ale"));
  CHECK_THAT(case_refusal("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage",
                                                "scheme.transport=ale", "scheme.ale.mach=2"}),
             Contains("scheme.ale.mach") && Contains("0 < Ma <= 1"));
  CHECK_FALSE(load_case(src + "/cases/dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage",
                                                            "scheme.transport=ale", "scheme.ale.cut_supports=free"})
                  .ale_tangential_cut);
  CHECK(s.ale_tangential_cut);
  CHECK_THAT(case_refusal("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage",
                                                "scheme.transport=ale", "scheme.ale.cut_supports=none"}),
             Contains("scheme.ale.cut_supports") && Contains("tangential"));
  CHECK_THAT(case_refusal("dam_break_2d.yaml", {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.riemann.variant=godunov"}),
             Contains("scheme.riemann.variant") && Contains("vila"));
}
