#pragma once
// Simulation<D> members used only with refinement zones (adaptive particle
// refinement, thesis 5.4; docs/apr.md); included by SimulationImpl.hpp. A scene
// without zones never reaches them. Particles are sorted by level, each level's
// SPH particles first, then its guards; every existing pass runs once per level
// over that level's SPH particles, with the level's radius R_l = R_0 / 2^l and
// the symmetric list L. (so its pair loop is the uniform one, with no test).
#include "kernels/apr/GuardSpacing.hpp"
#include "kernels/apr/LevelSums.hpp"

namespace ondine {

// Several ranks (docs/parallel.md, "Refinement zones"): each rank refines and derefines
// the particles it owns. Before: migration, and halos with their birth levels (the
// prolongation gradient reads the level-r neighbours of a mother, owned or not);
// after: a second migration (a daughter may lie in another rank's cell), the sort,
// halos with levels and roles, the lists. The dying and refining mothers' ids are
// gathered on every rank inside AdaptiveRefinement::update.
template <int D>
void Simulation<D>::refinement_bookkeeping() {
  if (!comm_.serial()) {
    n_own_ = exchange_.migrate(p_, n_own_, orb_, box_, comm_);
    exchange_.build_halos(p_, n_own_, orb_, box_, comm_);
    exchange_.refresh(p_, comm_, field::AprBirthLevel{});
  }
  cells_.build(local_grid_, p_.get(field::Position{}), static_cast<int>(p_.size()));  // for the prolongation gradient
  n_own_ = apr_.update(p_, cells_, box_, n_own_, comm_, walls_.segments());
  list_valid_ = false;
  bookkeeping_due_ = false;
  rebuild_level_lists(true, true);
  apr_.interpolate(p_, box_, true, walls_.segments());  // passive guards: once per bookkeeping
  refresh_guard_halos();
}

// The particles sorted by (level, role) and the lists L. and Lx over owned + halo
// particles. `roles`: recomputed from the zones (a bookkeeping), else kept (a rebuild
// within a step). One rank: no migration, and the order is already right without
// new roles. Several ranks: migration first (received particles come last, so the
// sort is redone), then halos that carry their birth level and role (the lists and
// the guard interpolation select partners by them); then the balance check of the
// uniform path, the work of a rank being its L. and Lx entries.
template <int D>
void Simulation<D>::rebuild_level_lists(bool roles, bool may_rebalance) {
  if (!comm_.serial()) n_own_ = exchange_.migrate(p_, n_own_, orb_, box_, comm_);
  if (roles || !comm_.serial()) apr_.sort(p_, n_own_, roles);
  if (!comm_.serial()) {
    exchange_.build_halos(p_, n_own_, orb_, box_, comm_);
    exchange_.refresh(p_, comm_, field::AprBirthLevel{}, field::AprGuard{});
    halos_fresh_ = true;
  }
  const auto x = p_.get(field::Position{});
  cells_.build(local_grid_, x, static_cast<int>(p_.size()));
  apr_.build_lists(p_, cells_, box_, n_own_);
  if (scene_.neighbour_skin > 0) {
    if (x_at_build_.extent(0) != x.extent(0))
      x_at_build_ = field_view_t<field::Position, D>("ondine::NeighbourList::x_at_build", x.extent(0));
    Kokkos::deep_copy(x_at_build_, x);
  }
  list_valid_ = true;
  ++builds_;
  if (comm_.serial()) return;
  // the work of a rank: its L. and Lx entries; the roles just computed are kept on a rebalance
  check_balance(static_cast<std::int64_t>(apr_.symmetric_list().total() + apr_.guard_list().total()), may_rebalance,
                [this] { rebuild_level_lists(false, false); });
}

// Several ranks, before an output: owned positions are wrapped into the periodic box
// only at a migration, so the output migrates; but a one-rank run does not rebuild its
// lists there, and with refinement zones a list build is not neutral (the next
// bookkeeping comes with the Verlet criterion, and a guard's choice of radius is reset).
// So the reference positions of the Verlet criterion and the guards' radius flags
// travel with their particles (in the stage storage, free between steps) and are put
// back, and the lists' validity is kept: the run goes on as if nothing had happened.
template <int D>
void Simulation<D>::relist_for_output() {
  allocate_stage_storage();
  const bool valid = list_valid_;
  const auto xs = p_.get(field::StagePosition{});
  const auto ws = p_.get(field::StageDensity{});
  const int n = n_own_;
  if (valid) {
    const auto xb = x_at_build_;
    const auto wide = apr_.wide_flags();
    const bool verlet = scene_.neighbour_skin > 0;
    Kokkos::parallel_for("ondine::APR::stash", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < D; ++k) xs(i, k) = verlet ? xb(i, k) : 0.0;
      ws(i) = wide.extent(0) > static_cast<std::size_t>(i) ? wide(i) : 0;
    });
  }
  n_own_ = exchange_.migrate(p_, n_own_, orb_, box_, comm_);
  apr_.sort(p_, n_own_, false);
  exchange_.build_halos(p_, n_own_, orb_, box_, comm_);
  exchange_.refresh(p_, comm_, field::AprBirthLevel{}, field::AprGuard{});
  halos_fresh_ = true;
  const auto x = p_.get(field::Position{});
  cells_.build(local_grid_, x, static_cast<int>(p_.size()));
  apr_.build_lists(p_, cells_, box_, n_own_, false);
  if (valid) {
    const auto xs2 = p_.get(field::StagePosition{});
    const auto ws2 = p_.get(field::StageDensity{});
    const auto wide = apr_.wide_flags();
    Kokkos::parallel_for("ondine::APR::unstash", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                         KOKKOS_LAMBDA(const int i) { wide(i) = static_cast<int>(ws2(i)); });
    if (scene_.neighbour_skin > 0) {
      if (x_at_build_.extent(0) != x.extent(0))
        x_at_build_ = field_view_t<field::Position, D>("ondine::NeighbourList::x_at_build", x.extent(0));
      Kokkos::deep_copy(x_at_build_, xs2);
    }
  }
  list_valid_ = valid;
}

