#pragma once
// Simulation<D>: the neighbour lists, one path for a uniform run (one level, the domain's
// list) and a run with refinement zones (particles sorted by (level, role), the lists L.
// and Lx of Algorithm 3, hooks/Refinement.hpp). Included by SimulationImpl.hpp only.
#include "solver/Simulation.hpp"
#include "solver/StepState.hpp"
#include "solver/hooks/Refinement.hpp"

namespace ondine {

template <int D>
std::vector<LevelSpan<D>> Simulation<D>::levels() const {
  if (refinement_) return refinement_->levels(walls_);
  return {{0, 0, n_own_, n_own_, R_, scene_.dx, domain_.list(), domain_.half_list(), walls_.points(), walls_.cells()}};
}

// The lists are rebuilt once some particle (on any rank) moved more than skin/2 since the
// last build (Verlet). With refinement zones, within a step the roles are kept and the next
// step start does the bookkeeping: otherwise, in a fast flow whose lists are rebuilt at the
// stages, the step start would measure the displacement from this build, skip the
// bookkeeping, and the roles (and the passive guards' velocities) would lag for tens of
// steps (dam break run-up: mother guards 2 dx_m above their zone; docs/apr.md).
template <int D>
void Simulation<D>::ensure_neighbours() {
  const Kokkos::View<int*, MemSpace> birth = p_.has(field::AprBirthLevel{}) ? p_.get(field::AprBirthLevel{}) : Kokkos::View<int*, MemSpace>();
  if (domain_.lists_hold(p_.get(field::Position{}), n_own_, birth)) return;
  rebuild_lists(false, true);
  if (refinement_) refinement_->bookkeeping_due();
}

template <int D>
void Simulation<D>::invalidate_neighbours() {
  domain_.invalidate_lists();
  if (refinement_) refinement_->bookkeeping_due();
}

// Several ranks: migration first (received particles come last, so with zones the sort is
// redone), then halos (with zones they carry their birth level and role: the lists and the
// guard interpolation select partners by them). The cell list over owned + halo particles,
// the lists of the owned ones (uniform, or L. and Lx), then the balance check, which may
// rebalance once; the work of a rank is its list entries. One rank: no migration, and with
// zones the order is already right without new roles.
template <int D>
void Simulation<D>::rebuild_lists(bool roles, bool may_rebalance) {
  const bool serial = comm().serial();
  StepState<D> state(*this);
  if (!serial) n_own_ = domain_.migrate(p_, n_own_);
  if (refinement_) refinement_->sort(state, roles);
  if (!serial) {
    domain_.build_halos(p_, n_own_);
    if (refinement_) refinement_->refresh_halo_roles(state);
  }
  const auto x = p_.get(field::Position{});
  domain_.build_cells(x, static_cast<int>(p_.size()));
  if (refinement_) refinement_->apr().build_lists(p_, domain_.box(), n_own_);
  else domain_.build_list(x, n_own_);
  domain_.built(x);
  if (serial) return;
  const AdaptiveRefinement<D>* apr = refinement_ ? &refinement_->apr() : nullptr;
  const std::int64_t work = apr ? static_cast<std::int64_t>(apr->symmetric_list().total() + apr->guard_list().total())
                                : static_cast<std::int64_t>(domain_.list().total());
  // a new decomposition weighted by the particles or the pairs of each cell
  const auto decompose = [&] {
    const NeighbourList<D> guards = apr ? apr->guard_list() : NeighbourList<D>();
    domain_.decompose(p_.get(field::Position{}), n_own_, apr ? apr->symmetric_list() : domain_.list(), apr ? &guards : nullptr, scene_.balance_by_pairs);
  };
  domain_.check_balance(scene_, work, n_own_, steps_, may_rebalance, decompose, [this] { rebuild_lists(false, false); });
}

}  // namespace ondine
