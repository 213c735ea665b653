#pragma once
// Definitions of Simulation<D>; included by Simulation2d.cpp and Simulation3d.cpp only.
#include <cmath>
#include <stdexcept>

#include "kernels/DensityGradientPass.hpp"
#include "kernels/EquationOfState.hpp"
#include "kernels/Permute.hpp"
#include "scene/CaseFile.hpp"
#include "solver/FluxSelect.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

namespace detail {


template <int D, class F>
void with_eos(const Scene& s, F&& f) {
  if (s.eos == EosLaw::Tait) f(TaitEos{s.rho0, s.c0, s.tait_gamma, s.eos_background_pressure});
  else f(LinearEos{s.rho0, s.c0, s.eos_background_pressure});
}

}  // namespace detail

template <int D>
Simulation<D>::Simulation(const Scene& scene) : scene_(scene), p_(count_particles(scene)) {
  if (scene.dimension != D) throw std::logic_error("Simulation<D>: scene dimension mismatch");
  R_ = scene.R();
  cutoff_ = R_ + scene.neighbour_skin * scene.dx;
  for (int k = 0; k < D; ++k) {
    box_.lo[k] = scene.domain.min[k];
    box_.len[k] = scene.domain.max[k] - scene.domain.min[k];
    box_.periodic[k] = scene.periodic[k];
    if (box_.periodic[k] && box_.len[k] < 2.0 * cutoff_)
      throw std::invalid_argument("a periodic axis must be at least 2 (R + skin) long");
  }
  p_.allocate(field::Position{});
  p_.allocate(field::Velocity{});
  p_.allocate(field::Density{});
  p_.allocate(field::Pressure{});
  p_.allocate(field::Mass{});
  p_.allocate(field::GlobalId{});
  p_.allocate(field::Acceleration{});
  p_.allocate(field::DensityRate{});
  if (scene.delta_sph > 0) p_.allocate(field::DensityGradient{});
  flux_ = with_kernel<D>(scene.kernel, R_, [&](auto W) { return select_flux<D, decltype(W)>(scene); });
  fill();
  detail::with_eos<D>(scene_, [&](auto eos) {
    update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), static_cast<int>(p_.size()));
  });
  initial_ = diagnostics();
}

// Lattice fill of each block at (k + 1/2) dx, with its initial velocity and pressure.
template <int D>
void Simulation<D>::fill() {
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto m = p_.get(field::Mass{});
  const auto id = p_.get(field::GlobalId{});
  const Scene s = scene_;
  const double dx = s.dx;
  const double volume = std::pow(dx, D);
  double g[D];
  double gnorm = 0;
  for (int k = 0; k < D; ++k) {
    g[k] = s.gravity[k] + s.body_force[k];
    gnorm += g[k] * g[k];
  }
  gnorm = std::sqrt(gnorm);
  std::int64_t offset = 0;
  for (const FluidBlock& b : s.blocks) {
    int cnt[D];
    double lo[D], top = 0;
    std::int64_t nb = 1;
    for (int k = 0; k < D; ++k) {
      cnt[k] = static_cast<int>(std::llround((b.box.max[k] - b.box.min[k]) / dx));
      lo[k] = b.box.min[k];
      nb *= cnt[k];
    }
    // hydrostatic column: the free surface is the block face facing against gravity
    for (int k = 0; k < D; ++k) top += (g[k] > 0 ? b.box.min[k] : b.box.max[k]) * (-g[k]);
    const FluidBlock blk = b;
    const std::int64_t off = offset;
    const double k_tg = blk.tg_wavelength > 0 ? 2.0 * M_PI / blk.tg_wavelength : 0.0;
    const bool tait = s.eos == EosLaw::Tait;
    const double rho0 = s.rho0, c0 = s.c0, gam = s.tait_gamma;
    Kokkos::parallel_for("ondine::InitialFill", Kokkos::RangePolicy<ExecSpace>(0, nb), KOKKOS_LAMBDA(const std::int64_t a) {
      const std::int64_t i = off + a;
      std::int64_t rest = a;
      double pos[D];
      for (int k = 0; k < D; ++k) {
        pos[k] = lo[k] + (static_cast<double>(rest % cnt[k]) + 0.5) * dx;
        rest /= cnt[k];
      }
      for (int k = 0; k < D; ++k) x(i, k) = pos[k];
      double P = 0.0;
      if (blk.velocity_kind == InitialVelocity::TaylorGreen) {
        const double U = blk.tg_amplitude;
        u(i, 0) = -U * kmath::cos(k_tg * pos[0]) * kmath::sin(k_tg * pos[1]);
        u(i, 1) = U * kmath::sin(k_tg * pos[0]) * kmath::cos(k_tg * pos[1]);
        for (int k = 2; k < D; ++k) u(i, k) = 0.0;
      } else {
        for (int k = 0; k < D; ++k) u(i, k) = blk.velocity[k];
      }
      if (blk.pressure_kind == InitialPressure::Hydrostatic) {
        double h = top;  // depth below the free surface along g: (x - x_top) . g
        for (int k = 0; k < D; ++k) h += pos[k] * g[k];
        P = rho0 * h;  // rho0 * (g . (x - x_top)) >= 0 inside the block
      } else if (blk.pressure_kind == InitialPressure::TaylorGreen) {
        const double U = blk.tg_amplitude;
        P = -0.25 * rho0 * U * U * (kmath::cos(2.0 * k_tg * pos[0]) + kmath::cos(2.0 * k_tg * pos[1]));
      }
      const double r = tait ? rho0 * kmath::pow(1.0 + gam * P / (rho0 * c0 * c0), 1.0 / gam) : rho0 + P / (c0 * c0);
      rho(i) = r;
      m(i) = r * volume;
      id(i) = i;
    });
    offset += nb;
  }
  (void)gnorm;
}

