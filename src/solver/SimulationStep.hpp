#pragma once
// Simulation<D>: the time step (2.102)-(2.103), the integrators (classical RK4, explicit
// midpoint) with the step hooks' points (solver/StepHook.hpp), and the state check that stops
// a blown-up run. Included by SimulationImpl.hpp only.
#include <cmath>
#include <limits>

#include "kernels/TimeStep.hpp"
#include "solver/BlowUpCheck.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/StageStorage.hpp"
#include "solver/StepState.hpp"

namespace ondine {

template <int D>
double Simulation<D>::time_step(const int only) const {
  // only >= 0 (local time stepping): that level's SPH particles and radius; otherwise every
  // owned particle and one global step, bounded by the finest level that has SPH particles
  // (on any rank)
  const std::vector<LevelSpan<D>> levels = this->levels();
  const int first = only >= 0 ? levels[only].first : 0, end = only >= 0 ? levels[only].active_end : n_own_;
  const auto rho = p_.get(field::Density{});
  const auto du = p_.get(field::Acceleration{});
  double cmax = 0, a2max = 0;
  with_eos<D>(scene_, [&](auto eos) {
    Kokkos::parallel_reduce("ondine::TimeStep::sound_speed", Kokkos::RangePolicy<ExecSpace>(first, end),
                            MaxSoundSpeed<D, decltype(eos)>{eos, rho}, Kokkos::Max<double>(cmax));
  });
  Kokkos::parallel_reduce("ondine::TimeStep::acceleration", Kokkos::RangePolicy<ExecSpace>(first, end),
                          MaxNorm2<D, std::decay_t<decltype(du)>>{du}, Kokkos::Max<double>(a2max));
  cmax = comm().max(cmax);
  a2max = comm().max(a2max);
  if (only >= 0 && !(cmax > 0)) return std::numeric_limits<double>::infinity();  // no SPH particle of the level on any rank
  std::int64_t finest = 0;
  for (const LevelSpan<D>& L : levels)
    if (L.active_end > L.first) finest = L.level;
  const double R = only >= 0 ? levels[only].R : levels.size() == 1 ? levels[0].R : levels[comm().max(finest)].R;
  double dt = scene_.cfl_acoustic * R / cmax;
  // with a turbulence model the largest nu + nu_T bounds the viscous step (2.103) and, as the wall
  // function's stress u_*^2 = nu_eff u_t / y with nu_eff of the order of nu_T there, the wall term's
  double nu_max = scene_.nu;
  if (scene_.turbulence.eddy_viscous()) {
    double nu_T = 0;
    Kokkos::parallel_reduce("ondine::TimeStep::eddy_viscosity", Kokkos::RangePolicy<ExecSpace>(first, end),
                            MaxValue<std::decay_t<decltype(p_.get(field::EddyViscosity{}))>>{p_.get(field::EddyViscosity{})},
                            Kokkos::Max<double>(nu_T));
    nu_max += comm().max(nu_T);
  }
  if (nu_max > 0) dt = std::min(dt, scene_.cfl_viscous * R * R / nu_max);
  if (a2max > 0) dt = std::min(dt, scene_.cfl_force * std::sqrt(R / std::sqrt(a2max)));
  // the viscous wall term's stiffness, level by level
  if (!walls_.empty() && scene_.viscous_term != ViscousTerm::None)
    for (const LevelSpan<D>& L : levels) {
      if (only >= 0 && L.level != only) continue;
      double kmax = scheme_.wall_stiffness(context(L));  // 0 on a rank without SPH particles of this level
      kmax = comm().max(kmax) * (scene_.nu > 0 ? nu_max / scene_.nu : 1.0);
      if (kmax > 0) dt = std::min(dt, 1.0 / kmax);
    }
  if (!std::isfinite(dt) || dt <= 0) throw std::runtime_error("time step is not finite (the state contains NaN)");
  return dt;
}

template <int D>
double Simulation<D>::step(double t_stop) {
  if (scene_.reorder_interval > 0 && steps_ % scene_.reorder_interval == 0) domain_.reorder_by_cell(p_, n_own_);
  StepState<D> state(*this);
  for (auto& h : hooks_) h->step_start(state);  // the refinement's last (hooks/StepHooks.hpp)
  for (auto& h : hooks_) h->after_lists(state);
  allocate_stage_storage(p_, scene_);
  if (refinement_ && scene_.refinement_local_time_stepping) return step_local(t_stop);  // solver/SimulationLocalSteps.hpp
  Kokkos::deep_copy(p_.get(field::StagePosition{}), p_.get(field::Position{}));
  Kokkos::deep_copy(p_.get(field::StageVelocity{}), p_.get(field::Velocity{}));
  Kokkos::deep_copy(p_.get(field::StageDensity{}), p_.get(field::Density{}));
  if (p_.has(field::MassRate{})) Kokkos::deep_copy(p_.get(field::StageMass{}), p_.get(field::Mass{}));

  // one stage of an explicit Runge-Kutta step: y = y0 + c_dt k with k the current
  // derivatives, and the weighted sum acc += w k used by the final RK4 update
  const auto stage = [&](double c_dt, double w, bool first) {
    RungeKuttaStage<D>{domain_.local_box(), stage_views(p_, scene_), c_dt, w, w != 0.0, first}.run(n_own_);
    domain_.halos_stale();
  };
  stage_time_ = t_;
  evaluate();  // k1 at y0, also the state the time step is computed from
  const double dt = capped_step(time_step(), t_stop);

  integrate(t_, dt, stage,
            [&](double t) {
              stage_time_ = t;
              evaluate(true);
            },
            [&] {
              RungeKutta4Final<D>{domain_.local_box(), stage_views(p_, scene_), dt}.run(n_own_);
              domain_.halos_stale();
            });
  finish_step(dt);
  if (refinement_) count_particle_steps(-1);
  return dt;
}

template <int D>
void Simulation<D>::count_particle_steps(const int level) {
  const std::vector<LevelSpan<D>> L = levels();
  if (level_particle_steps_.size() != L.size()) level_particle_steps_.assign(L.size(), 0.0);
  for (const LevelSpan<D>& s : L)
    if (level < 0 || s.level == level) level_particle_steps_[s.level] += s.active_end - s.first;
}

template <int D>
template <class Stage, class EvaluateAt, class Final>
void Simulation<D>::integrate(const double t0, const double h, const Stage& stage, const EvaluateAt& evaluate_at, const Final& rk4_final) {
  if (scene_.integrator == TimeIntegrator::RK4) {
    // classical RK4: y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4)
    stage(0.5 * h, 1.0 / 6.0, true);
    evaluate_at(t0 + 0.5 * h);
    stage(0.5 * h, 2.0 / 6.0, false);
    evaluate_at(t0 + 0.5 * h);
    stage(h, 2.0 / 6.0, false);
    evaluate_at(t0 + h);
    rk4_final();  // y = y0 + h (acc + k4/6)
  } else {
    // explicit midpoint: y_1/2 = y0 + h/2 k1, y1 = y0 + h k(y_1/2)
    stage(0.5 * h, 0.0, true);
    evaluate_at(t0 + 0.5 * h);
    stage(h, 0.0, false);
  }
}

// dt, shortened so that the step ends on t_stop without a sliver step before it
template <int D>
double Simulation<D>::capped_step(double dt, double t_stop) const {
  if (t_ + dt > t_stop) return std::max(t_stop - t_, 1e-300);
  if (t_ + 1.5 * dt > t_stop) return 0.5 * (t_stop - t_);
  return dt;
}

// the step's end: the hooks' (shifting, the impermeability guard, the start-up damping, ...:
// hooks/StepHooks.hpp), the state check, the clock
template <int D>
void Simulation<D>::finish_step(double dt) {
  StepState<D> state(*this);
  for (auto& h : hooks_) h->step_end(state, dt);
  try {
    check_state(p_, n_own_, scene_, comm(), steps_, t_, dt);
  } catch (const BlowUp&) {
    domain_.halos_stale();  // the state of the step's start is back
    throw;
  }
  t_ += dt;
  ++steps_;
  stage_time_ = t_;
}

}  // namespace ondine
