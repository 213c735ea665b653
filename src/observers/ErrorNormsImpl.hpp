#pragma once
// Definition of reference_errors (observers/ErrorNorms.hpp); included by ErrorNorms2d.cpp
// and ErrorNorms3d.cpp only.
#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/Math.hpp"
#include "kernels/turbulence/LogLaw.hpp"
#include "observers/ChannelReference.hpp"
#include "observers/ErrorNorms.hpp"
#include "solver/hooks/ImpermeabilityGuard.hpp"
#include "reference/References.hpp"

namespace ondine {

namespace errors {

// Means over horizontal layers dx thick (z in [k dx, (k + 1) dx), clamped to the first and the
// last layer): each layer's particle count, mean height and mean of one quantity, over the ranks.
class LayerMeans {
 public:
  LayerMeans(int layers, double dx) : dx_(dx), sums_(3 * layers, 0.0) {}
  int layer_of(double z) const { return std::clamp(static_cast<int>(std::floor(z / dx_)), 0, layers() - 1); }
  void add(double z, double value) {
    const int k = layer_of(z);
    sums_[3 * k] += 1, sums_[3 * k + 1] += z, sums_[3 * k + 2] += value;
  }
  void sum_over_ranks(const Communicator& comm) { comm.sum_in_place(sums_); }
  int layers() const { return static_cast<int>(sums_.size() / 3); }
  double count(int k) const { return sums_[3 * k]; }
  double height(int k) const { return sums_[3 * k + 1] / sums_[3 * k]; }
  double mean(int k) const { return sums_[3 * k + 2] / sums_[3 * k]; }

 private:
  double dx_;
  std::vector<double> sums_;  // per layer: count, sum z, sum value
};

template <int D>
bool every_axis_periodic(const Scene& scene) {
  for (int k = 0; k < D; ++k)
    if (!scene.periodic[k]) return false;
  return true;
}

// mass drift against the initial mass; with no walls and every axis periodic, internal
// forces cancel pairwise and the momentum is P(0) + M (g + f) t exactly
template <int D>
void conservation(const Simulation<D>& sim, const Diagnostics& d, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Diagnostics& initial = sim.initial_diagnostics();
  const double t = sim.time();
  const bool all_periodic = every_axis_periodic<D>(scene);
  e["mass_drift"] = std::abs(d.mass - initial.mass) / initial.mass;
  if (all_periodic && !!sim.walls().empty() && scene.damping_time == 0) {
    // With no walls, internal forces cancel pairwise: P(t) = P(0) + M (g + f) t exactly.
    double err2 = 0, scale2 = 0;
    for (int k = 0; k < D; ++k) {
      const double expect = initial.momentum[k] + d.mass * (scene.gravity[k] + scene.body_force[k]) * t;
      err2 += (d.momentum[k] - expect) * (d.momentum[k] - expect);
      scale2 += expect * expect;
    }
    const double scale = std::max(std::sqrt(scale2), d.mass * scene.reference_velocity);
    e["momentum_balance_error"] = std::sqrt(err2) / scale;
  }
}

// the decaying Taylor-Green vortex (2D, periodic): velocity L2 and Linf, peak-speed decay
template <int D>
void taylor_green(const Simulation<D>& sim, const Diagnostics& d, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Communicator& comm = sim.comm();
  const double t = sim.time();
  const bool all_periodic = every_axis_periodic<D>(scene);
  bool taylor_green = all_periodic && D == 2;
  for (const FluidBlock& b : scene.blocks) taylor_green = taylor_green && b.velocity_kind == InitialVelocity::TaylorGreen;
  if (taylor_green) {
    // Decaying vortex: u = -U e^{bt} cos kx sin ky, v = U e^{bt} sin kx cos ky, b = -2 nu k^2.
    const FluidBlock& b = scene.blocks.front();
    const double k = 2.0 * M_PI / b.tg_wavelength;
    const double amp = b.tg_amplitude * std::exp(-2.0 * scene.nu * k * k * t);
    const int n = static_cast<int>(sim.size());
    const auto x = sim.particles().get(field::Position{});
    const auto u = sim.particles().get(field::Velocity{});
    double num = 0, den = 0, linf = 0;
    Kokkos::parallel_reduce("ondine::Error::taylor_green_l2", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& a) {
                              const double ue = -amp * kmath::cos(k * x(i, 0)) * kmath::sin(k * x(i, 1));
                              const double ve = amp * kmath::sin(k * x(i, 0)) * kmath::cos(k * x(i, 1));
                              a += (u(i, 0) - ue) * (u(i, 0) - ue) + (u(i, 1) - ve) * (u(i, 1) - ve);
                            },
                            num);
    Kokkos::parallel_reduce("ondine::Error::taylor_green_norm", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& a) {
                              const double ue = -amp * kmath::cos(k * x(i, 0)) * kmath::sin(k * x(i, 1));
                              const double ve = amp * kmath::sin(k * x(i, 0)) * kmath::cos(k * x(i, 1));
                              a += ue * ue + ve * ve;
                            },
                            den);
    Kokkos::parallel_reduce("ondine::Error::taylor_green_linf", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& mx) {
                              const double ue = -amp * kmath::cos(k * x(i, 0)) * kmath::sin(k * x(i, 1));
                              const double ve = amp * kmath::sin(k * x(i, 0)) * kmath::cos(k * x(i, 1));
                              const double err = kmath::sqrt((u(i, 0) - ue) * (u(i, 0) - ue) + (u(i, 1) - ve) * (u(i, 1) - ve));
                              if (err > mx) mx = err;
                            },
                            Kokkos::Max<double>(linf));
    e["velocity_l2"] = std::sqrt(comm.sum(num) / comm.sum(den));
    e["velocity_linf"] = comm.max(linf) / amp;
    e["max_speed_decay_error"] = std::abs(d.max_speed - amp) / amp;
  }
}

