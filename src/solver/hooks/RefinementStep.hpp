#pragma once
// Refinement<D> (hooks/Refinement.hpp): the step start, the bookkeeping, the guard spacing,
// the relisting before an output and the levels' walls. Included by Refinement.hpp only.
#include <cmath>
#include <vector>

#include "particles/HostRow.hpp"
#include "solver/hooks/Refinement.hpp"

namespace ondine {

template <int D>
void Refinement<D>::step_start(StepState<D>& s) {
  output_saved_ = false;  // restore_after_output() after a step has nothing to put back
  ParticleSet<D>& p = s.particles();
  const Scene& scene = s.scene();
  const Communicator& comm = s.comm();
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  const auto P = p.get(field::Pressure{});
  const auto guard = p.get(field::AprGuard{});
  const int n = s.owned();
  apr_.invalidate_weights();  // positions moved since the last step
  bool pressure_fresh = false;
  const double moved = apr_.move(s.time(), s.steps(), [&](const RefinementZone& z, Vec3& at) {
    if (z.criterion == ZoneCriterion::Pressure && !pressure_fresh) {
      // the pressure of the current density (the stored one is the last stage's, or an output's)
      with_eos<D>(scene, [&](auto eos) { update_pressure<D>(eos, p.get(field::Density{}), P, n); });
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
      const auto h = row_to_host(x, best.loc);
      for (int k = 0; k < D; ++k) mine[1 + k] = h(k);
    }
    const std::vector<double> all = comm.gather_all(mine);
    int win = 0;
    for (int r = 1; r < comm.size(); ++r)
      if (all[r * (D + 1)] > all[win * (D + 1)]) win = r;
    if (!(all[win * (D + 1)] > 0)) return false;
    for (int k = 0; k < D; ++k) at[k] = all[win * (D + 1) + 1 + k];
    return true;
  });
  if (bookkeeping_due_ || moved > 0.5 * s.domain().skin() || !s.domain().lists_hold(x, n, p.get(field::AprBirthLevel{}))) bookkeeping(s);
  // with refinement.guard_shifting: the daughter guards shifted towards a regular
  // arrangement, with refinement.mother_shifting the mother guards towards their
  // daughters' volume (kernels/apr/GuardSpacing.hpp), from fresh halo positions; the
  // halos then carry the new positions
  if (!scene.refinement_guard_shifting && !scene.refinement_mother_shifting) return;
  s.domain().refresh_state_halos(p);
  if (space_guards(s) > 0 || !comm.serial()) s.domain().halos_stale();
}

// Several ranks (docs/parallel.md, "Refinement zones"): each rank refines and derefines
// the particles it owns. Before: migration, and halos with their birth levels (the
// prolongation gradient reads the level-r neighbours of a mother, owned or not);
// after: a second migration (a daughter may lie in another rank's cell), the sort,
// halos with levels and roles, the lists. The dying and refining mothers' ids are
// gathered on every rank inside AdaptiveRefinement::update.
template <int D>
void Refinement<D>::bookkeeping(StepState<D>& s) {
  ParticleSet<D>& p = s.particles();
  Domain<D>& domain = s.domain();
  if (!s.comm().serial()) {
    s.set_owned(domain.migrate(p, s.owned()));
    domain.build_halos(p, s.owned());
    domain.refresh(p, field::AprBirthLevel{});
    // adoption reads the halos' mother flags and parents (kernels/apr/Adoption.hpp)
    if (s.scene().refinement_adoption) domain.refresh(p, field::AprMother{}, field::AprParent{});
  }
  domain.build_cells(p.get(field::Position{}), static_cast<int>(p.size()));  // for the prolongation gradient
  s.set_owned(apr_.update(p, domain.cells(), domain.box(), s.owned(), s.comm(), s.walls().near_facets()));
  bookkeeping_due_ = false;
  relist_after_edit(s);
}

// After particles were created or removed: the roles' lists, then the passive guards (once per
// edit) and, on several ranks, their halo copies.
template <int D>
void Refinement<D>::relist_after_edit(StepState<D>& s) {
  s.domain().invalidate_lists();
  s.rebuild_lists(true, true);
  apr_.interpolate(s.particles(), s.domain().box(), true, s.walls().near_facets());
  refresh_guard_halos(s);
}

// The fill's cuts at each level's spacing: the particles beyond them go (their mothers keep
// the rest's mass), then the roles, halos and lists as after a bookkeeping.
template <int D>
void Refinement<D>::trim_to_cuts(StepState<D>& s) {
  s.set_owned(apr_.trim_to_cuts(s.particles(), s.owned(), s.comm(), fill_cuts<D>(s.scene())));
  relist_after_edit(s);
}

// Several ranks, before an output: owned positions are wrapped into the periodic box only
// at a migration, so the output migrates. A list build is not neutral with zones (the next
// bookkeeping comes with the Verlet criterion, and a guard's choice of radius is reset),
// and a one-rank run does not rebuild its lists there: so the reference positions of the
// Verlet criterion and the guards' radius flags travel with their particles (in the stage
// storage, free between steps) and are put back, and the lists' validity is kept: the run
// goes on as if nothing had happened.
template <int D>
void Refinement<D>::relist_for_output(StepState<D>& s) {
  ParticleSet<D>& p = s.particles();
  Domain<D>& domain = s.domain();
  allocate_stage_storage(p, s.scene());
  const bool valid = domain.lists_valid();
  const auto xs = p.get(field::StagePosition{});
  const auto ws = p.get(field::StageDensity{});
  const int n = s.owned();
  if (valid) {
    const auto xb = domain.built_positions();
    const auto wide = apr_.wide_flags();
    const bool verlet = domain.skin() > 0;
    Kokkos::parallel_for("ondine::APR::stash", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < D; ++k) xs(i, k) = verlet ? xb(i, k) : 0.0;
      ws(i) = wide.extent(0) > static_cast<std::size_t>(i) ? wide(i) : 0;
    });
  }
  s.set_owned(domain.migrate(p, n));
  apr_.sort(p, s.owned(), false);
  domain.build_halos(p, s.owned());
  refresh_halo_roles(s);
  const auto x = p.get(field::Position{});
  domain.build_cells(x, static_cast<int>(p.size()));
  apr_.build_lists(p, domain.box(), s.owned(), false);
  if (valid) {
    const auto ws2 = p.get(field::StageDensity{});
    const auto wide = apr_.wide_flags();
    Kokkos::parallel_for("ondine::APR::unstash", Kokkos::RangePolicy<ExecSpace>(0, s.owned()),
                         KOKKOS_LAMBDA(const int i) { wide(i) = static_cast<int>(ws2(i)); });
  }
  domain.restore_built_positions(p.get(field::StagePosition{}), valid);
}

