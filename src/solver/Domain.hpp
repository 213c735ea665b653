#pragma once
// The domain of a run: the periodic box, the cell grids, the ORB decomposition over the
// ranks (thesis Algorithm 4), halos and migration, the cell list and the neighbour lists'
// freshness. It keeps the orderings that no caller should have to know: the lists are
// valid until a decomposition or a reordering, the halos' state fields are fresh until
// the owned particles change, and the Verlet criterion measures from the last build.
// It reads the particles it is given and moves them between ranks; it computes no physics.
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "kernels/CellList.hpp"
#include "kernels/NeighbourList.hpp"
#include "kernels/OrbLookup.hpp"
#include "kernels/Permute.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/OrbLookupBuild.hpp"
#include "parallel/ParticleExchange.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D>
class Domain {
 public:
  Domain() = default;
  // `cutoff` = R + skin (the cell size and the list radius), `skin` the Verlet skin length
  Domain(const Scene& scene, double cutoff, double skin) : cutoff_(cutoff), skin_(skin), half_(scene.half_pair_list) {
    for (int k = 0; k < D; ++k) {
      box_.lo[k] = scene.domain.min[k];
      box_.len[k] = scene.domain.max[k] - scene.domain.min[k];
      box_.periodic[k] = scene.periodic[k];
      if (box_.periodic[k] && box_.len[k] < 2.0 * cutoff_)
        throw std::invalid_argument("a periodic axis must be at least 2 (R + skin) long");
    }
    global_grid_ = make_cell_grid(box_, cutoff_);
    local_grid_ = global_grid_;
    local_box_ = box_;
  }

  const Communicator& comm() const { return comm_; }
  bool serial() const { return comm_.serial(); }
  const PeriodicBox<D>& box() const { return box_; }
  // the box the integrator wraps owned positions in: periodic only along the axes this rank spans
  const PeriodicBox<D>& local_box() const { return local_box_; }
  double cutoff() const { return cutoff_; }
  double skin() const { return skin_; }
  // refinement zones with local time stepping: a Verlet skin per level (neighbour_skin dx_l; the
  // cells then hold R + the coarse level's skin); empty: skin() for every particle
  void set_level_skins(std::vector<double> skins) { level_skins_ = std::move(skins); }
  const std::vector<double>& level_skins() const { return level_skins_; }
  const CellList<D>& cells() const { return cells_; }
  const NeighbourList<D>& list() const { return list_; }
  // scheme.pair_list: half: each pair of owned particles once (kernels/SymmetricFluxPass.hpp); empty otherwise
  const NeighbourList<D>& half_list() const { return half_list_; }
  const OrbLookup<D>& orb() const { return orb_; }
  const Decomposition& decomposition() const { return decomposition_; }
  const ParticleExchange<D>& exchange() const { return exchange_; }

  // --- lists -----------------------------------------------------------------------
  bool lists_valid() const { return list_valid_; }
  void invalidate_lists() { list_valid_ = false; }
  std::int64_t builds() const { return builds_; }
  // Verlet criterion: the lists still hold every pair within R while no particle (on any
  // rank) has moved more than skin/2 since the last build
  // (with level skins and the particles' birth levels: each within half its level's skin)
  bool lists_hold(const field_view_t<field::Position, D>& x, int n, const Kokkos::View<int*, MemSpace>& birth = {}) const {
    if (!list_valid_ || skin_ <= 0) return false;
    if (!level_skins_.empty() && birth.extent(0) >= static_cast<std::size_t>(n)) {
      MaxScaledDisplacement2<D> f{box_, x, x_at_build_, birth, {}};
      for (std::size_t l = 0; l < level_skins_.size() && l < MaxScaledDisplacement2<D>::max_levels; ++l)
        f.inv_half_skin2[l] = 4.0 / (level_skins_[l] * level_skins_[l]);
      double s2max = 0;
      Kokkos::parallel_reduce("ondine::NeighbourList::level_displacement", Kokkos::RangePolicy<ExecSpace>(0, n), f,
                              Kokkos::Max<double>(s2max));
      return comm_.max(s2max) < 1.0;
    }
    double d2max = 0;
    Kokkos::parallel_reduce("ondine::NeighbourList::displacement", Kokkos::RangePolicy<ExecSpace>(0, n),
                            MaxDisplacement2<D>{box_, x, x_at_build_}, Kokkos::Max<double>(d2max));
    const double half_skin = 0.5 * skin_;
    return comm_.max(d2max) < half_skin * half_skin;
  }
  // the cell list over the first `count` particles (owned + halos)
  void build_cells(const field_view_t<field::Position, D>& x, int count) { cells_.build(local_grid_, x, count); }
  // the uniform list of the n owned particles (radius R + skin), from the current cells
  void build_list(const field_view_t<field::Position, D>& x, int n) {
    list_.build(cells_, box_, x, n, cutoff_);
    if (half_) half_list_.build_half(list_, 0, n);
  }
  // a list build is complete: the Verlet reference positions are these
  void built(const field_view_t<field::Position, D>& x) {
    set_reference(x);
    list_valid_ = true;
    ++builds_;
  }
  const field_view_t<field::Position, D>& built_positions() const { return x_at_build_; }
  // the Verlet reference positions after a relisting that moved particles between ranks
  void restore_built_positions(const field_view_t<field::Position, D>& x_ref, bool valid) {
    if (valid) set_reference(x_ref);
    list_valid_ = valid;
  }