// wall leaks and crossings, impermeability corrections; with zones the families moved off
// walls and the guard shifts
template <int D>
void walls(const Simulation<D>& sim, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Communicator& comm = sim.comm();
  const bool apr_on = sim.refinement_on();
  if (!sim.walls().empty()) {
    e["wall_leaks"] = static_cast<double>(wall_leaks(sim));
    e["wall_crossings"] = static_cast<double>(wall_leaks(sim, 0.0));  // on the solid side of a wall only
    if (apr_on) e["families_moved_off_walls"] = static_cast<double>(sim.refinement().families_moved());
    if (apr_on && scene.refinement_guard_shifting) e["guard_shifts"] = static_cast<double>(comm.sum(sim.refinement().guard_shifts()));
    if (const auto* guard = sim.template find_hook<ImpermeabilityGuard<D>>()) e["wall_corrections"] = static_cast<double>(guard->corrections(comm));
  }
}

// with zones: the guard interpolations put back into their sources' range (apr::GuardApply::limit)
template <int D>
void refinement(const Simulation<D>& sim, std::map<std::string, double>& e) {
  if (sim.refinement_on()) e["guards_limited"] = static_cast<double>(sim.comm().sum(sim.refinement().guards_limited()));
}

// start-up Poiseuille or Couette flow (reference.type poiseuille, couette): velocity L2 over
// the channel and near its walls
template <int D>
void channel(const Simulation<D>& sim, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Communicator& comm = sim.comm();
  const Reference& ref = scene.reference;
  const double t = sim.time();
  const bool apr_on = sim.refinement_on();
  const int n = static_cast<int>(sim.size());
  // start-up Poiseuille driven by the body force along x, or start-up Couette driven by the
  // upper wall (Morris et al. 1997), at the current time
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Position{}));
  auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Velocity{}));
  const double L = ref.length;
  // the analytic profile is evaluated on a fine table (a host loop over 1001 points, not
  // particles) and interpolated quadratically: exact for the steady parabola, O(h^3 u''') on
  // the transient. (A linear interpolation was off by up to h^2 |u''| / 8 = 1e-6 U_max, a bias
  // of 1e-5 relative near the walls that halved the near-wall error of a fine Poiseuille run.)
  const int m = 1000;
  std::vector<double> table(m + 1);
  for (int k = 0; k <= m; ++k) table[k] = channel_startup(scene, L * k / m, t);
  Kokkos::View<double*, Kokkos::HostSpace> tab(table.data(), m + 1);
  double num = 0, den = 0, num_wall = 0, den_wall = 0;
  // with refinement zones: the SPH particles only (guards are interpolated copies), each with its radius
  Kokkos::View<int*, Kokkos::HostSpace> guard, birth;
  if (apr_on) {
    guard = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::AprGuard{}));
    birth = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::AprBirthLevel{}));
  }
  // one pass on the host mirror: the error is a diagnostic at the end of a run
  for (int i = 0; i < n; ++i) {
    if (apr_on && guard(i)) continue;
    const double y = std::min(std::max(hx(i, 1) - ref.origin[1], 0.0), L);
    const double f = y / L * m;
    const int k = std::min(std::max(static_cast<int>(std::lround(f)), 1), m - 1);
    const double sk = f - k;
    const double ue = table[k] + 0.5 * sk * (table[k + 1] - table[k - 1]) +
                      0.5 * sk * sk * (table[k + 1] - 2.0 * table[k] + table[k - 1]);
    num += (hu(i, 0) - ue) * (hu(i, 0) - ue);
    den += ue * ue;
    // the particles whose support is cut by a wall (thesis Table 5.3's boundary error)
    const double Ri = apr_on ? sim.refinement().R(birth(i)) : sim.R();
    if (y < Ri || y > L - Ri) {
      num_wall += (hu(i, 0) - ue) * (hu(i, 0) - ue);
      den_wall += ue * ue;
    }
  }
  e["velocity_l2"] = std::sqrt(comm.sum(num) / comm.sum(den));
  den_wall = comm.sum(den_wall);
  if (den_wall > 0) e["velocity_l2_near_wall"] = std::sqrt(comm.sum(num_wall) / den_wall);
}

