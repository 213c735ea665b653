#pragma once
// Simulation<D>: the observers, which read the state: diagnostics (Kokkos reductions),
// probes, wave gauges, wall forces, leaks, the dam-break front; and the preparation of an
// output (pressure, Shepard factor, free surface; with zones the guards of the stored
// state, put back after it by finish_output). Included by SimulationImpl.hpp only.
#include <functional>

#include "kernels/EquationOfState.hpp"
#include "kernels/FreeSurfacePass.hpp"
#include "kernels/ProbeSum.hpp"
#include "kernels/WallForces.hpp"
#include "kernels/WaveGauge.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
Diagnostics Simulation<D>::diagnostics() const {
  const int n = n_own_;
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto m = p_.get(field::Mass{});
  Diagnostics d;
  Kokkos::parallel_reduce("ondine::Diagnostics::mass", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s += m(i); }, d.mass);
  for (int k = 0; k < D; ++k)
    Kokkos::parallel_reduce("ondine::Diagnostics::momentum", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& s) { s += m(i) * u(i, k); }, d.momentum[k]);
  Kokkos::parallel_reduce("ondine::Diagnostics::kinetic_energy", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s += 0.5 * m(i) * norm2(load<D>(u, i)); },
                          d.kinetic_energy);
  double v2 = 0;
  Kokkos::parallel_reduce("ondine::Diagnostics::max_speed", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) {
                            const double s = norm2(load<D>(u, i));
                            if (s > mx) mx = s;
                          },
                          Kokkos::Max<double>(v2));
  d.max_speed = std::sqrt(v2);
  Kokkos::parallel_reduce("ondine::Diagnostics::rho_min", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mn) { if (rho(i) < mn) mn = rho(i); },
                          Kokkos::Min<double>(d.rho_min));
  Kokkos::parallel_reduce("ondine::Diagnostics::rho_max", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) { if (rho(i) > mx) mx = rho(i); },
                          Kokkos::Max<double>(d.rho_max));
  if (apr_on_) {
    // with refinement zones the leaves carry the fluid: a mother's mass and
    // momentum are its daughters' (passive mothers and daughter guards overlap)
    apr::LeafSum<D> f{u, m, p_.get(field::AprMother{}), 0};
    d.mass = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::mass", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.mass);
    for (int k = 0; k < D; ++k) {
      f.what = 1 + k;
      d.momentum[k] = 0;
      Kokkos::parallel_reduce("ondine::Diagnostics::momentum", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.momentum[k]);
    }
    f.what = D + 1;
    d.kinetic_energy = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::kinetic_energy", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.kinetic_energy);
  }
  // open boundaries: the fluid region's mass is the (leaf) mass less the buffers' (a buffer
  // particle is never refined); a buffer particle beyond the outer face is removed at the next
  // step start
  d.fluid_mass = d.mass;
  const bool open = p_.has(field::OpenRole{});
  const auto role = open ? p_.get(field::OpenRole{}) : field_view_t<field::OpenRole, D>();
  if (open) {
    double buffers = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::buffer_mass", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& s) { s += role(i) != 0 ? m(i) : 0.0; }, buffers);
    d.fluid_mass = d.mass - buffers;
  }
  const auto box = domain_.box();
  double hi[D];
  for (int k = 0; k < D; ++k) hi[k] = box.lo[k] + box.len[k];
  std::int64_t bad = 0;
  Kokkos::parallel_reduce("ondine::Diagnostics::outside_and_nan", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, std::int64_t& c) {
                            bool out = false, nan = !kmath::isfinite(rho(i));
                            for (int k = 0; k < D; ++k) {
                              nan = nan || !kmath::isfinite(x(i, k)) || !kmath::isfinite(u(i, k));
                              out = out || (!box.periodic[k] && (x(i, k) < box.lo[k] || x(i, k) > hi[k]));
                            }
                            if (role.extent(0) > 0 && role(i) != 0) out = false;
                            c += (out ? 1 : 0) + (nan ? (std::int64_t(1) << 40) : 0);
                          },
                          bad);
  // over all ranks
  d.mass = comm().sum(d.mass);
  d.fluid_mass = comm().sum(d.fluid_mass);
  for (int k = 0; k < D; ++k) d.momentum[k] = comm().sum(d.momentum[k]);
  d.kinetic_energy = comm().sum(d.kinetic_energy);
  d.max_speed = comm().max(d.max_speed);
  d.rho_min = comm().min(d.rho_min);
  d.rho_max = comm().max(d.rho_max);
  bad = comm().sum(bad);
  d.outside_domain = bad & ((std::int64_t(1) << 40) - 1);
  d.finite = (bad >> 40) == 0 && std::isfinite(d.kinetic_energy);
  return d;
}

template <int D>
std::vector<ProbeSample> Simulation<D>::sample_probes() const {
  std::vector<Vec3> points;
  for (const Probe& pr : scene_.probes) points.push_back(pr.position);
  return sample_at(points);
}