template <int D>
void Simulation<D>::refresh_guard_halos() {
  if (comm_.serial()) return;
  if (p_.has(field::DensityGradient{}))
    exchange_.refresh(p_, comm_, field::Velocity{}, field::Density{}, field::DensityGradient{});
  else
    exchange_.refresh(p_, comm_, field::Velocity{}, field::Density{});
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
      detail::with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, p_.get(field::Density{}), P, n); });
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
    const std::vector<double> all = comm_.gather_all(mine);
    int win = 0;
    for (int r = 1; r < comm_.size(); ++r)
      if (all[r * (D + 1)] > all[win * (D + 1)]) win = r;
    if (!(all[win * (D + 1)] > 0)) return false;
    for (int k = 0; k < D; ++k) at[k] = all[win * (D + 1) + 1 + k];
    return true;
  });
  bool rebuild = !list_valid_ || bookkeeping_due_ || moved > 0.5 * skin_len_;
  if (!rebuild) {
    double d2max = 0;
    Kokkos::parallel_reduce("ondine::NeighbourList::displacement", Kokkos::RangePolicy<ExecSpace>(0, n),
                            MaxDisplacement2<D>{box_, x, x_at_build_}, Kokkos::Max<double>(d2max));
    rebuild = comm_.max(d2max) >= 0.25 * skin_len_ * skin_len_;
  }
  if (rebuild) refinement_bookkeeping();
  // with refinement.guard_shifting: the daughter guards shifted towards a regular
  // arrangement, with refinement.mother_shifting the mother guards towards their
  // daughters' volume (kernels/apr/GuardSpacing.hpp), from fresh halo positions; the
  // halos then carry the new positions
  if (!scene_.refinement_guard_shifting && !scene_.refinement_mother_shifting) return;
  refresh_halos();
  if (space_guards() > 0 || !comm_.serial()) halos_fresh_ = false;
}

