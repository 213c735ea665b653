#pragma once
// Host side of adaptive particle refinement (thesis 5.4; docs/apr.md): the zone
// table and its motion, the refinement/derefinement bookkeeping (Kokkos passes of
// kernels/apr/Refinement.hpp), the level ranges of the sorted particle set and the
// two interaction lists L. and Lx (Algorithm 3), and the guard interpolation (5.24).
// Exists only in a Simulation whose scene has refinement zones.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Kokkos_Sort.hpp>
#include <Kokkos_Timer.hpp>

#include "kernels/CellList.hpp"
#include "kernels/Permute.hpp"
#include "kernels/FillCuts.hpp"
#include "kernels/apr/Adoption.hpp"
#include "kernels/apr/CutTrim.hpp"
#include "kernels/apr/GuardInterpolation.hpp"
#include "kernels/apr/InteractionLists.hpp"
#include "kernels/apr/Refinement.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/SortedIds.hpp"
#include "io/Checkpoint.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"
#include "solver/KernelDispatch.hpp"

namespace ondine {

template <int D>
class AdaptiveRefinement {
 public:
  AdaptiveRefinement() = default;
  // `level_skins`: a Verlet skin per level (local time stepping), or empty: `skin` for every level
  AdaptiveRefinement(const Scene& s, const PeriodicBox<D>& box, double skin, const std::vector<double>& level_skins = {})
      : scene_zones_(s.refinement_zones), kernel_(s.kernel), skin_(skin), adoption_(s.refinement_adoption) {
    for (int l = 0; l < kAprMaxLevels; ++l) skins_[l] = l < static_cast<int>(level_skins.size()) ? level_skins[l] : skin;
    zones_.count = static_cast<int>(s.refinement_zones.size());
    zones_.max_level = s.max_refinement_level();
    zones_.box = box;
    for (int l = 0; l < kAprMaxLevels; ++l) {
      zones_.R[l] = s.R() / std::ldexp(1.0, l);
      zones_.dx[l] = s.dx / std::ldexp(1.0, l);
      zones_.layer[l] = l == 0 ? 0.0 : s.refinement_transition * zones_.R[l - 1];
      zones_.passive[l] = zones_.R[l] + 2.0 * skins_[l];
    }
    offset_.assign(scene_zones_.size(), Vec3{0, 0, 0});
    place_zones();
    levels_ = zones_.max_level + 1;
    first_.assign(levels_, 0);
    active_end_.assign(levels_, 0);
    guard_end_.assign(levels_, 0);
    end_.assign(levels_, 0);
  }

  bool active() const { return zones_.count > 0; }
  int levels() const { return levels_; }
  double R(int l) const { return zones_.R[l]; }
  double dx(int l) const { return zones_.dx[l]; }
  // particles of level l: SPH particles [first, active_end), guards [active_end,
  // guard_end), passive guards [guard_end, end)
  int first(int l) const { return first_[l]; }
  int active_end(int l) const { return active_end_[l]; }
  int guard_end(int l) const { return guard_end_[l]; }
  int end(int l) const { return end_[l]; }
  const NeighbourList<D>& symmetric_list() const { return l_dot_; }
  const NeighbourList<D>& guard_list() const { return l_cross_; }
  const RefinementZones<D>& zones() const { return zones_; }
  std::int64_t refined() const { return refined_; }    // mothers refined so far
  // the global id counter, which the open boundaries share for their new particles
  std::int64_t& id_counter() { return next_id_; }
  std::int64_t next_id() const { return next_id_; }
  std::int64_t deleted() const { return deleted_; }    // daughters deleted so far
  std::int64_t families_moved() const { return families_moved_; }  // moved off a wall (DaughterWallClearance)
  // daughters of a dying mother kept inside their zone by adoption (kernels/apr/Adoption.hpp), and
  // those inside it that found no adopter and went with their family
  std::int64_t adopted() const { return adopted_; }
  std::int64_t orphans_deleted() const { return orphans_deleted_; }
  // daughters an open boundary removed while their mother was still one: their mass left the
  // mother (and hers) at the next bookkeeping (remove_from_families)
  std::int64_t outflow_daughters() const { return outflow_daughters_; }
  // The daughters an open boundary removed (kernels/OpenBoundary.hpp, OpenFamilyLosses: triples
  // (mother level, mother id, -m) of this rank): their mass leaves their mothers at the next
  // bookkeeping, which follows the removal in the same step start (the lists are invalid then).
  void remove_from_families(const std::vector<double>& losses) {
    pending_losses_.insert(pending_losses_.end(), losses.begin(), losses.end());
  }
  std::int64_t guard_shifts() const { return guard_shifts_; }  // daughter guards shifted (GuardSpacing), summed over steps
  // guard interpolations put back into their sources' range (apr::GuardApply::limit), summed over stages
  std::int64_t guards_limited() const { return guards_limited_; }
  double interpolation_seconds() const { return interp_seconds_; }
  // sum over all refinements of sum_f m_f u_f - m_m u_m (component a), and of m_m |u_m|
  double momentum_change(int a) const { return momentum_change_[a]; }
  double momentum_scale() const { return momentum_scale_; }
  int guards() const {
    int g = 0;
    for (int l = 0; l < levels_; ++l) g += guard_end_[l] - active_end_[l];
    return g;
  }
  int passive() const {
    int g = 0;
    for (int l = 0; l < levels_; ++l) g += end_[l] - guard_end_[l];
    return g;
  }