// Shepard interpolation at each point (thesis 2.40-2.41), by reductions over the owned
// particles: sum_j w_j W(x - x_j) f_j / sum_j w_j W(x - x_j); with refinement zones over
// the SPH particles only, each with its level's radius (apr::ProbeSum). One reduction per
// quantity: probes are sampled at output times only.
template <int D>
std::vector<ProbeSample> Simulation<D>::sample_at(const std::vector<Vec3>& points) const {
  std::vector<ProbeSample> out;
  PassContext<D> c = pass_context(levels().front());
  c.end = n_own_;  // every owned particle; with zones, guards are skipped inside
  c.R = R_;
  for (const Vec3& point : points) {
    Vec<D> xp;
    for (int k = 0; k < D; ++k) xp[k] = point[k];
    // what = 0: the Shepard sum, 1: pressure, 2: density, 3 + k: velocity k
    const auto sum = [&](int what) { return comm().sum(scheme_.probe_sum(c, xp, what)); };
    ProbeSample s;
    s.shepard = sum(0);
    if (s.shepard > 0) {
      s.pressure = sum(1) / s.shepard;
      s.density = sum(2) / s.shepard;
      for (int k = 0; k < D; ++k) s.velocity[k] = sum(3 + k) / s.shepard;
    }
    out.push_back(s);
  }
  return out;
}

template <int D>
std::vector<double> Simulation<D>::wave_elevations() {
  std::vector<double> out;
  if (scene_.wave_gauges.empty()) return out;
  ensure_neighbours();  // the particle cell list is current
  domain_.refresh_state_halos(p_);
  const double step = 0.25 * (apr_on_ ? apr_.dx(apr_.levels() - 1) : scene_.dx);  // a quarter of the finest spacing
  PassContext<D> c = pass_context(levels().front());
  c.end = n_own_;
  c.R = R_;  // with zones the coarsest radius: the cell list's reach
  for (const WaveGauge& g : scene_.wave_gauges) {
    const int ns = static_cast<int>(std::floor((g.top - g.bottom) / step)) + 1;
    Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> pts("ondine::WaveGauge::points", ns);
    Kokkos::View<double*, MemSpace> sum("ondine::WaveGauge::sum", ns);
    auto hp = Kokkos::create_mirror_view(pts);
    std::vector<double> z(ns);
    for (int s = 0; s < ns; ++s) {  // the sample points of the line (not particles)
      z[s] = g.bottom + s * step;
      for (int k = 0; k < D - 1; ++k) hp(s, k) = g.position[k];
      hp(s, D - 1) = z[s];
    }
    Kokkos::deep_copy(pts, hp);
    // with zones: SPH particles only, each with its level's radius (WaveGauge.hpp)
    scheme_.gauge_sums(c, pts, sum);
    std::vector<double> shepard(ns);
    Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(shepard.data(), ns), sum);
    comm().sum_in_place(shepard);
    out.push_back(gauge_level(z.data(), shepard.data(), ns));
  }
  return out;
}

template <int D>
std::vector<WallForce> Simulation<D>::wall_forces() {
  std::vector<WallForce> out;
  if (walls_.empty()) return out;
  ensure_neighbours();  // the particle cell list is current
  domain_.refresh_state_halos(p_);
  const int nq = walls_.points().count;
  const double nu = scene_.viscous_term != ViscousTerm::None ? scene_.nu : 0.0;
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> traction("ondine::NFM::traction", nq, 2 * D);
  PassContext<D> c = pass_context(levels().front());
  c.R = R_;  // with zones each SPH particle with its level's radius (WallForces.hpp), R the coarsest
  c.nu = nu;
  scheme_.wall_traction(c, traction);
  // several ranks: each wall point is counted by the rank that owns its cell (its
  // support is complete there: owned particles and halos)
  Kokkos::View<int*, MemSpace> counted("ondine::NFM::counted", nq);
  Kokkos::deep_copy(counted, 1);
  if (!comm().serial()) {
    const auto orb = domain_.orb();
    const auto wx = walls_.points().x;
    const auto box = domain_.box();
    const int me = comm().rank();
    Kokkos::parallel_for("ondine::NFM::wall_point_owner", Kokkos::RangePolicy<ExecSpace>(0, nq), KOKKOS_LAMBDA(const int q) {
      Vec<D> xq;
      for (int k = 0; k < D; ++k) xq[k] = box.wrap(wx(q, k), k);
      counted(q) = orb.owner(xq) == me ? 1 : 0;
    });
  }
  for (int w = 0; w < walls_.wall_count(); ++w) {
    WallForce f;
    f.name = walls_.names()[w];
    for (int c = 0; c < 2 * D; ++c) {
      double v = 0;
      Kokkos::parallel_reduce("ondine::NFM::wall_force", Kokkos::RangePolicy<ExecSpace>(0, nq),
                              WallTractionSum{traction, walls_.points().wall, counted, w, c}, v);
      (c < D ? f.pressure[c] : f.viscous[c - D]) = comm().sum(v);
    }
    const Vec3& centre = scene_.walls[static_cast<std::size_t>(w)].moment_centre;
    for (int k = D == 2 ? 2 : 0; k < 3; ++k) {
      double v = 0;
      Kokkos::parallel_reduce("ondine::NFM::wall_moment", Kokkos::RangePolicy<ExecSpace>(0, nq),
                              WallMomentSum<D>{traction, walls_.points().x, walls_.points().wall, counted, w, k,
                                               {centre[0], centre[1], centre[2]}},
                              v);
      f.moment[k] = comm().sum(v);
    }
    out.push_back(f);
  }
  return out;
}