template <int D>
std::int64_t Simulation<D>::pair_count() const {
  // pairs within R, both ways, from the current list (skin pairs excluded)
  const auto x = p_.get(field::Position{});
  const auto list = list_;
  const auto box = box_;
  const double R2 = R_ * R_;
  std::int64_t total = 0;
  if (!list_valid_) return 0;
  Kokkos::parallel_reduce("ondine::PairCount", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p_.size())),
                          KOKKOS_LAMBDA(const int i, std::int64_t& acc) {
                            const Vec<D> xi = load<D>(x, i);
                            for (int n = 0; n < list.num_neighbours(i); ++n)
                              if (norm2(box.delta(xi, load<D>(x, list.neighbour(i, n)))) < R2) ++acc;
                          },
                          total);
  return total;
}

template <int D>
void Simulation<D>::ensure_neighbours() {
  const int n = static_cast<int>(p_.size());
  const auto x = p_.get(field::Position{});
  if (list_valid_ && scene_.neighbour_skin > 0) {
    // Verlet criterion: rebuild once some particle moved more than skin/2.
    const auto xb = x_at_build_;
    const auto box = box_;
    double d2max = 0;
    Kokkos::parallel_reduce("ondine::NeighbourList::displacement", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& mx) {
                              const double d2 = norm2(box.delta(load<D>(x, i), load<D>(xb, i)));
                              if (d2 > mx) mx = d2;
                            },
                            Kokkos::Max<double>(d2max));
    const double half_skin = 0.5 * scene_.neighbour_skin * scene_.dx;
    if (d2max < half_skin * half_skin) return;
  }
  cells_.build(make_cell_grid(box_, cutoff_), x, n);
  list_.build(cells_, box_, x, n, cutoff_);
  if (scene_.neighbour_skin > 0) {
    if (x_at_build_.extent(0) != x.extent(0))
      x_at_build_ = field_view_t<field::Position, D>("ondine::NeighbourList::x_at_build", x.extent(0));
    Kokkos::deep_copy(x_at_build_, x);
  }
  list_valid_ = true;
  ++builds_;
}