  // The APR fields of a fresh particle set: every particle is a coarse SPH particle.
  void initialise(ParticleSet<D>& p, std::int64_t global_count) {
    p.allocate(field::AprLevel{});
    p.allocate(field::AprBirthLevel{});
    p.allocate(field::AprGuard{});
    p.allocate(field::AprMother{});
    Kokkos::deep_copy(p.allocate(field::AprParent{}), std::int64_t(-1));
    next_id_ = global_count;
  }

  // The per-run state a checkpoint carries (io/Checkpoint.hpp): the next daughter id,
  // the counters, and where each zone is (its offset from the case-file box, and
  // its lower corner at the last bookkeeping).
  void save_state(CheckpointRefinement& c) const {
    c.present = true;
    c.next_id = next_id_;
    c.refined = refined_;
    c.deleted = deleted_;
    c.families_moved = families_moved_;
    c.adopted = adopted_;
    c.orphans_deleted = orphans_deleted_;
    c.outflow_daughters = outflow_daughters_;
    for (int a = 0; a < 3; ++a) c.momentum_change[a] = a < D ? momentum_change_[a] : 0.0;
    c.momentum_scale = momentum_scale_;
    c.offset.assign(3 * scene_zones_.size(), 0.0);
    c.lo_at_update.assign(3 * scene_zones_.size(), 0.0);
    for (std::size_t z = 0; z < scene_zones_.size(); ++z)
      for (int k = 0; k < D; ++k) {
        c.offset[3 * z + k] = offset_[z][k];
        c.lo_at_update[3 * z + k] = lo_at_update_[z][k];
      }
  }

  // A restart: the state of save_state() back, and the level ranges from the APR
  // fields read from the checkpoint (birth level and role of each particle, as the
  // last bookkeeping set them; the particles are in the order they were saved in,
  // already sorted by (level, role) on one rank: the stable sort keeps that order).
  void restore(ParticleSet<D>& p, int n, const CheckpointRefinement& c) {
    if (c.offset.size() != 3 * scene_zones_.size() || c.lo_at_update.size() != c.offset.size())
      throw std::logic_error("AdaptiveRefinement::restore: the checkpoint's zone count differs from the scene's");
    next_id_ = c.next_id;
    refined_ = c.refined;
    deleted_ = c.deleted;
    families_moved_ = c.families_moved;
    adopted_ = c.adopted;
    orphans_deleted_ = c.orphans_deleted;
    outflow_daughters_ = c.outflow_daughters;
    for (int a = 0; a < D; ++a) momentum_change_[a] = c.momentum_change[a];
    momentum_scale_ = c.momentum_scale;
    for (std::size_t z = 0; z < scene_zones_.size(); ++z)
      for (int k = 0; k < D; ++k) {
        offset_[z][k] = c.offset[3 * z + k];
        lo_at_update_[z][k] = c.lo_at_update[3 * z + k];
      }
    place_zones();
    sort(p, n, false);  // each particle keeps the role stored with it
    weights_valid_ = 0;
  }

  // An output interpolates every guard (and may fit some at R_m): the guards' fields
  // and flags are saved before and put back after it, so that an output (and so a
  // checkpoint or a restart) does not change the run.
  void save_wide_flags() {
    if (wide_saved_.extent(0) != wide_.extent(0)) wide_saved_ = Kokkos::View<int*, MemSpace>("ondine::APR::guard_wide_saved", wide_.extent(0));
    Kokkos::deep_copy(wide_saved_, wide_);
  }
  void restore_wide_flags() {
    if (wide_saved_.extent(0) == wide_.extent(0)) Kokkos::deep_copy(wide_, wide_saved_);
    weights_valid_ = 0;
  }