template <int D>
std::int64_t Simulation<D>::wall_leaks(double clearance) const {
  if (walls_.empty()) return 0;
  long c = 0;
  Kokkos::parallel_reduce("ondine::NFM::leaks", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          WallLeakCount<D>{region_, clearance < 0 ? 0.1 * scene_.dx : clearance, p_.get(field::Position{})}, c);
  return comm().sum(static_cast<std::int64_t>(c));
}

template <int D>
void Simulation<D>::prepare_output() {
  // several ranks: owned positions are wrapped into the periodic box only at
  // migration; migrate now so that snapshots hold wrapped positions
  if (!comm().serial()) relist_for_output();
  // the stored state's own pressure and Shepard factor (the flux passes left last-stage values)
  domain_.refresh_state_halos(p_);
  if (apr_on_) {
    // a list rebuild here would have been the next step start's, with its bookkeeping: it still is
    const std::int64_t builds = domain_.builds();
    ensure_neighbours();
    if (domain_.builds() != builds) bookkeeping_due_ = true;
    // the guards' fields as the run has them, put back by finish_output()
    auto keep = [](auto& saved, const auto& v) {
      if (saved.extent(0) != v.extent(0)) saved = std::decay_t<decltype(saved)>("ondine::APR::saved_for_output", v.extent(0));
      Kokkos::deep_copy(saved, v);
    };
    keep(saved_u_, p_.get(field::Velocity{}));
    keep(saved_rho_, p_.get(field::Density{}));
    if (p_.has(field::DensityGradient{})) keep(saved_grad_rho_, p_.get(field::DensityGradient{}));
    apr_.save_wide_flags();
    output_saved_ = true;
    apr_.interpolate(p_, domain_.box(), true, walls_.near_facets());  // the guards of the stored state (5.24)
    refresh_guard_halos();
  }
  const int n = static_cast<int>(p_.size());
  with_eos<D>(scene_, [&](auto eos) {
    update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), n);
  });
  if (!walls_.empty()) update_walls(t_);
  update_free_surface();
}

template <int D>
void Simulation<D>::finish_output() {
  if (!apr_on_ || !output_saved_) return;
  Kokkos::deep_copy(p_.get(field::Velocity{}), saved_u_);
  Kokkos::deep_copy(p_.get(field::Density{}), saved_rho_);
  if (p_.has(field::DensityGradient{})) Kokkos::deep_copy(p_.get(field::DensityGradient{}), saved_grad_rho_);
  apr_.restore_wide_flags();
  output_saved_ = false;
}

// The free-surface flag (4.86-4.87) of each level's SPH particles, and the Shepard factor
// of the walls at the stored state (guards included; a guard is no SPH particle: no flag).
template <int D>
void Simulation<D>::update_free_surface() {
  const bool flags = p_.has(field::FreeSurface{});
  const bool walls = !walls_.empty();
  if (flags) {
    ensure_neighbours();
    domain_.refresh_state_halos(p_);
  }
  const auto x = p_.get(field::Position{});
  for (const LevelSpan<D>& L : levels()) {
    if (flags && L.end > L.active_end)
      Kokkos::deep_copy(Kokkos::subview(p_.get(field::FreeSurface{}), std::make_pair(L.active_end, L.end)), 0.0);
    // gamma of every particle of the level, its guards included, even on a rank that holds
    // only guards of it (the snapshot would otherwise depend on the rank count)
    if (walls && L.end > L.first)
      Kokkos::parallel_for("ondine::NFM::shepard_gamma", Kokkos::RangePolicy<ExecSpace>(L.first, L.end),
                           ShepardGammaPass<D>{walls_.facets(), walls_.facet_cells(), L.R, domain_.box(), x, p_.get(field::ShepardGamma{})});
    if (L.active_end == L.first) continue;
    if (!flags) continue;
    scheme_.free_surface(pass_context(L));
  }
}

template <int D>
double Simulation<D>::front_position() const {
  double xmax = -1e300;
  Kokkos::parallel_reduce("ondine::Front", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          MaxComponent<D>{p_.get(field::Position{}), 0}, Kokkos::Max<double>(xmax));
  return comm().max(xmax) + 0.5 * scene_.dx;
}

template <int D>
std::int64_t Simulation<D>::sph_particles() const {
  if (!apr_on_) return n_own_;
  long g = 0;
  Kokkos::parallel_reduce("ondine::APR::count_guards", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          apr::CountGuards{p_.get(field::AprGuard{})}, g);
  return n_own_ - g;
}

}  // namespace ondine