template <int D>
void Simulation<D>::reorder_by_cell() {
  const int n = static_cast<int>(p_.size());
  cells_.build(make_cell_grid(box_, cutoff_), p_.get(field::Position{}), n);
  const auto perm = Kokkos::subview(cells_.sorted, std::make_pair(0, n));
  Kokkos::View<int*, MemSpace> order("ondine::Reorder::order", n);
  Kokkos::deep_copy(order, perm);
  p_.permute([&order](const auto& v) { return permuted(v, order); });
  list_valid_ = false;
}

template <int D>
void Simulation<D>::evaluate() {
  ensure_neighbours();
  const int n = static_cast<int>(p_.size());
  FluxArgs<D> a;
  a.n = n;
  a.list = list_;
  a.box = box_;
  a.R = R_;
  for (int k = 0; k < D; ++k) a.body[k] = scene_.gravity[k] + scene_.body_force[k];
  a.x = p_.get(field::Position{});
  a.u = p_.get(field::Velocity{});
  a.rho = p_.get(field::Density{});
  a.P = p_.get(field::Pressure{});
  a.m = p_.get(field::Mass{});
  a.du = p_.get(field::Acceleration{});
  a.drho = p_.get(field::DensityRate{});
  a.nu = scene_.nu;
  a.delta_coeff = scene_.delta_sph * scene_.c0 * R_;
  a.av_alpha_R_c0 = scene_.artificial_viscosity * R_ * scene_.c0;
  detail::with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, a.rho, a.P, n); });
  if (scene_.background_pressure) {
    // (2.105): P_min = max(0, -min_k P_k)
    double pmin = 0;
    const auto P = a.P;
    Kokkos::parallel_reduce("ondine::BackgroundPressure::min", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& mn) { if (P(i) < mn) mn = P(i); },
                            Kokkos::Min<double>(pmin));
    a.P_min = pmin < 0 ? -pmin : 0.0;
  }
  if (scene_.delta_sph > 0) {
    a.grad_rho = p_.get(field::DensityGradient{});
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      DensityGradientPass<D, decltype(W)>{list_, box_, W, R_ * R_, a.x, a.rho, a.m, a.grad_rho}.run(n);
    });
  }
  flux_(a);
}

// dt = min(CFL_a R / c_max (2.102), CFL_nu R^2 / nu (2.103), CFL_f sqrt(R / |a|_max) [V&I 11]).
template <int D>
double Simulation<D>::time_step() const {
  const int n = static_cast<int>(p_.size());
  const auto rho = p_.get(field::Density{});
  const auto du = p_.get(field::Acceleration{});
  double cmax = 0, a2max = 0;
  detail::with_eos<D>(scene_, [&](auto eos) {
    Kokkos::parallel_reduce("ondine::TimeStep::sound_speed", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& mx) {
                              const double c = eos.sound_speed(rho(i));
                              if (c > mx) mx = c;
                            },
                            Kokkos::Max<double>(cmax));
  });
  Kokkos::parallel_reduce("ondine::TimeStep::acceleration", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) {
                            const double a2 = norm2(load<D>(du, i));
                            if (a2 > mx) mx = a2;
                          },
                          Kokkos::Max<double>(a2max));
  double dt = scene_.cfl_acoustic * R_ / cmax;
  if (scene_.nu > 0) dt = std::min(dt, scene_.cfl_viscous * R_ * R_ / scene_.nu);
  if (a2max > 0) dt = std::min(dt, scene_.cfl_force * std::sqrt(R_ / std::sqrt(a2max)));
  if (!std::isfinite(dt) || dt <= 0) throw std::runtime_error("time step is not finite (the state contains NaN)");
  return dt;
}

