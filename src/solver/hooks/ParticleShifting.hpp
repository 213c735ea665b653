#pragma once
// Particle shifting (2.107)-(2.111) at the end of each step (scheme.shifting or transport:
// shifting): the shifted state is computed into scratch views, shown to the hooks' `shifted`
// point (the open boundaries keep their buffers there), then copied back; at most 0.02 dx
// per step (kernels/ShiftingPass.hpp). With refinement zones each level's SPH particles are
// shifted with their level's radius, spacing and list (their level's SPH particles and
// guards), at most 0.02 dx_l; guards are not shifted here (refinement.guard_shifting). With
// local time stepping each level is shifted at the end of each of its own steps.
#include <utility>
#include <vector>

#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class ParticleShifting final : public StepHook<D> {
 public:
  const char* name() const override { return "particle_shifting"; }
  void step_end(StepState<D>& s, double) override {
    if (!s.scene().refinement_local_time_stepping) shift(s, -1);
  }
  void level_step_end(StepState<D>& s, int level, int, int, double) override { shift(s, level); }

 private:
  // every level's SPH particles (only < 0) or those of level `only`
  void shift(StepState<D>& s, int only) {
    ParticleSet<D>& p = s.particles();
    s.ensure_lists();
    s.domain().refresh_state_halos(p);
    // with a free surface possible: the flags (4.86)-(4.87) of this state, halos included, for
    // the surface particles' tangential shift
    if (p.has(field::FreeSurface{})) {
      s.update_free_surface(only);
      s.domain().refresh(p, field::FreeSurface{});
    }
    const std::size_t n = p.size();
    if (x_.extent(0) != n) {
      x_ = field_view_t<field::Position, D>("ondine::Shifting::x", n);
      u_ = field_view_t<field::Velocity, D>("ondine::Shifting::u", n);
      rho_ = field_view_t<field::Density, D>("ondine::Shifting::rho", n);
    }
    // every level's shift from the state at the step's end (each level's SPH particles), then applied
    std::vector<LevelSpan<D>> levels = s.levels();
    if (only >= 0) levels = {levels[only]};
    for (const LevelSpan<D>& L : levels)
      if (L.active_end > L.first) s.scheme().shifting(s.context(L), x_, u_, rho_, 0.02 * L.dx);
    for (const LevelSpan<D>& L : levels) {
      if (L.active_end == L.first) continue;
      s.shifted(ShiftedState<D>{L.first, L.active_end, x_, u_, rho_});
      const auto range = std::make_pair(static_cast<std::size_t>(L.first), static_cast<std::size_t>(L.active_end));
      Kokkos::deep_copy(Kokkos::subview(p.get(field::Position{}), range, Kokkos::ALL), Kokkos::subview(x_, range, Kokkos::ALL));
      Kokkos::deep_copy(Kokkos::subview(p.get(field::Velocity{}), range, Kokkos::ALL), Kokkos::subview(u_, range, Kokkos::ALL));
      Kokkos::deep_copy(Kokkos::subview(p.get(field::Density{}), range), Kokkos::subview(rho_, range));
    }
    s.domain().halos_stale();
  }

  // the shifted state, copied back at once (the stage storage keeps the step's start for the
  // impermeability guard and the blow-up restore)
  field_view_t<field::Position, D> x_;
  field_view_t<field::Velocity, D> u_;
  field_view_t<field::Density, D> rho_;
};

}  // namespace ondine
