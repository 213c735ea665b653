#pragma once
// Simulation<D>: the neighbour lists, one path for a uniform run (one level, the domain's
// list) and a run with refinement zones (particles sorted by (level, role), the lists L.
// and Lx of Algorithm 3); the refinement bookkeeping at a step start, the guard spacing.
// Included by SimulationImpl.hpp only.
#include "kernels/apr/GuardSpacing.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
std::vector<LevelSpan<D>> Simulation<D>::levels() const {
  std::vector<LevelSpan<D>> out;
  if (!apr_on_) {
    out.push_back({0, 0, n_own_, n_own_, R_, scene_.dx, domain_.list(), walls_.points(), walls_.cells()});
    return out;
  }
  for (int l = 0; l < apr_.levels(); ++l) {
    const WallModel<D>& w = l == 0 || l >= static_cast<int>(level_walls_.size()) ? walls_ : level_walls_[l];
    out.push_back({l, apr_.first(l), apr_.active_end(l), apr_.end(l), apr_.R(l), apr_.dx(l), apr_.symmetric_list(), w.points(),
                   w.cells()});
  }
  return out;
}

template <int D>
std::int64_t Simulation<D>::pair_count() const {
  // pairs within R, both ways, from the current list (skin pairs excluded)
  if (!domain_.lists_valid()) return 0;
  if (apr_on_) return comm().sum(static_cast<std::int64_t>(apr_.symmetric_list().total()));  // L. pairs within R + skin
  const auto x = p_.get(field::Position{});
  const auto list = domain_.list();
  const auto box = domain_.box();
  const double R2 = R_ * R_;
  std::int64_t total = 0;
  Kokkos::parallel_reduce("ondine::PairCount", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          KOKKOS_LAMBDA(const int i, std::int64_t& acc) {
                            for_each_neighbour_within<D>(list, box, x, i, load<D>(x, i), R2,
                                                         [&](const int, const Vec<D>&, const double) { ++acc; });
                          },
                          total);
  return comm().sum(total);
}

// The lists are rebuilt once some particle (on any rank) moved more than skin/2 since the
// last build (Verlet). With refinement zones, within a step the roles are kept and the next
// step start does the bookkeeping: otherwise, in a fast flow whose lists are rebuilt at the
// stages, the step start would measure the displacement from this build, skip the
// bookkeeping, and the roles (and the passive guards' velocities) would lag for tens of
// steps (dam break run-up: mother guards 2 dx_m above their zone; docs/apr.md).
template <int D>
void Simulation<D>::ensure_neighbours() {
  if (domain_.lists_hold(p_.get(field::Position{}), n_own_)) return;
  rebuild_lists(false, true);
  if (apr_on_) bookkeeping_due_ = true;
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
  if (!serial) n_own_ = domain_.migrate(p_, n_own_);
  if (apr_on_ && (roles || !serial)) apr_.sort(p_, n_own_, roles);
  if (!serial) {
    domain_.build_halos(p_, n_own_);
    if (apr_on_) domain_.refresh(p_, field::AprBirthLevel{}, field::AprGuard{});
  }
  const auto x = p_.get(field::Position{});
  domain_.build_cells(x, static_cast<int>(p_.size()));
  if (apr_on_) apr_.build_lists(p_, domain_.cells(), domain_.box(), n_own_);
  else domain_.build_list(x, n_own_);
  domain_.built(x);
  if (serial) return;
  const std::int64_t work = apr_on_ ? static_cast<std::int64_t>(apr_.symmetric_list().total() + apr_.guard_list().total())
                                    : static_cast<std::int64_t>(domain_.list().total());
  domain_.check_balance(scene_, work, n_own_, steps_, may_rebalance, [this] { decompose(scene_.balance_by_pairs); },
                        [this] { rebuild_lists(false, false); });
}

template <int D>
void Simulation<D>::decompose(bool by_pairs) {
  const NeighbourList<D> guards = apr_on_ ? apr_.guard_list() : NeighbourList<D>();
  domain_.decompose(p_.get(field::Position{}), n_own_, apr_on_ ? apr_.symmetric_list() : domain_.list(),
                    apr_on_ ? &guards : nullptr, by_pairs);
}