// One stage of an explicit Runge-Kutta step: y = y0 + c_dt k with k the current
// derivatives, and the weighted sum acc += w k used by the final RK4 update.
template <int D>
void Simulation<D>::stage_update(double c_dt, double w, bool first) {
  const int n = static_cast<int>(p_.size());
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto du = p_.get(field::Acceleration{});
  const auto drho = p_.get(field::DensityRate{});
  const auto x0 = x0_, u0 = u0_, r0 = rho0_, xa = x_acc_, ua = u_acc_, ra = rho_acc_;
  const auto box = box_;
  const bool acc = w != 0.0;
  Kokkos::parallel_for("ondine::Integrator::stage", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
    for (int k = 0; k < D; ++k) {
      const double uk = u(i, k);
      if (acc) {
        xa(i, k) = (first ? 0.0 : xa(i, k)) + w * uk;
        ua(i, k) = (first ? 0.0 : ua(i, k)) + w * du(i, k);
      }
      x(i, k) = box.wrap(x0(i, k) + c_dt * uk, k);
      u(i, k) = u0(i, k) + c_dt * du(i, k);
    }
    if (acc) ra(i) = (first ? 0.0 : ra(i)) + w * drho(i);
    rho(i) = r0(i) + c_dt * drho(i);
  });
}

template <int D>
double Simulation<D>::step(double t_stop) {
  const int n = static_cast<int>(p_.size());
  if (scene_.reorder_interval > 0 && steps_ % scene_.reorder_interval == 0) reorder_by_cell();
  if (x0_.extent(0) != p_.size()) {
    x0_ = field_view_t<field::Position, D>("ondine::Integrator::x0", n);
    u0_ = field_view_t<field::Velocity, D>("ondine::Integrator::u0", n);
    rho0_ = field_view_t<field::Density, D>("ondine::Integrator::rho0", n);
    if (scene_.integrator == TimeIntegrator::RK4) {
      x_acc_ = field_view_t<field::Position, D>("ondine::Integrator::x_sum", n);
      u_acc_ = field_view_t<field::Velocity, D>("ondine::Integrator::u_sum", n);
      rho_acc_ = field_view_t<field::Density, D>("ondine::Integrator::rho_sum", n);
    }
  }
  Kokkos::deep_copy(x0_, p_.get(field::Position{}));
  Kokkos::deep_copy(u0_, p_.get(field::Velocity{}));
  Kokkos::deep_copy(rho0_, p_.get(field::Density{}));

  evaluate();  // k1 at y0, also the state the time step is computed from
  double dt = time_step();
  if (t_ + dt > t_stop) dt = std::max(t_stop - t_, 1e-300);
  else if (t_ + 1.5 * dt > t_stop) dt = 0.5 * (t_stop - t_);  // avoid a sliver step before t_stop

  if (scene_.integrator == TimeIntegrator::RK4) {
    // classical RK4: y1 = y0 + dt/6 (k1 + 2 k2 + 2 k3 + k4)
    stage_update(0.5 * dt, 1.0 / 6.0, true);
    evaluate();
    stage_update(0.5 * dt, 2.0 / 6.0, false);
    evaluate();
    stage_update(dt, 2.0 / 6.0, false);
    evaluate();
    // final: y = y0 + dt (acc + k4/6)
    const auto x = p_.get(field::Position{});
    const auto u = p_.get(field::Velocity{});
    const auto rho = p_.get(field::Density{});
    const auto du = p_.get(field::Acceleration{});
    const auto drho = p_.get(field::DensityRate{});
    const auto x0 = x0_, u0 = u0_, r0 = rho0_, xa = x_acc_, ua = u_acc_, ra = rho_acc_;
    const auto box = box_;
    Kokkos::parallel_for("ondine::Integrator::rk4_final", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < D; ++k) {
        const double uk = u(i, k);
        x(i, k) = box.wrap(x0(i, k) + dt * (xa(i, k) + uk / 6.0), k);
        u(i, k) = u0(i, k) + dt * (ua(i, k) + du(i, k) / 6.0);
      }
      rho(i) = r0(i) + dt * (ra(i) + drho(i) / 6.0);
    });
  } else {
    // explicit midpoint: y_1/2 = y0 + dt/2 k1, y1 = y0 + dt k(y_1/2)
    stage_update(0.5 * dt, 0.0, true);
    evaluate();
    stage_update(dt, 0.0, false);
  }
  t_ += dt;
  ++steps_;
  return dt;
}