// a channel between an inlet and an outlet (reference.type open_channel): the developed plane
// Poiseuille flow u(y) = 6 U_m y (H - y) / H^2, -dp/dx = 12 rho0 nu U_m / H^2, measured on
// the SPH interpolation (sample_at) at the section x0 = origin.x: U_m the trapezoid mean of 19
// points H/20 apart (u = 0 at the walls) against the inlet's U; the profile's largest departure
// from the parabola of that mean, over u_max = 1.5 U_m; the gradient between the pressures at
// mid-height at x0 - 1.5 H and x0 + 0.5 H against the one of that mean
template <int D>
void open_channel(const Simulation<D>& sim, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Reference& ref = scene.reference;
  const double H = ref.length, x0 = ref.origin[0], y0 = ref.origin[1];
  constexpr int m = 20;
  std::vector<Vec3> pts;
  for (int k = 1; k < m; ++k) pts.push_back({x0, y0 + H * k / m, 0});
  pts.push_back({x0 - 1.5 * H, y0 + 0.5 * H, 0});
  pts.push_back({x0 + 0.5 * H, y0 + 0.5 * H, 0});
  const std::vector<ProbeSample> s = sample_at(sim, pts);
  double mean = 0;
  for (int k = 0; k < m - 1; ++k) mean += s[k].velocity[0] / m;
  double worst = 0;
  for (int k = 0; k < m - 1; ++k) {
    const double eta = double(k + 1) / m;
    worst = std::max(worst, std::abs(s[k].velocity[0] - 6 * mean * eta * (1 - eta)) / (1.5 * mean));
  }
  const double gradient = (s[m - 1].pressure - s[m].pressure) / (2 * H);
  const double poiseuille = 12 * scene.rho0 * scene.nu * mean / (H * H);
  e["mean_velocity_error"] = std::abs(mean / ref.velocity - 1);
  e["profile_linf"] = worst;
  e["pressure_gradient_error"] = std::abs(gradient / poiseuille - 1);
}

