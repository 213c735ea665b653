#pragma once
// Adaptive particle refinement (solver/AdaptiveRefinement.hpp, docs/apr.md) in the run: the
// first levels or a checkpoint's APR state at the set-up; at a step start the zones at time t
// and the bookkeeping (refinement, derefinement, roles, 5.9-5.24), then the guard spacing;
// the guards interpolated from each stage's SPH particles (5.24) and from the stored state at
// an output; the walls of each level. Simulation asks it for the levels of its lists and
// evaluation (levels()); runs with refinement_zones, as the last hook of the list.
#include <stdexcept>
#include <vector>

#include "kernels/apr/GuardSpacing.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "solver/AdaptiveRefinement.hpp"
#include "solver/FillCutsBuild.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/StageStorage.hpp"
#include "solver/StepHook.hpp"
#include "solver/StepState.hpp"

namespace ondine {

template <int D>
class Refinement final : public StepHook<D> {
 public:
  Refinement(const Scene&, const CheckpointSlice* restart) {
    if (restart && !restart->header.refinement.present)
      throw std::logic_error("Simulation<D>: a checkpoint without the APR state for a scene with refinement zones");
  }
  const char* name() const override { return "refinement"; }
  const AdaptiveRefinement<D>& apr() const { return apr_; }
  AdaptiveRefinement<D>& apr() { return apr_; }

  // The levels' ranges, radii, lists and wall points; level 0 with the base walls.
  std::vector<LevelSpan<D>> levels(const WallModel<D>& base) const {
    std::vector<LevelSpan<D>> out;
    for (int l = 0; l < apr_.levels(); ++l) {
      const WallModel<D>& w = l == 0 || l >= static_cast<int>(level_walls_.size()) ? base : level_walls_[l];
      out.push_back({l, apr_.first(l), apr_.active_end(l), apr_.end(l), apr_.R(l), apr_.dx(l), apr_.symmetric_list(), {},
                     w.points(), w.cells()});
    }
    return out;
  }

  // The next step start runs the bookkeeping even if the lists are valid (after a
  // checkpoint, a restart, or a list rebuild outside a step start).
  void bookkeeping_due() { bookkeeping_due_ = true; }

  // After the other hooks' start (the open boundaries' roles): the walls of each level, then
  // the APR state of the checkpoint (each rank sorts the particles it owns by their stored
  // level and role; the first step starts with the bookkeeping the saved run would have done
  // after writing it), or every particle a coarse SPH particle and one bookkeeping pass per
  // level, creating the daughters of each nested level in turn, and the blocks' cuts applied
  // at each level's own spacing.
  void start(StepState<D>& s, const CheckpointSlice* restart) override {
    if (s.has_walls()) build_level_walls(s);
    apr_ = AdaptiveRefinement<D>(s.scene(), s.domain().box(), s.domain().skin(), s.domain().level_skins());
    if (restart) {
      apr_.restore(s.particles(), s.owned(), restart->header.refinement);
      apr_.count_guard_shifts(s.comm().rank() == 0 ? restart->header.refinement.guard_shifts : 0);
      apr_.count_guards_limited(s.comm().rank() == 0 ? restart->header.refinement.guards_limited : 0);
      s.domain().invalidate_lists();
      bookkeeping_due_ = true;
      return;
    }
    // ids from the fill's count on (the open boundaries may have dropped particles since)
    const std::int64_t ids = s.hooks_next_id();
    apr_.initialise(s.particles(), ids >= 0 ? ids : s.comm().sum(static_cast<std::int64_t>(s.owned())));
    for (int l = 1; l < apr_.levels(); ++l) bookkeeping(s);
    bool cuts = false;
    for (const FluidBlock& b : s.scene().blocks) cuts = cuts || !b.cuts.empty();
    if (cuts) trim_to_cuts(s);
  }

  // At the start of a step (after the other hooks'): the zones at time t (moving, or
  // re-centred on their criterion), then the bookkeeping whenever the lists have to be
  // rebuilt anyway (Verlet criterion, a reordering, zones moved by more than half the skin,
  // or bookkeeping_due()); then the guard spacing.
  void step_start(StepState<D>& s) override;