  // Moves the zones to time t (translation) and, every `every` steps, re-centres a
  // following zone on the maximum of |P| or |u| in its search region. Returns the
  // largest zone displacement since the last bookkeeping (m).
  template <class Maximum>
  double move(double t, std::int64_t step, Maximum&& where_max) {
    for (std::size_t z = 0; z < scene_zones_.size(); ++z) {
      const RefinementZone& rz = scene_zones_[z];
      if (rz.motion == ZoneMotion::Translation) {
        for (int k = 0; k < D; ++k) offset_[z][k] = rz.velocity[k] * t;
      } else if (rz.motion == ZoneMotion::Criterion && step % rz.every == 0) {
        Vec3 at;
        if (where_max(rz, at))
          for (int k = 0; k < D; ++k) offset_[z][k] = at[k] - 0.5 * (rz.box.min[k] + rz.box.max[k]);
      }
    }
    place_zones();
    double moved = 0;
    for (int z = 0; z < zones_.count; ++z)
      for (int k = 0; k < D; ++k) moved = std::max(moved, std::abs(zones_.lo[z][k] - lo_at_update_[z][k]));
    return moved;
  }

  // Refinement and derefinement (classify, prolongation, daughters) of the n owned
  // particles; the caller then sorts them (sort(), after a migration on several
  // ranks: a daughter may lie in another rank's cell). `cells` must hold the
  // current positions of the owned particles and, on several ranks, of the halos
  // (with their birth levels): the prolongation gradient reads level-r neighbours.
  // Collective over `comm`: the dying mothers' ids and the refining mothers' ids are
  // gathered on every rank (a daughter may live on another rank than its mother;
  // daughter ids follow the global order of their mothers' ids, so they do not
  // depend on the rank count). Families next to a wall are moved off it (`walls`).
  // Returns the new owned count (halos dropped).
  int update(ParticleSet<D>& p, const CellList<D>& cells, const PeriodicBox<D>& box, int n, const Communicator& comm,
             const NearFacets<D>& walls = NearFacets<D>()) {
    Kokkos::View<int*, MemSpace> action("ondine::APR::action", n);
    // the mother flags before this pass (a deleted mother takes its daughters along)
    Kokkos::View<int*, MemSpace> was_mother("ondine::APR::was_mother", n);
    Kokkos::deep_copy(was_mother, Kokkos::subview(p.get(field::AprMother{}), std::make_pair(0, n)));  // halos follow
    Kokkos::parallel_for("ondine::APR::classify", Kokkos::RangePolicy<ExecSpace>(0, n),
                         apr::Classify<D>{zones_, p.get(field::Position{}), p.get(field::AprBirthLevel{}),
                                          p.get(field::AprMother{}), action});
    // derefinement (5.23): the daughters of each derefining (or deleted) mother, level by level
    // the dying ids of every rank, sorted (they are few): a daughter may live on another rank
    Kokkos::View<int*, MemSpace> classified;  // Classify's actions (an adopted daughter takes hers back)
    if (adoption_) {
      classified = Kokkos::View<int*, MemSpace>("ondine::APR::classified", n);
      Kokkos::deep_copy(classified, action);
    }
    std::vector<std::vector<double>> changes(levels_);  // (mother id, mass change) pairs of this rank, per mother level
    Kokkos::View<std::int64_t*, MemSpace> dying_above;  // the previous level's dying ids
    for (int l = 1; l < levels_; ++l) {
      Kokkos::View<std::int64_t*, MemSpace> dying("ondine::APR::dying", n);
      int count = 0;
      Kokkos::parallel_scan("ondine::APR::dying", Kokkos::RangePolicy<ExecSpace>(0, n),
                            apr::DyingScan{action, p.get(field::AprBirthLevel{}), was_mother, p.get(field::GlobalId{}), dying, l - 1},
                            count);
      const auto all = sorted_on_every_rank(Kokkos::subview(dying, std::make_pair(0, count)), comm, "ondine::APR::dying_all");
      const int total = static_cast<int>(all.extent(0));
      if (total > 0) {
        Kokkos::parallel_for("ondine::APR::remove_daughters", Kokkos::RangePolicy<ExecSpace>(0, n),
                             apr::DaughterRemoval{action, p.get(field::AprBirthLevel{}), p.get(field::AprParent{}), all, l, total});
        if (adoption_) adopt(p, cells, box, n, comm, action, classified, dying_above, l, changes[l - 1]);
      }
      dying_above = all;
    }
    // the daughters an open boundary removed since the last bookkeeping leave their mothers
    for (std::size_t k = 0; k + 2 < pending_losses_.size(); k += 3) {
      const int l = static_cast<int>(pending_losses_[k]);
      if (l >= 0 && l < levels_ - 1) changes[l].insert(changes[l].end(), {pending_losses_[k + 1], pending_losses_[k + 2]});
    }
    outflow_daughters_ += comm.sum(static_cast<std::int64_t>(pending_losses_.size() / 3));
    pending_losses_.clear();
    pass_mass_changes(p, n, comm, action, changes);
    // the survivors, then 2^D copies of each refining mother (kernels/ParticleSetEdit.hpp)
    const edit::Plan plan = edit::plan(action, n, apr::Delete, apr::Refine, 1 << D, "ondine::APR");
    const int kept = plan.kept, nref = plan.spawned;
    const int nd = nref << D;
    const Kokkos::View<int*, MemSpace> order = plan.order, refining = plan.spawners, kept_index = plan.kept_index;
    // the refining mothers of all ranks by id: a family's ids are next_id + 2^D (its rank in that order) + c
    const auto families =
        sorted_on_every_rank(edit::spawner_ids(plan, p.get(field::GlobalId{}), "ondine::APR"), comm, "ondine::APR::families");
    const std::int64_t nfam = static_cast<std::int64_t>(families.extent(0));
    deleted_ += comm.sum(static_cast<std::int64_t>(n - kept));
    refined_ += nfam;
    double dp[D + 1] = {};
    long moved = 0;  // families moved off a wall
    if (kept != n || nref > 0) {
      Kokkos::View<double* [D + 1][D], Kokkos::LayoutRight, MemSpace> grad("ondine::APR::prolongation_gradient", nref);
      with_kernel<D>(kernel_, 1.0, [&](auto W1) {
        Kokkos::parallel_for("ondine::APR::prolongation_gradient", Kokkos::RangePolicy<ExecSpace>(0, nref),
                             apr::ProlongationGradient<D, decltype(W1)>{cells, box, zones_, W1, p.get(field::Position{}),
                                                                       p.get(field::Velocity{}), p.get(field::Density{}),
                                                                       p.get(field::Mass{}), p.get(field::AprBirthLevel{}),
                                                                       refining, grad});
      });
      p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept + nd));
      Kokkos::parallel_for("ondine::APR::daughters", Kokkos::RangePolicy<ExecSpace>(0, nref),
                           apr::DaughterFill<D>{zones_, box, refining, kept_index, grad, kept, next_id_, families,
                                                p.get(field::Position{}), p.get(field::Velocity{}), p.get(field::Density{}),
                                                p.get(field::Mass{}), p.get(field::GlobalId{}), p.get(field::AprBirthLevel{}),
                                                p.get(field::AprMother{}), p.get(field::AprParent{})});
      if (walls.facets.count > 0)
        Kokkos::parallel_reduce("ondine::APR::daughter_wall_clearance", Kokkos::RangePolicy<ExecSpace>(0, nref),
                                apr::DaughterWallClearance<D>{walls, box, zones_, refining, kept_index, kept,
                                                              p.get(field::Position{}), p.get(field::AprBirthLevel{})},
                                moved);
      Kokkos::parallel_reduce("ondine::APR::family_momentum", Kokkos::RangePolicy<ExecSpace>(0, nref),
                              apr::FamilyMomentum<D>{D + 1, refining, kept_index, kept, p.get(field::Velocity{}), p.get(field::Mass{})},
                              dp);
      n = kept + nd;
    }
    families_moved_ += comm.sum(static_cast<std::int64_t>(moved));
    for (int a = 0; a < D; ++a) momentum_change_[a] += comm.sum(dp[a]);
    momentum_scale_ += comm.sum(dp[D]);
    next_id_ += nfam << D;
    for (int z = 0; z < zones_.count; ++z)
      for (int k = 0; k < D; ++k) lo_at_update_[z][k] = zones_.lo[z][k];
    return n;
  }

  // The fill at each level's own spacing (kernels/apr/CutTrim.hpp), after the first levels:
  // from the finest level up, a particle that is not a mother and lies beyond its block's
  // cuts goes, a mother keeps its remaining daughters' mass or goes with the last of them.
  // Collective over `comm` (a daughter may live on another rank than its mother: the losses
  // are gathered by mother id on every rank). Returns the new owned count (halos dropped).
  int trim_to_cuts(ParticleSet<D>& p, int n, const Communicator& comm, const FillCuts<D>& cuts) {
    Kokkos::View<int*, MemSpace> action("ondine::APR::trim_action", n);  // Keep
    Kokkos::View<double*, MemSpace> lost("ondine::APR::trim_lost", n);
    std::vector<double> losses;  // (mother id, mass) pairs of the level below
    for (int l = levels_ - 1; l >= 0; --l) {
      const auto [parent, mass] = sorted_pairs(comm.gather_all(losses), "ondine::APR::trim");
      Kokkos::parallel_for("ondine::APR::trim", Kokkos::RangePolicy<ExecSpace>(0, n),
                           apr::CutTrim<D>{cuts, p.get(field::Position{}), p.get(field::Mass{}), p.get(field::AprBirthLevel{}),
                                           p.get(field::AprMother{}), p.get(field::GlobalId{}), parent, mass, action, lost, l});
      losses.clear();
      if (l == 0) break;
      apr::LossScan<D> scan{lost, p.get(field::AprParent{}), {}};
      append_pairs(scan, n, 2, "ondine::APR::trim_losses", losses);
    }
    const edit::Plan plan = edit::plan(action, n, apr::Delete, apr::Refine, 1 << D, "ondine::APR::trim");
    const Kokkos::View<int*, MemSpace> order = plan.order;
    p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(plan.kept));
    return plan.kept;
  }

  // L. and Lx for the n owned particles (sorted), from the levels' cell lists of the current
  // positions of the owned particles and the halos (with their birth levels and roles).
  // `reset_wide`: each guard tries its own radius R_f again (a new list; false when
  // the lists are rebuilt only to follow a migration, and the flags are put back).
  void build_lists(const ParticleSet<D>& p, const PeriodicBox<D>& box, int n, bool reset_wide = true) {
    double cutoff[kAprMaxLevels];
    for (int l = 0; l < kAprMaxLevels; ++l) cutoff[l] = zones_.R[l] + skins_[l];
    cells_.build(box, cutoff, levels_, p.get(field::Position{}), p.get(field::AprBirthLevel{}), static_cast<int>(p.size()));
    apr::LevelVisitor<D, false> dot{cells_.grids, box, cells_.cell_start, cells_.sorted, p.get(field::Position{}),
                                    p.get(field::AprBirthLevel{}), p.get(field::AprGuard{}), p.get(field::AprMother{}), {}, {}, {}};
    for (int l = 0; l < kAprMaxLevels; ++l) dot.cut2[l] = cutoff[l] * cutoff[l];
    apr::build_list<D, false>(l_dot_, dot, n, "SymmetricList");
    apr::LevelVisitor<D, true> cross{cells_.grids, box, cells_.cell_start, cells_.sorted, p.get(field::Position{}),
                                     p.get(field::AprBirthLevel{}), p.get(field::AprGuard{}), p.get(field::AprMother{}), {}, {}, {}};
    for (int l = 0; l < kAprMaxLevels; ++l) {
      cross.cut2[l] = dot.cut2[l];
      const int f = l + 1 < kAprMaxLevels ? l + 1 : l, c = l > 0 ? l - 1 : 0;
      const double rm = zones_.R[f] + 0.5 * (skins_[l] + skins_[f]), rd = zones_.R[c] + 0.5 * (skins_[l] + skins_[c]);
      cross.mother_cut2[l] = rm * rm;
      cross.daughter_cut2[l] = rd * rd;
    }
    apr::build_list<D, true>(l_cross_, cross, n, "GuardList");
    if (psi_.extent(0) < l_cross_.neighbours.extent(0))
      psi_ = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("ondine::APR::guard_weights", l_cross_.neighbours.extent(0), D + 1);
    if (static_cast<int>(used_.extent(0)) < n) {
      used_ = Kokkos::View<int*, MemSpace>("ondine::APR::guard_sources", n + n / 8);
      wide_ = Kokkos::View<int*, MemSpace>("ondine::APR::guard_wide", n + n / 8);
    } else if (reset_wide) {
      Kokkos::deep_copy(wide_, 0);  // new roles: each guard tries R_f again
    }
    weights_valid_ = 0;
  }

  // Guard interpolation (5.24) of the velocity and density (and density gradient),
  // at the start of every Runge-Kutta stage, from the SPH particles of this stage;
  // with `passive`, of the passive guards too (at a bookkeeping and before an output);
  // `only` >= 0: the guards of that level only (local time stepping). The shape functions
  // are recomputed when invalidated (a new step, new lists) and always with `passive`.
  void interpolate(ParticleSet<D>& p, const PeriodicBox<D>& box, bool passive = false,
                   const NearFacets<D>& walls = NearFacets<D>(), int only = -1) {
    Kokkos::Timer timer;
    const auto selected = [&](int l) { return only < 0 || l == only; };
    bool stale = passive;
    for (int l = 0; l < levels_; ++l) stale = stale || (selected(l) && !(weights_valid_ & (1u << l)));
    if (stale) {
      with_kernel<D>(kernel_, 1.0, [&](auto W1) {
        apr::GuardWeights<D, decltype(W1)> f{l_cross_, box, zones_, W1, p.get(field::Position{}), p.get(field::Density{}),
                                             p.get(field::Mass{}), p.get(field::AprBirthLevel{}), p.get(field::AprMother{}), psi_, used_, wide_};
        for (int l = 0; l < levels_; ++l) {
          if (!selected(l) || (!passive && (weights_valid_ & (1u << l)))) continue;
          const int e = passive ? end_[l] : guard_end_[l];
          if (e > active_end_[l])
            Kokkos::parallel_for("ondine::APR::GuardWeights", Kokkos::RangePolicy<ExecSpace>(active_end_[l], e), f);
          if (!passive) weights_valid_ |= 1u << l;
        }
      });
      // the passive guards' weights are fitted with the others': every selected level is fresh
      if (passive)
        for (int l = 0; l < levels_; ++l)
          if (selected(l)) weights_valid_ |= 1u << l;
    }
    apr::GuardApply<D> f{l_cross_, psi_, used_, p.get(field::Velocity{}), p.get(field::Density{}), field_view_t<field::DensityGradient, D>(),
                         walls, box, zones_, p.get(field::Position{}), p.get(field::AprBirthLevel{})};
    if (p.has(field::DensityGradient{})) f.grad_rho = p.get(field::DensityGradient{});
    for (int l = 0; l < levels_; ++l) {
      if (!selected(l)) continue;
      const int e = passive ? end_[l] : guard_end_[l];
      if (e > active_end_[l]) {
        std::int64_t limited = 0;
        Kokkos::parallel_reduce("ondine::APR::GuardInterpolation", Kokkos::RangePolicy<ExecSpace>(active_end_[l], e), f, limited);
        guards_limited_ += limited;
      }
    }
    Kokkos::fence();
    interp_seconds_ += timer.seconds();
  }
  // daughter guards moved by GuardSpacing (kernels/apr/GuardSpacing.hpp), counted by the caller
  void count_guard_shifts(std::int64_t moved) { guard_shifts_ += moved; }
  void count_guards_limited(std::int64_t n) { guards_limited_ += n; }

  // positions moved (a new step; with local time stepping a new step of `level`): the shape
  // functions (of that level's guards) are recomputed at the next interpolation
  void invalidate_weights(int level = -1) { weights_valid_ = level < 0 ? 0u : weights_valid_ & ~(1u << level); }
  // per guard (owned index): fitted at R_m since the last list build (kept across a migration)
  const Kokkos::View<int*, MemSpace>& wide_flags() const { return wide_; }

  // The n owned particles sorted by (level, role) (halos dropped), and the level ranges.
  // `roles`: the roles are computed from the zones (a bookkeeping); otherwise each
  // particle keeps its role (a list rebuild in the middle of a step, after a migration).
  void sort(ParticleSet<D>& p, int n, bool roles) {
    Kokkos::View<int*, MemSpace> key("ondine::APR::key", n), order("ondine::APR::sort_order", n);
    if (roles)
      Kokkos::parallel_for("ondine::APR::roles", Kokkos::RangePolicy<ExecSpace>(0, n),
                           apr::Roles<D>{zones_, p.get(field::Position{}), p.get(field::AprBirthLevel{}), p.get(field::AprMother{}),
                                         p.get(field::AprGuard{}), p.get(field::AprLevel{}), key});
    else
      Kokkos::parallel_for("ondine::APR::role_key", Kokkos::RangePolicy<ExecSpace>(0, n),
                           apr::RoleKey{p.get(field::AprBirthLevel{}), p.get(field::AprGuard{}), key});
    int base = 0;
    for (int l = 0; l < levels_; ++l)
      for (int g = 0; g < 3; ++g) {
        int count = 0;
        Kokkos::parallel_scan("ondine::APR::sort", Kokkos::RangePolicy<ExecSpace>(0, n), apr::KeyScatter{key, order, 3 * l + g, base},
                              count);
        if (g == 0) first_[l] = base;
        base += count;
        (g == 0 ? active_end_[l] : g == 1 ? guard_end_[l] : end_[l]) = base;
      }
    if (base != n)  // only a restart can bring them: a checkpoint of other zones, or a corrupted one
      throw std::runtime_error(std::to_string(n - base) + " particles have a birth level or a role (guard) outside 0.." +
                               std::to_string(levels_ - 1) + " and 0..2");
    p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(n));
    // guards are never integrated: their rates stay zero (the flux passes cover SPH particles only)
    for (int l = 0; l < levels_; ++l)
      if (end_[l] > active_end_[l])
        Kokkos::parallel_for("ondine::APR::zero_guard_rates", Kokkos::RangePolicy<ExecSpace>(active_end_[l], end_[l]),
                             apr::ZeroGuardRates<D>{p.get(field::Acceleration{}), p.get(field::DensityRate{})});
  }

