#pragma once
// Simulation<D>: the time step (2.102)-(2.103), the integrators (classical RK4, explicit
// midpoint) with the step hooks' points (solver/StepHook.hpp), and the state check that stops
// a blown-up run. Included by SimulationImpl.hpp only.
#include <climits>
#include <cmath>
#include <sstream>

#include "kernels/Integrator.hpp"
#include "kernels/StateCheck.hpp"
#include "kernels/TimeStep.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/StepState.hpp"

namespace ondine {

template <int D>
double Simulation<D>::time_step() const {
  const int n = n_own_;
  const auto rho = p_.get(field::Density{});
  const auto du = p_.get(field::Acceleration{});
  double cmax = 0, a2max = 0;
  with_eos<D>(scene_, [&](auto eos) {
    Kokkos::parallel_reduce("ondine::TimeStep::sound_speed", Kokkos::RangePolicy<ExecSpace>(0, n),
                            MaxSoundSpeed<D, decltype(eos)>{eos, rho}, Kokkos::Max<double>(cmax));
  });
  Kokkos::parallel_reduce("ondine::TimeStep::acceleration", Kokkos::RangePolicy<ExecSpace>(0, n),
                          MaxNorm2<D, std::decay_t<decltype(du)>>{du}, Kokkos::Max<double>(a2max));
  cmax = comm().max(cmax);
  a2max = comm().max(a2max);
  // one global step, bounded by the finest level that has SPH particles (on any rank)
  const std::vector<LevelSpan<D>> levels = this->levels();
  std::int64_t finest = 0;
  for (const LevelSpan<D>& L : levels)
    if (L.active_end > L.first) finest = L.level;
  const double R = levels.size() == 1 ? levels[0].R : levels[comm().max(finest)].R;
  double dt = scene_.cfl_acoustic * R / cmax;
  if (scene_.nu > 0) dt = std::min(dt, scene_.cfl_viscous * R * R / scene_.nu);
  if (a2max > 0) dt = std::min(dt, scene_.cfl_force * std::sqrt(R / std::sqrt(a2max)));
  // the viscous wall term's stiffness, level by level
  if (!walls_.empty() && scene_.viscous_term != ViscousTerm::None)
    for (const LevelSpan<D>& L : levels) {
      double kmax = scheme_.wall_stiffness(pass_context(L));  // 0 on a rank without SPH particles of this level
      kmax = comm().max(kmax);
      if (kmax > 0) dt = std::min(dt, 1.0 / kmax);
    }
  if (!std::isfinite(dt) || dt <= 0) throw std::runtime_error("time step is not finite (the state contains NaN)");
  return dt;
}

// The state, its derivatives and the integrator's stage storage (RK4 sums only with RK4).
template <int D>
RungeKuttaViews<D> Simulation<D>::stage_views() const {
  const bool rk4 = scene_.integrator == TimeIntegrator::RK4;
  RungeKuttaViews<D> v{p_.get(field::Position{}),
          p_.get(field::Velocity{}),
          p_.get(field::Density{}),
          p_.get(field::Acceleration{}),
          p_.get(field::DensityRate{}),
          p_.get(field::StagePosition{}),
          rk4 ? p_.get(field::StagePositionSum{}) : field_view_t<field::Position, D>(),
          p_.get(field::StageVelocity{}),
          rk4 ? p_.get(field::StageVelocitySum{}) : field_view_t<field::Velocity, D>(),
          p_.get(field::StageDensity{}),
          rk4 ? p_.get(field::StageDensitySum{}) : field_view_t<field::Density, D>()};
  if (p_.has(field::TransportCorrection{})) {
    v.du0 = p_.get(field::TransportCorrection{});
    v.transport = true;
  }
  if (p_.has(field::MassRate{})) {
    v.m = p_.get(field::Mass{});
    v.m0 = p_.get(field::StageMass{});
    if (rk4) v.ma = p_.get(field::StageMassSum{});
    v.dm = p_.get(field::MassRate{});
    v.masses = true;
  }
  return v;
}

// One stage of an explicit Runge-Kutta step: y = y0 + c_dt k with k the current
// derivatives, and the weighted sum acc += w k used by the final RK4 update.
template <int D>
void Simulation<D>::stage_update(double c_dt, double w, bool first) {
  RungeKuttaStage<D>{domain_.local_box(), stage_views(), c_dt, w, w != 0.0, first}.run(n_own_);
  domain_.halos_stale();
}

template <int D>
void Simulation<D>::allocate_stage_storage() {
  if (p_.has(field::StagePosition{})) return;
  p_.allocate(field::StagePosition{});
  p_.allocate(field::StageVelocity{});
  p_.allocate(field::StageDensity{});
  if (scene_.integrator == TimeIntegrator::RK4) {
    p_.allocate(field::StagePositionSum{});
    p_.allocate(field::StageVelocitySum{});
    p_.allocate(field::StageDensitySum{});
  }
  if (p_.has(field::MassRate{})) {
    p_.allocate(field::StageMass{});
    if (scene_.integrator == TimeIntegrator::RK4) p_.allocate(field::StageMassSum{});
  }
}

template <int D>
double Simulation<D>::step(double t_stop) {
  output_saved_ = false;  // finish_output() after a step has nothing to put back
  if (scene_.reorder_interval > 0 && steps_ % scene_.reorder_interval == 0) domain_.reorder_by_cell(p_, n_own_);
  StepState<D> state(*this);
  for (auto& h : hooks_) h->step_start(state);
  if (apr_on_) refinement_step_start();
  for (auto& h : hooks_) h->after_lists(state);
  allocate_stage_storage();
  Kokkos::deep_copy(p_.get(field::StagePosition{}), p_.get(field::Position{}));
  Kokkos::deep_copy(p_.get(field::StageVelocity{}), p_.get(field::Velocity{}));
  Kokkos::deep_copy(p_.get(field::StageDensity{}), p_.get(field::Density{}));
  if (p_.has(field::MassRate{})) Kokkos::deep_copy(p_.get(field::StageMass{}), p_.get(field::Mass{}));

  stage_time_ = t_;
  evaluate();  // k1 at y0, also the state the time step is computed from
  double dt = time_step();
  if (t_ + dt > t_stop) dt = std::max(t_stop - t_, 1e-300);
  else if (t_ + 1.5 * dt > t_stop) dt = 0.5 * (t_stop - t_);  // avoid a sliver step before t_stop

  if (scene_.integrator == TimeIntegrator::RK4) {
    // classical RK4: y1 = y0 + dt/6 (k1 + 2 k2 + 2 k3 + k4)
    stage_update(0.5 * dt, 1.0 / 6.0, true);
    stage_time_ = t_ + 0.5 * dt;
    evaluate(true);
    stage_update(0.5 * dt, 2.0 / 6.0, false);
    evaluate(true);
    stage_update(dt, 2.0 / 6.0, false);
    stage_time_ = t_ + dt;
    evaluate(true);
    // final: y = y0 + dt (acc + k4/6)
    RungeKutta4Final<D>{domain_.local_box(), stage_views(), dt}.run(n_own_);
    domain_.halos_stale();
  } else {
    // explicit midpoint: y_1/2 = y0 + dt/2 k1, y1 = y0 + dt k(y_1/2)
    stage_update(0.5 * dt, 0.0, true);
    stage_time_ = t_ + 0.5 * dt;
    evaluate(true);
    stage_update(dt, 0.0, false);
  }
  // shifting, the impermeability guard, the start-up damping, ... (hooks/StepHooks.hpp)
  for (auto& h : hooks_) h->step_end(state, dt);
  check_state(dt);
  t_ += dt;
  ++steps_;
  stage_time_ = t_;
  return dt;
}

// Stops the run at the first step that produced a non-finite state or a density
// outside [0.5, 2] rho0, naming the step, time, particle and quantity; the state
// at the start of the step is put back so that the caller can write it.
template <int D>
void Simulation<D>::check_state(double dt) {
  int first = INT_MAX;
  Kokkos::parallel_reduce("ondine::StateCheck", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          FirstBadParticle<D>{p_.get(field::Position{}), p_.get(field::Velocity{}),
                                              p_.get(field::Density{}), 0.5 * scene_.rho0, 2.0 * scene_.rho0},
                          Kokkos::Min<int>(first));
  // the lowest rank with a bad particle names it
  const std::int64_t bad_rank = comm().min(first == INT_MAX ? std::int64_t(comm().size()) : std::int64_t(comm().rank()));
  if (bad_rank == comm().size()) return;
  if (first == INT_MAX) first = 0;
  // what went wrong, read from the host for that one particle
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::Position{}), first, Kokkos::ALL));
  auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::Velocity{}), first, Kokkos::ALL));
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::Density{}), first));
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p_.get(field::GlobalId{}), first));
  std::ostringstream m;
  m << "blow-up at step " << steps_ + 1 << ", t = " << t_ + dt << " s: particle " << id() << " (at";
  for (int k = 0; k < D; ++k) m << " " << x(k);
  m << ") has ";
  bool finite = std::isfinite(r());
  for (int k = 0; k < D; ++k) finite = finite && std::isfinite(x(k)) && std::isfinite(u(k));
  if (!finite) {
    m << "a non-finite state (density " << r() << ", velocity";
    for (int k = 0; k < D; ++k) m << " " << u(k);
    m << ")";
  } else {
    m << "density " << r() / scene_.rho0 << " rho0, outside [0.5, 2] rho0";
  }
  Kokkos::deep_copy(p_.get(field::Position{}), p_.get(field::StagePosition{}));
  Kokkos::deep_copy(p_.get(field::Velocity{}), p_.get(field::StageVelocity{}));
  Kokkos::deep_copy(p_.get(field::Density{}), p_.get(field::StageDensity{}));
  if (p_.has(field::MassRate{})) Kokkos::deep_copy(p_.get(field::Mass{}), p_.get(field::StageMass{}));
  domain_.halos_stale();
  throw BlowUp(comm().broadcast(m.str(), static_cast<int>(bad_rank)));
}


}  // namespace ondine