// Several ranks (docs/parallel.md, "Refinement zones"): each rank refines and derefines
// the particles it owns. Before: migration, and halos with their birth levels (the
// prolongation gradient reads the level-r neighbours of a mother, owned or not);
// after: a second migration (a daughter may lie in another rank's cell), the sort,
// halos with levels and roles, the lists. The dying and refining mothers' ids are
// gathered on every rank inside AdaptiveRefinement::update.
template <int D>
void Simulation<D>::refinement_bookkeeping() {
  if (!comm().serial()) {
    n_own_ = domain_.migrate(p_, n_own_);
    domain_.build_halos(p_, n_own_);
    domain_.refresh(p_, field::AprBirthLevel{});
  }
  domain_.build_cells(p_.get(field::Position{}), static_cast<int>(p_.size()));  // for the prolongation gradient
  n_own_ = apr_.update(p_, domain_.cells(), domain_.box(), n_own_, comm(), walls_.near_facets());
  domain_.invalidate_lists();
  bookkeeping_due_ = false;
  rebuild_lists(true, true);
  apr_.interpolate(p_, domain_.box(), true, walls_.near_facets());  // passive guards: once per bookkeeping
  refresh_guard_halos();
}

// Several ranks, before an output: owned positions are wrapped into the periodic box
// only at a migration, so the output migrates. Without zones that is a list rebuild. With
// zones a list build is not neutral (the next bookkeeping comes with the Verlet criterion,
// and a guard's choice of radius is reset), and a one-rank run does not rebuild its lists
// there: so the reference positions of the Verlet criterion and the guards' radius flags
// travel with their particles (in the stage storage, free between steps) and are put
// back, and the lists' validity is kept: the run goes on as if nothing had happened.
template <int D>
void Simulation<D>::relist_for_output() {
  if (!apr_on_) {
    rebuild_lists(false, false);
    return;
  }
  allocate_stage_storage();
  const bool valid = domain_.lists_valid();
  const auto xs = p_.get(field::StagePosition{});
  const auto ws = p_.get(field::StageDensity{});
  const int n = n_own_;
  if (valid) {
    const auto xb = domain_.built_positions();
    const auto wide = apr_.wide_flags();
    const bool verlet = domain_.skin() > 0;
    Kokkos::parallel_for("ondine::APR::stash", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < D; ++k) xs(i, k) = verlet ? xb(i, k) : 0.0;
      ws(i) = wide.extent(0) > static_cast<std::size_t>(i) ? wide(i) : 0;
    });
  }
  n_own_ = domain_.migrate(p_, n_own_);
  apr_.sort(p_, n_own_, false);
  domain_.build_halos(p_, n_own_);
  domain_.refresh(p_, field::AprBirthLevel{}, field::AprGuard{});
  const auto x = p_.get(field::Position{});
  domain_.build_cells(x, static_cast<int>(p_.size()));
  apr_.build_lists(p_, domain_.cells(), domain_.box(), n_own_, false);
  if (valid) {
    const auto ws2 = p_.get(field::StageDensity{});
    const auto wide = apr_.wide_flags();
    Kokkos::parallel_for("ondine::APR::unstash", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                         KOKKOS_LAMBDA(const int i) { wide(i) = static_cast<int>(ws2(i)); });
  }
  domain_.restore_built_positions(p_.get(field::StagePosition{}), valid);
}

template <int D>
void Simulation<D>::refresh_guard_halos() {
  if (comm().serial()) return;
  if (p_.has(field::DensityGradient{}))
    domain_.refresh(p_, field::Velocity{}, field::Density{}, field::DensityGradient{});
  else
    domain_.refresh(p_, field::Velocity{}, field::Density{});
}


// At the start of a step: the zones at time t (moving, or re-centred on their
// criterion), then the bookkeeping whenever the lists have to be rebuilt anyway
// (Verlet criterion, a reordering, zones moved by more than half the skin, or
// bookkeeping_due_: after a checkpoint, at a restart, after a list rebuild at an output).
template <int D>
void Simulation<D>::refinement_step_start() {
  const auto x = p_.get(field::Position{});
  const auto u = p_.get(field::Velocity{});
  const auto P = p_.get(field::Pressure{});
  const auto guard = p_.get(field::AprGuard{});
  const int n = n_own_;
  apr_.invalidate_weights();  // positions moved since the last step
  bool pressure_fresh = false;
  const double moved = apr_.move(t_, steps_, [&](const RefinementZone& z, Vec3& at) {
    if (z.criterion == ZoneCriterion::Pressure && !pressure_fresh) {
      // the pressure of the current density (the stored one is the last stage's, or an output's)
      with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, p_.get(field::Density{}), P, n); });
      pressure_fresh = true;
    }
    apr::MaxInBox<D> f{{}, {}, z.criterion == ZoneCriterion::Speed, x, u, P, guard};
    for (int k = 0; k < D; ++k) {
      f.lo[k] = z.search.min[k];
      f.hi[k] = z.search.max[k];
    }
    typename Kokkos::MaxLoc<double, int>::value_type best;
    Kokkos::parallel_reduce("ondine::APR::zone_criterion", Kokkos::RangePolicy<ExecSpace>(0, n), f,
                            Kokkos::MaxLoc<double, int>(best));
    // (value, position) of every rank; the largest wins (the lowest rank on a tie)
    std::vector<double> mine(D + 1, 0.0);
    mine[0] = best.val > 0 ? best.val : -1.0;
    if (best.val > 0) {
      auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(x, best.loc, Kokkos::ALL));
      for (int k = 0; k < D; ++k) mine[1 + k] = h(k);
    }
    const std::vector<double> all = comm().gather_all(mine);
    int win = 0;
    for (int r = 1; r < comm().size(); ++r)
      if (all[r * (D + 1)] > all[win * (D + 1)]) win = r;
    if (!(all[win * (D + 1)] > 0)) return false;
    for (int k = 0; k < D; ++k) at[k] = all[win * (D + 1) + 1 + k];
    return true;
  });
  if (bookkeeping_due_ || moved > 0.5 * skin_len_ || !domain_.lists_hold(x, n)) refinement_bookkeeping();
  // with refinement.guard_shifting: the daughter guards shifted towards a regular
  // arrangement, with refinement.mother_shifting the mother guards towards their
  // daughters' volume (kernels/apr/GuardSpacing.hpp), from fresh halo positions; the
  // halos then carry the new positions
  if (!scene_.refinement_guard_shifting && !scene_.refinement_mother_shifting) return;
  domain_.refresh_state_halos(p_);
  if (space_guards() > 0 || !comm().serial()) domain_.halos_stale();
}