// the turbulent channel (reference.type log_law, V&I §4.1.1-4.1.2): the friction velocity of the
// momentum balance u_* = sqrt(F H) and the law of the wall function (kernels/turbulence/LogLaw.hpp),
// u(z) = u_* (ln(z u_* / nu) / kappa + B) or u_* (ln(z / k_s) / kappa + B_r), z above the bed (a
// plane channel: from the nearer wall, H the half-width).
// velocity_l2: over the particles at z+ >= 30 (the log layer's lower bound; with the channel's
// mixing length the model's solution is the law up to H), relative L2 of u_x - u(z);
// velocity_l2_near_bed: the same for the particles within R of the bed; friction_velocity_error:
// the mean u_* the wall function reads on the first row (z < dx) against sqrt(F H);
// y_plus_first_row: that row's mean y+ (shown). The mean profile: u_x averaged over rows dx deep
// (over x, and both halves of a plane channel), at each row's mean z:
// mean_velocity_l2: its relative L2 against the law over the rows at z+ >= 30;
// kappa_fit: u_* / the least-squares slope of the mean u against ln z over those rows with z <= H/2
// (von Karman's constant the flow shows); kappa_error: |kappa_fit / kappa - 1|;
// fluctuation_ratio (the Langevin model): sqrt(sum |u - u_row|^2 / sum (2d/3) k) over the log
// layer's particles, 1 where the d velocity components carried hold their isotropic share of k.
template <int D>
void log_law(const Simulation<D>& sim, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Reference& ref = scene.reference;
  const Communicator& comm = sim.comm();
  const Turbulence& tu = scene.turbulence;
  const double H = ref.length, F = scene.body_force[0] + scene.gravity[0], us = std::sqrt(F * H);
  const LogLaw law = LogLaw::make(tu.kappa, scene.nu, tu.smooth_constant, tu.wall_function == WallLaw::Rough ? tu.roughness : 0.0,
                                  tu.rough_constant);
  const auto& p = sim.particles();
  const int n = static_cast<int>(sim.size());
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Velocity{}));
  auto hs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::FrictionVelocity{}));
  auto hy = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::YPlus{}));
  const bool has_k = tu.model == TurbulenceModel::Langevin;
  auto hk = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), has_k ? p.get(field::TurbulentKineticEnergy{})
                                                                           : field_view_t<field::TurbulentKineticEnergy, D>("k", 0));
  const int up = D - 1;
  const auto height = [&](int i) {
    const double z = hx(i, up) - ref.origin[up];
    return ref.plane && z > H ? 2 * H - z : z;
  };
  LayerMeans row(static_cast<int>(std::ceil(H / scene.dx)), scene.dx);  // u_x per row
  double num = 0, den = 0, num_bed = 0, den_bed = 0, first_us = 0, first_yp = 0, first = 0;
  for (int i = 0; i < n; ++i) {  // a diagnostic at the end of the run, on the host mirror
    const double z = height(i);
    if (!(z > 0)) continue;
    const double ue = law.speed(us, z);
    const double d2 = (hu(i, 0) - ue) * (hu(i, 0) - ue);
    if (z * us / scene.nu >= 30.0) {
      num += d2;
      den += ue * ue;
    }
    if (z < sim.R()) {
      num_bed += d2;
      den_bed += ue * ue;
    }
    if (z < scene.dx) {
      first_us += hs(i);
      first_yp += hy(i);
      first += 1;
    }
    row.add(z, hu(i, 0));
  }
  row.sum_over_ranks(comm);
  num = comm.sum(num), den = comm.sum(den), first = comm.sum(first);
  if (den > 0) e["velocity_l2"] = std::sqrt(num / den);
  if (comm.sum(den_bed) > 0) e["velocity_l2_near_bed"] = std::sqrt(comm.sum(num_bed) / comm.sum(den_bed));
  if (first > 0) {
    e["friction_velocity_error"] = std::abs(comm.sum(first_us) / first / us - 1.0);
    e["y_plus_first_row"] = comm.sum(first_yp) / first;
  }
  // the mean profile over rows
  double mnum = 0, mden = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, fits = 0;
  for (int b = 0; b < row.layers(); ++b) {
    if (row.count(b) < 1) continue;
    const double z = row.height(b), um = row.mean(b);
    if (z * us / scene.nu < 30.0) continue;
    const double ue = law.speed(us, z);
    mnum += (um - ue) * (um - ue), mden += ue * ue;
    if (z > 0.5 * H) continue;
    const double lz = std::log(z);
    sx += lz, sy += um, sxx += lz * lz, sxy += lz * um, fits += 1;
  }
  if (mden > 0) e["mean_velocity_l2"] = std::sqrt(mnum / mden);
  if (fits >= 3) {
    const double slope = (fits * sxy - sx * sy) / (fits * sxx - sx * sx);
    if (slope > 0) {
      e["kappa_fit"] = us / slope;
      e["kappa_error"] = std::abs(us / slope / tu.kappa - 1.0);
    }
  }
  if (has_k) {
    double f2 = 0, k2 = 0;
    for (int i = 0; i < n; ++i) {
      const double z = height(i);
      if (!(z > 0) || z * us / scene.nu < 30.0) continue;
      const double u_mean = row.mean(row.layer_of(z));
      double d2 = 0;
      for (int a = 0; a < D; ++a) {
        const double da = hu(i, a) - (a == 0 ? u_mean : 0.0);
        d2 += da * da;
      }
      f2 += d2, k2 += 2.0 * D / 3.0 * hk(i);
    }
    f2 = comm.sum(f2), k2 = comm.sum(k2);
    if (k2 > 0) e["fluctuation_ratio"] = std::sqrt(f2 / k2);
  }
}

