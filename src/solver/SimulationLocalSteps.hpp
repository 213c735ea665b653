#pragma once
// Simulation<D>: local time stepping by level (refinement.local_time_stepping; docs/apr.md;
// not in the seeds). A coarse step of dt_0 advances level 0 over dt_0, then level 1 over two
// steps of dt_0/2, each followed by level 2's two steps of dt_0/4, and so on (the recursive
// subcycling of Berger & Oliger). A level's step runs the integrator's stages over its own
// particles (SPH particles and guards) and evaluates its own fluxes only; its guards are
// interpolated (5.24) at each stage from the other levels' SPH particles at the stage's time
// (kernels/apr/LevelTimeInterpolation.hpp): a coarser level, already at the end of its step,
// interpolated linearly in time; a finer level, not yet started, its velocity and density
// extrapolated from the start of this level's step by their rates there, and put back before
// its own steps. dt_0 = min over the levels of 2^l dt_l, dt_l the step (2.102)-(2.103) that
// level l's own SPH particles allow. Included by SimulationImpl.hpp only.
#include <cmath>
#include <limits>
#include <vector>

#include "kernels/apr/LevelTimeInterpolation.hpp"
#include "solver/StageStorage.hpp"
#include "solver/StepState.hpp"

namespace ondine {

template <int D>
double Simulation<D>::step_local(double t_stop) {
  const int nl = static_cast<int>(levels().size());
  if (static_cast<int>(level_steps_.size()) != nl) level_steps_.assign(nl, 0);
  if (!p_.has(field::LevelEndPosition{}) && nl > 1) {
    p_.allocate(field::LevelEndPosition{});
    p_.allocate(field::LevelEndVelocity{});
    p_.allocate(field::LevelEndDensity{});
  }
  stage_time_ = t_;
  eval_level_ = -1;
  evaluate();  // every level's first stage at t, the state the levels' steps are computed from
  // the deepest level with particles on some rank: the (empty) levels below it take no steps
  int depth = 1;
  {
    const std::vector<LevelSpan<D>> L = levels();
    for (int l = 1; l < nl; ++l)
      if (comm().max(static_cast<std::int64_t>(L[l].end - L[l].first)) > 0) depth = l + 1;
  }
  double dt0 = std::numeric_limits<double>::infinity();
  for (int l = 0; l < depth; ++l) dt0 = std::min(dt0, std::ldexp(time_step(l), l));
  if (!std::isfinite(dt0) || dt0 <= 0) throw std::runtime_error("time step is not finite (the state contains NaN)");
  dt0 = capped_step(dt0, t_stop);
  std::vector<double> start(depth, t_), span(depth, dt0);
  try {
    advance_level(0, t_, dt0, true, start, span);
  } catch (...) {
    eval_level_ = -1;
    throw;
  }
  eval_level_ = -1;
  stage_time_ = t_ + dt0;
  finish_step(dt0);
  return dt0;
}

// Level l from t0 to t0 + h (`fresh`: t0 is the coarse step's start, where evaluate() has
// already given every level its first stage), then the finer levels' two steps each.
template <int D>
void Simulation<D>::advance_level(const int l, const double t0, const double h, const bool fresh, std::vector<double>& start,
                                  std::vector<double>& span) {
  start[l] = t0;
  span[l] = h;
  eval_level_ = l;
  // the level's particles (SPH particles and guards) as they are sorted now: a list rebuild
  // inside an evaluation may migrate them (several ranks)
  const auto all = [&] {
    const LevelSpan<D> L = levels()[l];
    return std::pair<int, int>(L.first, L.end);
  };
  const auto sph = [&] {
    const LevelSpan<D> L = levels()[l];
    return std::pair<int, int>(L.first, L.active_end);
  };
  const auto views = [&] { return stage_views(p_, scene_); };
  {
    const auto [a, b] = all();
    RungeKuttaStart<D>{views()}.run(a, b);
  }
  const int depth = static_cast<int>(start.size());
  // the finer levels' SPH particles: their state now kept (LevelEnd*, free until their own
  // steps), extrapolated at this level's stages, put back after them
  const auto finer_state = [&](bool keep) {
    const std::vector<LevelSpan<D>> L = levels();
    for (int m = l + 1; m < depth; ++m) level_end_copy(L[m].first, L[m].active_end, keep);
    if (!keep) domain_.halos_stale();
  };
  const auto hold_finer_at = [&](double tau) {
    if (l + 1 >= depth) return;
    const std::vector<LevelSpan<D>> L = levels();
    for (int m = l + 1; m < depth; ++m)
      apr::LevelTimeExtrapolation<D>{p_.get(field::Velocity{}), p_.get(field::LevelEndVelocity{}),
                                     p_.get(field::Density{}), p_.get(field::LevelEndDensity{}),
                                     p_.get(field::Acceleration{}), p_.get(field::DensityRate{}), tau - t0}
          .run(L[m].first, L[m].active_end);
    domain_.halos_stale();
  };
  if (l + 1 < depth) finer_state(true);
  const auto stage = [&](double c_dt, double w, bool first) {
    const auto [a, b] = all();
    RungeKuttaStage<D>{domain_.local_box(), views(), c_dt, w, w != 0.0, first}.run(a, b);
    domain_.halos_stale();
  };
  const auto evaluate_at = [&](double tau, bool later_stage) {
    hold_coarser_at(l, tau, start, span);
    hold_finer_at(tau);
    stage_time_ = tau;
    evaluate(later_stage);
  };
  if (!fresh) {
    if (refinement_) refinement_->level_step_start(l);  // its guards' shape functions at the new positions
    evaluate_at(t0, false);
  }
  integrate(t0, h, stage, [&](double tau) { evaluate_at(tau, true); },
            [&] {
              const auto [a, b] = all();
              RungeKutta4Final<D>{domain_.local_box(), views(), h}.run(a, b);
              domain_.halos_stale();
            });
  ++level_steps_[l];
  count_particle_steps(l);
  stage_time_ = t0 + h;
  {
    StepState<D> state(*this);
    const auto [a, b] = all();
    for (auto& hk : hooks_) hk->level_step_end(state, l, a, b, h);  // the impermeability guard, shifting
  }
  if (l + 1 >= depth) return;
  finer_state(false);
  const auto end_state = [&](bool keep) {
    const auto [a, b] = sph();
    level_end_copy(a, b, keep);
  };
  end_state(true);
  advance_level(l + 1, t0, 0.5 * h, fresh, start, span);
  advance_level(l + 1, t0 + 0.5 * h, 0.5 * h, false, start, span);
  end_state(false);  // the finer levels' stages held it in between
  domain_.halos_stale();
  eval_level_ = l;
}

template <int D>
void Simulation<D>::level_end_copy(const int first, const int end, const bool keep) {
  apr::LevelEndCopy<D>{p_.get(field::Position{}), p_.get(field::LevelEndPosition{}), p_.get(field::Velocity{}),
                       p_.get(field::LevelEndVelocity{}), p_.get(field::Density{}), p_.get(field::LevelEndDensity{}), keep}
      .run(first, end);
}

// The SPH particles of every level coarser than l at time tau, between the start of their
// current step (the stage storage) and its end (LevelEnd*).
template <int D>
void Simulation<D>::hold_coarser_at(const int l, const double tau, const std::vector<double>& start, const std::vector<double>& span) {
  if (l == 0) return;
  const std::vector<LevelSpan<D>> levels = this->levels();
  for (int k = 0; k < l; ++k) {
    const double theta = (tau - start[k]) / span[k];
    apr::LevelTimeInterpolation<D>{domain_.local_box(),
                                   p_.get(field::Position{}), p_.get(field::StagePosition{}), p_.get(field::LevelEndPosition{}),
                                   p_.get(field::Velocity{}), p_.get(field::StageVelocity{}), p_.get(field::LevelEndVelocity{}),
                                   p_.get(field::Density{}), p_.get(field::StageDensity{}), p_.get(field::LevelEndDensity{}), theta}
        .run(levels[k].first, levels[k].active_end);
  }
  domain_.halos_stale();
}

}  // namespace ondine