// The daughter guards of each level l >= 1 (refinement.guard_shifting) and the mother
// guards of each level l < levels - 1 (refinement.mother_shifting) shifted
// (kernels/apr/GuardSpacing.hpp) from the positions of the owned particles and the halos
// (domain_.cells() of the last list build, fresh positions); returns the number of guards moved
// on this rank. The shape functions of the guard interpolation are recomputed at the
// next stage. Each level's shifts are computed, then applied: a level's daughter guards
// read that level only, its mother guards that level and the next, which is shifted after.
template <int D>
long Simulation<D>::space_guards() {
  long total = 0;
  const bool daughters = scene_.refinement_guard_shifting, mothers = scene_.refinement_mother_shifting;
  if (apr_.levels() < 2 || !(daughters || mothers)) return 0;
  const int n_all = static_cast<int>(p_.size());
  if (static_cast<int>(guard_shift_.extent(0)) < n_all)
    guard_shift_ = Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace>("ondine::APR::guard_shift", n_all + n_all / 8);
  const bool walls = !walls_.empty();
  const auto x = p_.get(field::Position{});
  const std::vector<LevelSpan<D>> spans = levels();
  for (int l = mothers ? 0 : 1; l < apr_.levels(); ++l) {
    const int b = apr_.active_end(l), e = apr_.end(l);
    if (e == b) continue;
    const double Rl = apr_.R(l);
    if (walls && daughters && l > 0)
      Kokkos::parallel_for("ondine::NFM::ShepardGamma", Kokkos::RangePolicy<ExecSpace>(b, e),
                           ShepardGammaPass<D>{walls_.facets(), walls_.facet_cells(), Rl, domain_.box(), x, p_.get(field::ShepardGamma{})});
    PassContext<D> c = pass_context(spans[l]);
    c.first = b;  // the level's guards
    c.end = e;
    const long moved = scheme_.guard_spacing(c, guard_shift_, daughters, mothers);
    if (moved > 0)
      Kokkos::parallel_for("ondine::APR::GuardSpacing::apply", Kokkos::RangePolicy<ExecSpace>(b, e), apr::ApplyShift<D>{domain_.box(), x, guard_shift_});
    total += moved;
  }
  apr_.count_guard_shifts(total);
  apr_.invalidate_weights();
  return total;
}

// The walls of each level l >= 1 (set-up): their quadrature at the level's default spacing
// (2D: the finest level's dx / 4, as level 0's; 3D: kWallQuadratureSpacing3D dx_l, so that
// level 0 keeps the coarse points and the fine level has the points of a uniform run at
// dx_l), or at the case's wall_quadrature_spacing, binned with cells of R_l: a particle
// visits the wall points of its own neighbourhood at its level's spacing.
template <int D>
void Simulation<D>::build_level_walls() {
  const int levels = scene_.max_refinement_level() + 1;
  level_walls_.clear();
  level_walls_.resize(levels);
  for (int l = 1; l < levels; ++l) {
    const double spacing = D == 3 ? wall_quadrature_spacing<D>(scene_, scene_.dx / (1 << l)) : wall_spacing_;
    level_walls_[l] = WallModel<D>(scene_, domain_.box(), R_ / (1 << l), spacing, false);
  }
}

}  // namespace ondine