// The daughter guards of each level l >= 1 (refinement.guard_shifting) and the mother
// guards of each level l < levels - 1 (refinement.mother_shifting) shifted
// (kernels/apr/GuardSpacing.hpp) from the positions of the owned particles and the halos
// (cells_ of the last list build, fresh positions); returns the number of guards moved
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
  if (walls && level_wall_cells_.empty()) build_level_wall_cells();
  const auto x = p_.get(field::Position{});
  for (int l = mothers ? 0 : 1; l < apr_.levels(); ++l) {
    const int b = apr_.active_end(l), e = apr_.end(l);
    if (e == b) continue;
    const double Rl = apr_.R(l), dxl = apr_.dx(l);
    if (walls && daughters && l > 0)
      Kokkos::parallel_for("ondine::NFM::ShepardGamma", Kokkos::RangePolicy<ExecSpace>(b, e),
                           ShepardGammaPass<D>{walls_.segments(), Rl, box_, x, p_.get(field::ShepardGamma{})});
    long moved = 0;
    with_kernel<D>(scene_.kernel, 1.0, [&](auto W1) {
      auto run = [&](auto f) { Kokkos::parallel_reduce("ondine::APR::GuardSpacing", Kokkos::RangePolicy<ExecSpace>(b, e), f, moved); };
      if (walls)
        run(apr::GuardSpacing<D, decltype(W1), true>{cells_, box_, apr_.zones(), W1, Rl, dxl, walls_.segments(), walls_.points(),
                                                     wall_cells(l), x, p_.get(field::Density{}), p_.get(field::Mass{}),
                                                     p_.get(field::AprBirthLevel{}), p_.get(field::AprMother{}),
                                                     p_.get(field::ShepardGamma{}), guard_shift_, daughters, mothers});
      else
        run(apr::GuardSpacing<D, decltype(W1), false>{cells_, box_, apr_.zones(), W1, Rl, dxl, walls_.segments(), walls_.points(),
                                                      wall_cells(0), x, p_.get(field::Density{}), p_.get(field::Mass{}),
                                                      p_.get(field::AprBirthLevel{}), p_.get(field::AprMother{}),
                                                      field_view_t<field::ShepardGamma, D>(), guard_shift_, daughters, mothers});
    });
    if (moved > 0)
      Kokkos::parallel_for("ondine::APR::GuardSpacing::apply", Kokkos::RangePolicy<ExecSpace>(b, e), apr::ApplyShift<D>{box_, x, guard_shift_});
    total += moved;
  }
  apr_.count_guard_shifts(total);
  apr_.invalidate_weights();
  return total;
}

