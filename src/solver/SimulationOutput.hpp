#pragma once
// OutputFrame<D> (Simulation.hpp): the preparation of an output (pressure, Shepard factor,
// free surface; with zones the guards of the stored state, put back when the frame ends),
// and the free-surface flag. The measures the observers read are in solver/Measures.hpp.
// Included by SimulationImpl.hpp only.
#include "kernels/EquationOfState.hpp"
#include "kernels/FreeSurfacePass.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/Simulation.hpp"
#include "solver/StepState.hpp"
#include "solver/hooks/Refinement.hpp"

namespace ondine {

template <int D>
OutputFrame<D>::OutputFrame(Simulation<D>& sim, bool flags) : sim_(sim) {
  StepState<D> s(sim);
  ParticleSet<D>& p = s.particles();
  // several ranks: owned positions are wrapped into the periodic box only at
  // migration; migrate now so that snapshots hold wrapped positions
  if (!s.comm().serial()) {
    if (sim.refinement_) sim.refinement_->relist_for_output(s);
    else s.rebuild_lists(false, false);
  }
  // the stored state's own pressure and Shepard factor (the flux passes left last-stage values)
  s.domain().refresh_state_halos(p);
  if (sim.refinement_) sim.refinement_->interpolate_for_output(s);  // the guards of the stored state (5.24)
  const int n = static_cast<int>(p.size());
  with_eos<D>(s.scene(), [&](auto eos) {
    update_pressure<D>(eos, p.get(field::Density{}), p.get(field::Pressure{}), n);
  });
  if (s.has_walls()) s.update_walls(s.time());
  update_free_surface(sim, flags);
}

template <int D>
OutputFrame<D>::~OutputFrame() {
  if (sim_.refinement_) sim_.refinement_->restore_after_output(sim_.p_);
}

// The free-surface flag (4.86-4.87) of each level's SPH particles (flags: when asked), and
// the Shepard factor of the walls at the stored state (guards included; a guard is no SPH
// particle: no flag); `only` >= 0: that level's particles only.
template <int D>
void update_free_surface(Simulation<D>& sim, bool flags_asked, int only) {
  StepState<D> s(sim);
  ParticleSet<D>& p = s.particles();
  const bool flags = flags_asked && p.has(field::FreeSurface{});
  const bool walls = s.has_walls();
  if (flags) {
    s.ensure_lists();
    s.domain().refresh_state_halos(p);
  }
  const auto x = p.get(field::Position{});
  for (const LevelSpan<D>& L : s.levels()) {
    if (only >= 0 && L.level != only) continue;
    if (flags && L.end > L.active_end)
      Kokkos::deep_copy(Kokkos::subview(p.get(field::FreeSurface{}), std::make_pair(L.active_end, L.end)), 0.0);
    // gamma of every particle of the level, its guards included, even on a rank that holds
    // only guards of it (the snapshot would otherwise depend on the rank count)
    if (walls && L.end > L.first)
      Kokkos::parallel_for("ondine::NFM::shepard_gamma", Kokkos::RangePolicy<ExecSpace>(L.first, L.end),
                           ShepardGammaPass<D>{s.walls().facets(), s.walls().facet_cells(), L.R, s.domain().box(), x,
                                               p.get(field::ShepardGamma{})});
    if (L.active_end == L.first) continue;
    if (!flags) continue;
    s.scheme().free_surface(s.context(L));
  }
}

}  // namespace ondine