// the lid-driven cavity against Ghia et al. (1982) (reference.type ghia_re100, ghia_re1000)
template <int D>
void cavity(const Simulation<D>& sim, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Reference& ref = scene.reference;
  // lid-driven cavity: RMS of (u - u_Ghia)/U on the vertical centreline and of (v - v_Ghia)/U on the
  // horizontal one, Shepard-interpolated at Ghia et al.'s points (the walls' own points excluded)
  const int column = ref.kind == ReferenceKind::GhiaRe100 ? 1 : 2;
  const auto slash = scene.source_file.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : scene.source_file.substr(0, slash);
  const double L = ref.length, U = scene.reference_velocity;
  for (int line = 0; line < 2; ++line) {
    const auto table = reference::read_table(dir + (line == 0 ? "/reference/ghia1982_u_vertical_centreline.csv"
                                                               : "/reference/ghia1982_v_horizontal_centreline.csv"));
    std::vector<Vec3> pts;
    std::vector<double> expect;
    for (const auto& row : table) {
      if (row[0] <= 0.0 || row[0] >= 1.0) continue;
      Vec3 pnt = ref.origin;
      pnt[line == 0 ? 1 : 0] += row[0] * L;  // along the line
      pnt[line == 0 ? 0 : 1] += 0.5 * L;     // at the centre
      pts.push_back(pnt);
      expect.push_back(row[column] * U);
    }
    const auto got = sample_at(sim, pts);
    double sq = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const double d = (got[k].velocity[line == 0 ? 0 : 1] - expect[k]) / U;
      sq += d * d;
    }
    e[line == 0 ? "centreline_u_rms" : "centreline_v_rms"] = std::sqrt(sq / pts.size());
  }
}