template <int D>
Diagnostics Simulation<D>::diagnostics() const {
  const int n = static_cast<int>(p_.size());
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
  const auto box = box_;
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
                            c += (out ? 1 : 0) + (nan ? (std::int64_t(1) << 40) : 0);
                          },
                          bad);
  d.outside_domain = bad & ((std::int64_t(1) << 40) - 1);
  d.finite = (bad >> 40) == 0 && std::isfinite(d.kinetic_energy);
  return d;
}

// Shepard interpolation at each probe (thesis 2.40-2.41), by a reduction over all particles.
template <int D>
std::vector<ProbeSample> Simulation<D>::sample_probes() const {
  std::vector<ProbeSample> out;
  const int n = static_cast<int>(p_.size());
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto rho = p_.get(field::Density{});
  const auto P = p_.get(field::Pressure{});
  const auto m = p_.get(field::Mass{});
  const auto box = box_;
  for (const Probe& pr : scene_.probes) {
    Vec<D> xp;
    for (int k = 0; k < D; ++k) xp[k] = pr.position[k];
    ProbeSample s;
    with_kernel<D>(scene_.kernel, R_, [&](auto W) {
      // one reduction per quantity: probes are sampled at output times only
      auto sum = [&](auto value) {
        double acc = 0;
        Kokkos::parallel_reduce("ondine::Probe", Kokkos::RangePolicy<ExecSpace>(0, n),
                                KOKKOS_LAMBDA(const int j, double& a) {
                                  const double r = kmath::sqrt(norm2(box.delta(xp, load<D>(x, j))));
                                  a += m(j) / rho(j) * W.value(r) * value(j);
                                },
                                acc);
        return acc;
      };
      s.shepard = sum(KOKKOS_LAMBDA(int) { return 1.0; });
      if (s.shepard > 0) {
        s.pressure = sum(KOKKOS_LAMBDA(int j) { return P(j); }) / s.shepard;
        s.density = sum(KOKKOS_LAMBDA(int j) { return rho(j); }) / s.shepard;
        for (int k = 0; k < D; ++k) s.velocity[k] = sum(KOKKOS_LAMBDA(int j) { return u(j, k); }) / s.shepard;
      }
    });
    out.push_back(s);
  }
  return out;
}

template <int D>
std::map<std::string, double> Simulation<D>::errors() const {
  std::map<std::string, double> e;
  const Diagnostics d = diagnostics();
  e["mass_drift"] = std::abs(d.mass - initial_.mass) / initial_.mass;
  bool all_periodic = true;
  for (int k = 0; k < D; ++k) all_periodic = all_periodic && scene_.periodic[k];
  if (all_periodic) {
    // With no walls, internal forces cancel pairwise: P(t) = P(0) + M (g + f) t exactly.
    double err2 = 0, scale2 = 0;
    for (int k = 0; k < D; ++k) {
      const double expect = initial_.momentum[k] + d.mass * (scene_.gravity[k] + scene_.body_force[k]) * t_;
      err2 += (d.momentum[k] - expect) * (d.momentum[k] - expect);
      scale2 += expect * expect;
    }
    const double scale = std::max(std::sqrt(scale2), d.mass * scene_.reference_velocity);
    e["momentum_balance_error"] = std::sqrt(err2) / scale;
  }
  bool taylor_green = all_periodic && D == 2;
  for (const FluidBlock& b : scene_.blocks) taylor_green = taylor_green && b.velocity_kind == InitialVelocity::TaylorGreen;
  if (taylor_green) {
    // Decaying vortex: u = -U e^{bt} cos kx sin ky, v = U e^{bt} sin kx cos ky, b = -2 nu k^2.
    const FluidBlock& b = scene_.blocks.front();
    const double k = 2.0 * M_PI / b.tg_wavelength;
    const double amp = b.tg_amplitude * std::exp(-2.0 * scene_.nu * k * k * t_);
    const int n = static_cast<int>(p_.size());
    const auto x = p_.get(field::Position{});
    const auto u = p_.get(field::Velocity{});
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
    e["velocity_l2"] = std::sqrt(num / den);
    e["velocity_linf"] = linf / amp;
    e["max_speed_decay_error"] = std::abs(d.max_speed - amp) / amp;
  }
  return e;
}

}  // namespace ondine