  // --- ranks -----------------------------------------------------------------------
  // every owned particle to the owner of its cell; returns the new owned count
  int migrate(ParticleSet<D>& p, int n_own) { return exchange_.migrate(p, n_own, orb_, box_, comm_); }
  void build_halos(ParticleSet<D>& p, int n_own) {
    exchange_.build_halos(p, n_own, orb_, box_, comm_);
    halos_fresh_ = true;
  }
  template <class... Tags>
  void refresh(ParticleSet<D>& p, Tags... tags) {
    if (!comm_.serial()) exchange_.refresh(p, comm_, tags...);
  }
  // the halos' position, velocity and density, when the owned ones changed since
  void refresh_state_halos(ParticleSet<D>& p) {
    if (comm_.serial() || halos_fresh_) return;
    exchange_.refresh(p, comm_, field::Position{}, field::Velocity{}, field::Density{});
    halos_fresh_ = true;
  }
  void halos_stale() { halos_fresh_ = false; }

  // ORB of the global cell grid (src/parallel/Decomposition.hpp), weighted by the pair
  // interactions of each cell (`pairs`, and `guards` with refinement zones: a guard's
  // work is its interpolation sources) or, before the first list, by its particle count
  void decompose(const field_view_t<field::Position, D>& x, int n_own, const NeighbourList<D>& pairs,
                 const NeighbourList<D>* guards, bool by_pairs) {
    const int ncell = global_grid_.cells();
    Kokkos::View<double*, MemSpace> work("ondine::Decomposition::work", ncell);
    const bool counted = by_pairs && list_valid_;
    Kokkos::parallel_for("ondine::Decomposition::work", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                         CellWork<D>{global_grid_, box_, pairs, x, work, counted});
    if (guards && counted)
      Kokkos::parallel_for("ondine::Decomposition::guard_work", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                           CellWork<D>{global_grid_, box_, *guards, x, work, true});
    std::vector<double> host(ncell);
    Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(host.data(), ncell), work);
    comm_.sum_in_place(host);
    bool periodic[D];
    for (int k = 0; k < D; ++k) periodic[k] = box_.periodic[k];
    decomposition_ = Decomposition::bisect(D, global_grid_.n, periodic, host, comm_.size());
    orb_ = make_orb_lookup<D>(decomposition_, global_grid_);
    const CellBox& mine = decomposition_.box(comm_.rank());
    local_grid_ = local_cell_grid<D>(global_grid_, mine);
    local_box_ = box_;
    for (int k = 0; k < D; ++k) local_box_.periodic[k] = box_.periodic[k] && decomposition_.spans(comm_.rank(), k);
    list_valid_ = false;
  }

  // tau = min work / max work over the ranks (thesis 5.30), work = this rank's pair
  // interactions `pairs` (scene.balance_by_pairs) or particles. Below the threshold the
  // domain is bisected again (`bisect`) and `relist` rebuilds the lists; when cell-wide
  // cuts cannot reach the threshold, only once the balance is clearly worse (0.05) than
  // the last rebalance achieved.
  template <class Bisect, class Relist>
  void check_balance(const Scene& scene, std::int64_t pairs, int n_own, std::int64_t step, bool may_rebalance,
                     Bisect&& bisect, Relist&& relist) {
    std::vector<double> work;
    const std::int64_t mine = scene.balance_by_pairs ? pairs : n_own;
    for (std::int64_t w : comm_.gather_all(mine)) work.push_back(static_cast<double>(w));
    tau_ = balance_indicator(work);
    if (may_rebalance && tau_ < std::min(scene.rebalance_threshold, achieved_tau_ - 0.05)) {
      const double before = tau_;
      Kokkos::Timer timer;
      bisect();
      ++rebalances_;
      relist();
      rebalance_seconds_ += timer.seconds();
      achieved_tau_ = tau_;
      if (comm_.rank() == 0)
        std::fprintf(stderr, "ondine: step %lld: rebalanced, tau %.3f -> %.3f\n", static_cast<long long>(step), before, tau_);
    }
  }
  double balance() const { return tau_; }
  int rebalances() const { return rebalances_; }
  double rebalance_seconds() const { return rebalance_seconds_; }  // new bisections and the list rebuilds they cause

  // owned particles sorted by cell for memory locality; halos are dropped (the next list
  // build brings them back)
  void reorder_by_cell(ParticleSet<D>& p, int n_own) {
    cells_.build(local_grid_, p.get(field::Position{}), n_own);
    const auto perm = Kokkos::subview(cells_.sorted, std::make_pair(0, n_own));
    Kokkos::View<int*, MemSpace> order("ondine::Reorder::order", n_own);
    Kokkos::deep_copy(order, perm);
    p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(n_own));
    list_valid_ = false;
  }

 private:
  // the Verlet reference positions (only with a skin)
  void set_reference(const field_view_t<field::Position, D>& x) {
    if (skin_ <= 0) return;
    if (x_at_build_.extent(0) != x.extent(0))
      x_at_build_ = field_view_t<field::Position, D>("ondine::NeighbourList::x_at_build", x.extent(0));
    Kokkos::deep_copy(x_at_build_, x);
  }

  Communicator comm_;
  PeriodicBox<D> box_, local_box_;
  double cutoff_ = 0, skin_ = 0;
  std::vector<double> level_skins_;
  // global grid, this rank's grid (own cells + halo ring)
  CellGrid<D> global_grid_, local_grid_;
  Decomposition decomposition_;
  OrbLookup<D> orb_;
  ParticleExchange<D> exchange_;
  CellList<D> cells_;
  NeighbourList<D> list_;
  bool half_ = false;
  NeighbourList<D> half_list_;
  field_view_t<field::Position, D> x_at_build_;
  bool list_valid_ = false, halos_fresh_ = true;
  std::int64_t builds_ = 0;
  double tau_ = 1.0, achieved_tau_ = 2.0;
  int rebalances_ = 0;
  double rebalance_seconds_ = 0;
};

}  // namespace ondine