// The daughter guards of each level l >= 1 (refinement.guard_shifting) and the mother
// guards of each level l < levels - 1 (refinement.mother_shifting) shifted
// (kernels/apr/GuardSpacing.hpp) from the positions of the owned particles and the halos
// (the cells of the last list build, fresh positions); returns the number of guards moved
// on this rank. The shape functions of the guard interpolation are recomputed at the
// next stage. Each level's shifts are computed, then applied: a level's daughter guards
// read that level only, its mother guards that level and the next, which is shifted after.
template <int D>
long Refinement<D>::space_guards(StepState<D>& s) {
  long total = 0;
  const bool daughters = s.scene().refinement_guard_shifting, mothers = s.scene().refinement_mother_shifting;
  if (apr_.levels() < 2 || !(daughters || mothers)) return 0;
  ParticleSet<D>& p = s.particles();
  const int n_all = static_cast<int>(p.size());
  if (static_cast<int>(guard_shift_.extent(0)) < n_all)
    guard_shift_ = Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace>("ondine::APR::guard_shift", n_all + n_all / 8);
  const bool walls = s.has_walls();
  const auto x = p.get(field::Position{});
  const std::vector<LevelSpan<D>> spans = s.levels();
  for (int l = mothers ? 0 : 1; l < apr_.levels(); ++l) {
    const int b = apr_.active_end(l), e = apr_.end(l);
    if (e == b) continue;
    const double Rl = apr_.R(l);
    if (walls && daughters && l > 0)
      Kokkos::parallel_for("ondine::NFM::ShepardGamma", Kokkos::RangePolicy<ExecSpace>(b, e),
                           ShepardGammaPass<D>{s.walls().facets(), s.walls().facet_cells(), Rl, s.domain().box(), x,
                                               p.get(field::ShepardGamma{})});
    PassContext<D> c = s.context(spans[l]);
    c.first = b;  // the level's guards
    c.end = e;
    const long moved = s.scheme().guard_spacing(c, guard_shift_, daughters, mothers);
    if (moved > 0)
      Kokkos::parallel_for("ondine::APR::GuardSpacing::apply", Kokkos::RangePolicy<ExecSpace>(b, e),
                           apr::ApplyShift<D>{s.domain().box(), x, guard_shift_});
    total += moved;
  }
  apr_.count_guard_shifts(total);
  apr_.invalidate_weights();
  return total;
}

// The walls of each level l >= 1: their quadrature at the level's default spacing (2D: the
// finest level's dx / 4, as level 0's; 3D: kWallQuadratureSpacing3D dx_l, so that level 0
// keeps the coarse points and the fine level has the points of a uniform run at dx_l), or
// at the case's wall_quadrature_spacing, binned with cells of R_l: a particle visits the
// wall points of its own neighbourhood at its level's spacing.
template <int D>
void Refinement<D>::build_level_walls(StepState<D>& s) {
  const Scene& scene = s.scene();
  const int levels = scene.max_refinement_level() + 1;
  const double dx_finest = scene.dx / std::ldexp(1.0, scene.max_refinement_level());
  level_walls_.clear();
  level_walls_.resize(levels);
  for (int l = 1; l < levels; ++l) {
    const double spacing = wall_quadrature_spacing<D>(scene, D == 3 ? scene.dx / (1 << l) : dx_finest);
    level_walls_[l] = WallModel<D>(scene, s.domain().box(), s.R() / (1 << l), spacing, false);
  }
}

}  // namespace ondine