private:
  // The adoptions of level l's daughters (kernels/apr/Adoption.hpp), and their (mother id,
  // mass change) pairs appended to `out`.
  void adopt(ParticleSet<D>& p, const CellList<D>& cells, const PeriodicBox<D>& box, int n, const Communicator& comm,
             const Kokkos::View<int*, MemSpace>& action, const Kokkos::View<int*, MemSpace>& classified,
             const Kokkos::View<std::int64_t*, MemSpace>& dying_above, int l, std::vector<double>& out) {
    Kokkos::View<std::int64_t*, MemSpace> from("ondine::APR::adopted_from", n);
    long counts[2] = {0, 0};
    Kokkos::parallel_reduce("ondine::APR::adoption", Kokkos::RangePolicy<ExecSpace>(0, n),
                            apr::Adoption<D>{2, cells, box, zones_, p.get(field::Position{}), p.get(field::AprBirthLevel{}),
                                             p.get(field::AprMother{}), p.get(field::AprParent{}), p.get(field::GlobalId{}), action,
                                             classified, dying_above, from, l, n},
                            counts);
    adopted_ += comm.sum(static_cast<std::int64_t>(counts[0]));
    orphans_deleted_ += comm.sum(static_cast<std::int64_t>(counts[1]));
    apr::AdoptionScan<D> scan{from, p.get(field::AprParent{}), p.get(field::Mass{}), {}};
    append_pairs(scan, n, 4, "ondine::APR::adoption_pairs", out);
  }

  // The mass changes of the adoptions and of the open boundaries' removals (remove_from_families),
  // from the finest mother level up: each mother takes the
  // sum of hers (gathered by id on every rank: a mother may live on another rank than her
  // daughters) and passes it on to her own mother, so that every mother holds the sum of her
  // daughters' masses.
  void pass_mass_changes(ParticleSet<D>& p, int n, const Communicator& comm, const Kokkos::View<int*, MemSpace>& action,
                         std::vector<std::vector<double>>& changes) {
    Kokkos::View<double*, MemSpace> change("ondine::APR::mass_change", n);
    for (int l = levels_ - 2; l >= 0; --l) {
      const std::vector<double> all = comm.gather_all(changes[l]);
      if (all.empty()) continue;
      const auto [target, delta] = sorted_pairs(all, "ondine::APR::change");
      Kokkos::parallel_for("ondine::APR::mass_change", Kokkos::RangePolicy<ExecSpace>(0, n),
                           apr::MassChange<D>{p.get(field::Mass{}), p.get(field::AprBirthLevel{}), p.get(field::GlobalId{}), target,
                                              delta, action, change, l});
      if (l == 0) break;
      apr::LossScan<D> scan{change, p.get(field::AprParent{}), {}};
      append_pairs(scan, n, 2, "ondine::APR::change_pairs", changes[l - 1]);
    }
  }

  // (id, value) pairs packed as doubles, sorted (by id, then value: the same order on any rank
  // count), on the device
  static std::pair<Kokkos::View<std::int64_t*, MemSpace>, Kokkos::View<double*, MemSpace>> sorted_pairs(const std::vector<double>& packed,
                                                                                                         const std::string& name) {
    std::vector<std::pair<std::int64_t, double>> by_id(packed.size() / 2);
    for (std::size_t k = 0; k < by_id.size(); ++k) by_id[k] = {static_cast<std::int64_t>(packed[2 * k]), packed[2 * k + 1]};
    std::sort(by_id.begin(), by_id.end());
    Kokkos::View<std::int64_t*, MemSpace> id(name + "_id", by_id.size());
    Kokkos::View<double*, MemSpace> value(name + "_value", by_id.size());
    auto hi = Kokkos::create_mirror_view(id);
    auto hv = Kokkos::create_mirror_view(value);
    for (std::size_t k = 0; k < by_id.size(); ++k) {
      hi(k) = by_id[k].first;
      hv(k) = by_id[k].second;
    }
    Kokkos::deep_copy(id, hi);
    Kokkos::deep_copy(value, hv);
    return {id, value};
  }

  // a packing scan's pairs (`width` doubles per entry), counted first, appended to `out`
  template <class Scan>
  static void append_pairs(Scan& scan, int n, int width, const char* name, std::vector<double>& out) {
    int count = 0;
    Kokkos::parallel_scan(name, Kokkos::RangePolicy<ExecSpace>(0, n), scan, count);
    if (count == 0) return;
    scan.pairs = Kokkos::View<double*, MemSpace>(std::string(name), static_cast<std::size_t>(width) * count);
    Kokkos::parallel_scan(name, Kokkos::RangePolicy<ExecSpace>(0, n), scan, count);
    const std::size_t at = out.size();
    out.resize(at + scan.pairs.extent(0));
    Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(out.data() + at, scan.pairs.extent(0)), scan.pairs);
  }

  // zone boxes at their current offsets (a nested zone moves with its outermost parent)
  void place_zones() {
    for (std::size_t z = 0; z < scene_zones_.size(); ++z) {
      std::size_t top = z;
      while (scene_zones_[top].parent >= 0) top = static_cast<std::size_t>(scene_zones_[top].parent);
      zones_.level[z] = scene_zones_[z].level;
      for (int k = 0; k < D; ++k) {
        zones_.lo[z][k] = scene_zones_[z].box.min[k] + offset_[top][k];
        zones_.hi[z][k] = scene_zones_[z].box.max[k] + offset_[top][k];
      }
    }
  }

  std::vector<RefinementZone> scene_zones_;
  std::vector<Vec3> offset_;
  double lo_at_update_[kAprMaxZones][D] = {};
  RefinementZones<D> zones_;
  KernelType kernel_ = KernelType::WendlandC2;
  double skin_ = 0;
  bool adoption_ = true;  // refinement.adoption (kernels/apr/Adoption.hpp)
  double skins_[kAprMaxLevels] = {};  // each level's Verlet skin (skin_ unless local time stepping)
  apr::LevelCells<D> cells_;          // the levels' cell lists L. and Lx are built from
  int levels_ = 1;
  std::vector<int> first_, active_end_, guard_end_, end_;
  NeighbourList<D> l_dot_, l_cross_;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> psi_;  // guard shape functions (Lx entry, value + gradient)
  Kokkos::View<int*, MemSpace> wide_;  // per guard: fitted at R_m since the last list build (GuardWeights)
  Kokkos::View<int*, MemSpace> wide_saved_;  // wide_ before an output (save_wide_flags)
  Kokkos::View<int*, MemSpace> used_;  // per guard: its Lx entries within the interpolation radius (first in its row)
  unsigned weights_valid_ = 0;  // bit l: the shape functions of level l's guards are up to date
  std::int64_t next_id_ = 0, refined_ = 0, deleted_ = 0, families_moved_ = 0, guard_shifts_ = 0, guards_limited_ = 0,
               adopted_ = 0, orphans_deleted_ = 0, outflow_daughters_ = 0;
  std::vector<double> pending_losses_;  // remove_from_families' triples, until the next bookkeeping
  double interp_seconds_ = 0;
  double momentum_change_[D] = {}, momentum_scale_ = 0;
};

}  // namespace ondine