template <int D>
void Simulation<D>::evaluate_levels() {
  ensure_neighbours();  // lists only: roles change at a step start (refinement_step_start)
  refresh_halos();      // several ranks: this stage's halo sources of the guards
  const int n = n_own_, n_all = static_cast<int>(p_.size());
  if (!walls_.empty()) update_walls(stage_time_);
  apr_.interpolate(p_, box_, false, walls_.segments());  // guards from this stage's SPH particles (5.24)
  // several ranks: the guards' halo copies (their density gradient travels after the gradient pass)
  if (!comm_.serial()) exchange_.refresh(p_, comm_, field::Velocity{}, field::Density{});
  FluxArgs<D> a = state_flux_args(n);
  a.list = apr_.symmetric_list();
  // with no-slip walls the consistent Laplacian's weights are solved per level
  const bool morris_walls = consistent_laplacian();
  detail::with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, a.rho, a.P, n_all); });
  if (scene_.background_pressure) {
    double pmin = 0;
    Kokkos::parallel_reduce("ondine::BackgroundPressure::min", Kokkos::RangePolicy<ExecSpace>(0, n), apr::MinOf{a.P},
                            Kokkos::Min<double>(pmin));
    pmin = comm_.min(pmin);
    a.P_min = pmin < 0 ? -pmin : 0.0;
  }
  const bool walls = !walls_.empty();
  if (walls) {
    update_walls(stage_time_);
    if (walls_.moving() || level_wall_cells_.empty()) build_level_wall_cells();
  }
  const bool gradient = scene_.delta_sph > 0 || walls;
  if (gradient) a.grad_rho = p_.get(field::DensityGradient{});
  for (int l = 0; l < apr_.levels(); ++l) {
    const int b = apr_.first(l), e = apr_.active_end(l);
    if (e == b) continue;
    const double Rl = apr_.R(l);
    if (walls)
      Kokkos::parallel_for("ondine::NFM::ShepardGamma", Kokkos::RangePolicy<ExecSpace>(b, e),
                           ShepardGammaPass<D>{walls_.segments(), Rl, box_, a.x, p_.get(field::ShepardGamma{})});
    if (gradient)
      with_kernel<D>(scene_.kernel, Rl, [&](auto W) {
        if (morris_walls)
          Kokkos::parallel_for("ondine::DensityGradient+consistent_laplacian", Kokkos::RangePolicy<ExecSpace>(b, e),
                               DensityGradientPass<D, decltype(W), true>{
                                   a.list, box_, W, Rl * Rl, a.x, a.rho, a.m, a.grad_rho,
                                   {walls_.points(), wall_cells(l), 0.05 * Rl, morris_factor_, p_.get(field::ShepardGamma{}),
                                    laplacian_weights_}});
        else
          Kokkos::parallel_for("ondine::DensityGradient", Kokkos::RangePolicy<ExecSpace>(b, e),
                               DensityGradientPass<D, decltype(W)>{a.list, box_, W, Rl * Rl, a.x, a.rho, a.m, a.grad_rho});
      });
  }
  // the guards' density gradient came with their interpolation (GuardInterpolation.hpp)
  if (gradient && !comm_.serial()) exchange_.refresh(p_, comm_, field::DensityGradient{});
  for (int l = 0; l < apr_.levels(); ++l) {
    const int b = apr_.first(l), e = apr_.active_end(l);
    if (e == b) continue;
    const double Rl = apr_.R(l);
    a.first = b;
    a.n = e - b;
    a.R = Rl;
    a.delta_coeff = scene_.delta_sph * scene_.c0 * Rl;
    a.av_alpha_R_c0 = scene_.artificial_viscosity * Rl * scene_.c0;
    flux_(a);
    if (!walls) continue;
    with_kernel<D>(scene_.kernel, Rl, [&](auto W) {
      const WallEos weos = wall_eos();
      if (morris_walls)
        Kokkos::parallel_for("ondine::NFM::WallFlux", Kokkos::RangePolicy<ExecSpace>(b, e),
                             WallFluxPass<D, decltype(W), true, true>{walls_.points(), wall_cells(l), W, Rl * Rl, a.body, scene_.nu, weos,
                                                                      0.05 * Rl, box_, a.P_min, a.x, a.u, a.rho, a.P, a.grad_rho,
                                                                      p_.get(field::ShepardGamma{}), a.du, a.drho, laplacian_weights_, a.list, a.m,
                                                                      0.5 * Rl / scene_.R_over_dx, scene_.wall_velocity_reconstruction});
      else if (scene_.viscous_term != ViscousTerm::None)
        Kokkos::parallel_for("ondine::NFM::WallFlux", Kokkos::RangePolicy<ExecSpace>(b, e),
                             WallFluxPass<D, decltype(W), true, false>{walls_.points(), wall_cells(l), W, Rl * Rl, a.body, scene_.nu, weos,
                                                                       0.05 * Rl, box_, a.P_min, a.x, a.u, a.rho, a.P, a.grad_rho,
                                                                       p_.get(field::ShepardGamma{}), a.du, a.drho, {}, a.list, a.m, 0.5 * Rl / scene_.R_over_dx,
                                                                        scene_.wall_velocity_reconstruction});
      else
        Kokkos::parallel_for("ondine::NFM::WallFlux", Kokkos::RangePolicy<ExecSpace>(b, e),
                             WallFluxPass<D, decltype(W), false, false>{walls_.points(), wall_cells(l), W, Rl * Rl, a.body, scene_.nu, weos,
                                                                        0.05 * Rl, box_, a.P_min, a.x, a.u, a.rho, a.P, a.grad_rho,
                                                                        p_.get(field::ShepardGamma{}), a.du, a.drho, {}, a.list, a.m, 0.5 * Rl / scene_.R_over_dx,
                                                                        scene_.wall_velocity_reconstruction});
    });
  }
}

// Cell lists of the wall points with cells of level l's radius (l >= 1): a fine
// particle then visits the wall points of its own neighbourhood, not of the coarse one.
template <int D>
void Simulation<D>::build_level_wall_cells() {
  level_wall_cells_.resize(apr_.levels());
  for (int l = 1; l < apr_.levels(); ++l)
    level_wall_cells_[l].build(make_cell_grid(box_, apr_.R(l)), walls_.points().x, walls_.points().count);
}