// still water (reference.type hydrostatic): pressure against rho0 |g| (H - z), kinetic over
// potential energy
template <int D>
void hydrostatic(const Simulation<D>& sim, const Diagnostics& d, std::map<std::string, double>& e) {
  const Scene& scene = sim.scene();
  const Communicator& comm = sim.comm();
  const Reference& ref = scene.reference;
  const int n = static_cast<int>(sim.size());
  // P = rho0 |g| (H - z) for particles deeper than 3 dx; ratio of kinetic to potential energy
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Position{}));
  auto hP = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Pressure{}));
  auto hm = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Mass{}));
  constexpr int up = D - 1;  // the vertical axis: y in 2D, z in 3D
  const double g = std::abs(scene.gravity[up]), H = ref.length, z0 = ref.origin[up];
  // pressure_layer_mean: the same against the mean of each horizontal layer dx thick
  LayerMeans layer(static_cast<int>(std::ceil(H / scene.dx)) + 1, scene.dx);
  double worst = 0, pe = 0;
  for (int i = 0; i < n; ++i) {
    const double z = hx(i, up) - z0;
    pe += hm(i) * g * z;
    if (H - z < 3 * scene.dx) continue;
    worst = std::max(worst, std::abs(hP(i) - scene.rho0 * g * (H - z)));
    layer.add(z, hP(i));
  }
  worst = comm.max(worst);
  pe = comm.sum(pe);
  layer.sum_over_ranks(comm);
  double worst_layer = 0;
  for (int k = 0; k < layer.layers(); ++k)
    if (layer.count(k) > 0) worst_layer = std::max(worst_layer, std::abs(layer.mean(k) - scene.rho0 * g * (H - layer.height(k))));
  e["pressure_linf"] = worst / (scene.rho0 * g * H);
  e["pressure_layer_mean"] = worst_layer / (scene.rho0 * g * H);
  e["kinetic_over_potential"] = d.kinetic_energy / pe;
}

// laminar square-duct flow (reference.type duct, 3D): u_x against the start-up series
// solution at the run's time, relative L2 over the particles
template <int D>
void duct(const Simulation<D>& sim, std::map<std::string, double>& e) {
  if constexpr (D == 3) {
    const Scene& scene = sim.scene();
    const Reference& ref = scene.reference;
    const int n = static_cast<int>(sim.size());
    auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Position{}));
    auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().get(field::Velocity{}));
    const double L = ref.length, F = scene.body_force[0] + scene.gravity[0];
    double num = 0, den = 0;
    for (int i = 0; i < n; ++i) {  // a host loop at the end of a run (a diagnostic)
      const double y = std::min(std::max(hx(i, 1) - ref.origin[1], 0.0), L);
      const double z = std::min(std::max(hx(i, 2) - ref.origin[2], 0.0), L);
      const double ue = reference::duct_startup(y, z, sim.time(), L, F, scene.nu);
      num += (hu(i, 0) - ue) * (hu(i, 0) - ue);
      den += ue * ue;
    }
    num = sim.comm().sum(num);
    den = sim.comm().sum(den);
    e["velocity_l2"] = std::sqrt(num / den);
  }
}

}  // namespace errors

template <int D>
std::map<std::string, double> reference_errors(const Simulation<D>& sim) {
  std::map<std::string, double> e;
  const Diagnostics d = diagnostics(sim);
  errors::conservation(sim, d, e);
  errors::taylor_green(sim, d, e);
  errors::walls(sim, e);
  errors::refinement(sim, e);
  switch (sim.scene().reference.kind) {
    case ReferenceKind::Poiseuille:
    case ReferenceKind::Couette: errors::channel(sim, e); break;
    case ReferenceKind::GhiaRe100:
    case ReferenceKind::GhiaRe1000: errors::cavity(sim, e); break;
    case ReferenceKind::Hydrostatic: errors::hydrostatic(sim, d, e); break;
    case ReferenceKind::Duct: errors::duct(sim, e); break;
    case ReferenceKind::OpenChannel: errors::open_channel(sim, e); break;
    case ReferenceKind::LogLaw: errors::log_law(sim, e); break;
    default: break;
  }
  return e;
}

}  // namespace ondine