  // Several ranks: the lists' rebuild with the particles sorted by level and role (`roles`:
  // new roles, at a bookkeeping), after migration; the halos with their birth level and role.
  void sort(StepState<D>& s, bool roles) {
    if (roles || !s.comm().serial()) apr_.sort(s.particles(), s.owned(), roles);
  }
  void refresh_halo_roles(StepState<D>& s) { s.domain().refresh(s.particles(), field::AprBirthLevel{}, field::AprGuard{}); }

  // Each stage: the guards from this stage's SPH particles (5.24), and on several ranks
  // their halo copies (their density gradient travels after the gradient pass); `only` >= 0:
  // the guards of that level only (local time stepping).
  void interpolate_guards(StepState<D>& s, int only = -1) {
    apr_.interpolate(s.particles(), s.domain().box(), false, s.walls().near_facets(), only);
    s.domain().refresh(s.particles(), field::Velocity{}, field::Density{});
  }
  // local time stepping: a new step of `level`, its guards' shape functions at its positions
  void level_step_start(int level) { apr_.invalidate_weights(level); }

  // An output: the guards of the stored state (5.24), the run's own kept and put back after
  // it (restore_after_output), so that an output never changes the run.
  void interpolate_for_output(StepState<D>& s) {
    ParticleSet<D>& p = s.particles();
    // a list rebuild here would have been the next step start's, with its bookkeeping: it still is
    const std::int64_t builds = s.domain().builds();
    s.ensure_lists();
    if (s.domain().builds() != builds) bookkeeping_due_ = true;
    auto keep = [](auto& saved, const auto& v) {
      if (saved.extent(0) != v.extent(0)) saved = std::decay_t<decltype(saved)>("ondine::APR::saved_for_output", v.extent(0));
      Kokkos::deep_copy(saved, v);
    };
    keep(saved_u_, p.get(field::Velocity{}));
    keep(saved_rho_, p.get(field::Density{}));
    if (p.has(field::DensityGradient{})) keep(saved_grad_rho_, p.get(field::DensityGradient{}));
    apr_.save_wide_flags();
    output_saved_ = true;
    apr_.interpolate(p, s.domain().box(), true, s.walls().near_facets());
    refresh_guard_halos(s);
  }
  void restore_after_output(ParticleSet<D>& p) {
    if (!output_saved_) return;
    Kokkos::deep_copy(p.get(field::Velocity{}), saved_u_);
    Kokkos::deep_copy(p.get(field::Density{}), saved_rho_);
    if (p.has(field::DensityGradient{})) Kokkos::deep_copy(p.get(field::DensityGradient{}), saved_grad_rho_);
    apr_.restore_wide_flags();
    output_saved_ = false;
  }

  // the walls of each level follow the base walls' motion
  void move_walls(double t) {
    for (WallModel<D>& w : level_walls_)
      if (!w.empty()) w.move_to(t);
  }

  // Several ranks, before an output: a migration as if the lists had not been rebuilt.
  void relist_for_output(StepState<D>& s);
  // (public only for their KOKKOS_LAMBDAs, which nvcc refuses in a private member)
  void bookkeeping(StepState<D>& s);
  long space_guards(StepState<D>& s);
  // the blocks' cuts applied at each level's own spacing (AdaptiveRefinement::trim_to_cuts)
  void trim_to_cuts(StepState<D>& s);

 private:
  void build_level_walls(StepState<D>& s);
  void relist_after_edit(StepState<D>& s);
  void refresh_guard_halos(StepState<D>& s) {
    if (s.comm().serial()) return;
    ParticleSet<D>& p = s.particles();
    if (p.has(field::DensityGradient{}))
      s.domain().refresh(p, field::Velocity{}, field::Density{}, field::DensityGradient{});
    else
      s.domain().refresh(p, field::Velocity{}, field::Density{});
  }

  AdaptiveRefinement<D> apr_;
  bool bookkeeping_due_ = false;
  // the guards' fields before interpolate_for_output (restore_after_output puts them back)
  bool output_saved_ = false;
  field_view_t<field::Velocity, D> saved_u_;
  field_view_t<field::Density, D> saved_rho_;
  field_view_t<field::DensityGradient, D> saved_grad_rho_;
  Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace> guard_shift_;  // per particle: GuardSpacing's shift
  // with walls: the walls of each level l >= 1, their quadrature at the level's spacing (3D;
  // in 2D at the finest level's, as level 0's) and their points binned at R_l
  std::vector<WallModel<D>> level_walls_;
};

}  // namespace ondine

#include "solver/hooks/RefinementStep.hpp"