template <int D>
void Simulation<D>::update_free_surface_levels() {
  ensure_neighbours();
  const bool walls = !walls_.empty();
  if (walls && level_wall_cells_.empty()) build_level_wall_cells();
  for (int l = 0; l < apr_.levels(); ++l) {
    const int b = apr_.first(l), e = apr_.active_end(l);
    // a guard is no SPH particle: no free-surface flag (not a value left from when it was one)
    if (p_.has(field::FreeSurface{}) && apr_.end(l) > e)
      Kokkos::deep_copy(Kokkos::subview(p_.get(field::FreeSurface{}), std::make_pair(e, apr_.end(l))), 0.0);
    if (e == b) continue;
    const double Rl = apr_.R(l);
    if (walls)
      Kokkos::parallel_for("ondine::NFM::ShepardGamma", Kokkos::RangePolicy<ExecSpace>(b, apr_.end(l)),
                           ShepardGammaPass<D>{walls_.segments(), Rl, box_, p_.get(field::Position{}), p_.get(field::ShepardGamma{})});
    if (!p_.has(field::FreeSurface{})) continue;
    with_kernel<D>(scene_.kernel, Rl, [&](auto W) {
      using K = decltype(W);
      if (!walls)
        Kokkos::parallel_for("ondine::FreeSurface", Kokkos::RangePolicy<ExecSpace>(b, e),
                             FreeSurfacePass<D, K, false>{apr_.symmetric_list(), box_, W, Rl, Rl * Rl, walls_.points(), walls_.cells(),
                                                          p_.get(field::Position{}), p_.get(field::Density{}), p_.get(field::Mass{}),
                                                          field_view_t<field::ShepardGamma, D>(), p_.get(field::FreeSurface{})});
      else
        Kokkos::parallel_for("ondine::FreeSurface", Kokkos::RangePolicy<ExecSpace>(b, e),
                             FreeSurfacePass<D, K, true>{apr_.symmetric_list(), box_, W, Rl, Rl * Rl, walls_.points(), wall_cells(l),
                                                         p_.get(field::Position{}), p_.get(field::Density{}), p_.get(field::Mass{}),
                                                         p_.get(field::ShepardGamma{}), p_.get(field::FreeSurface{})});
    });
  }
}

// Probes with refinement zones: Shepard sums over the SPH particles, each with its level's radius.
template <int D>
std::vector<ProbeSample> Simulation<D>::sample_levels(const std::vector<Vec3>& points) const {
  std::vector<ProbeSample> out;
  for (const Vec3& point : points) {
    ProbeSample s;
    with_kernel<D>(scene_.kernel, 1.0, [&](auto W1) {
      apr::ProbeSum<D, decltype(W1)> f{apr_.zones(), W1, Vec<D>::zero(), p_.get(field::Position{}), p_.get(field::Velocity{}),
                                       p_.get(field::Density{}), p_.get(field::Pressure{}), p_.get(field::Mass{}),
                                       p_.get(field::AprBirthLevel{}), p_.get(field::AprGuard{}), 0};
      for (int k = 0; k < D; ++k) f.xp[k] = point[k];
      auto sum = [&](int what) {
        f.what = what;
        double acc = 0;
        Kokkos::parallel_reduce("ondine::Probe", Kokkos::RangePolicy<ExecSpace>(0, n_own_), f, acc);
        return comm_.sum(acc);
      };
      s.shepard = sum(0);
      if (s.shepard > 0) {
        s.pressure = sum(1) / s.shepard;
        s.density = sum(2) / s.shepard;
        for (int k = 0; k < D; ++k) s.velocity[k] = sum(3 + k) / s.shepard;
      }
    });
    out.push_back(s);
  }
  return out;
}

template <int D>
std::int64_t Simulation<D>::sph_particles() const {
  if (!apr_on_) return n_own_;
  long g = 0;
  Kokkos::parallel_reduce("ondine::APR::count_guards", Kokkos::RangePolicy<ExecSpace>(0, n_own_),
                          apr::CountGuards{p_.get(field::AprGuard{})}, g);
  return n_own_ - g;
}

}  // namespace ondine
