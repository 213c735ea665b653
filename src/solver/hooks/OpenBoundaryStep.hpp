#pragma once
// The open boundaries (solver/OpenBoundaries.hpp, kernels/OpenBoundary.hpp) in the step:
// at a step start the roles and the particles created and removed (before the refinement's
// bookkeeping, which then sorts them); on the lists of the new particle set, the fluid's state
// at each facet's sample point, the facets' filtered invariants and the buffer particles'
// state; the buffers' rates zeroed after each evaluation (they are not integrated) and their
// lattice and state kept through shifting. Runs with open_boundaries.
#include <stdexcept>

#include "solver/KernelDispatch.hpp"
#include "solver/OpenBoundaries.hpp"
#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class OpenBoundaryStep final : public StepHook<D> {
 public:
  OpenBoundaryStep(const Scene& s, const CheckpointSlice* restart) : open_(s) {
    if (restart && !restart->header.open.present)
      throw std::runtime_error("the checkpoint was written by a run without open boundaries; the case has open_boundaries");
  }
  const char* name() const override { return "open_boundaries"; }
  const OpenBoundaries<D>& boundaries() const { return open_; }

  void allocate(ParticleSet<D>& p) override { p.allocate(field::OpenRole{}); }
  // the roles, and the particles beyond the buffers dropped, before the refinement sorts them
  void start(StepState<D>& s, const CheckpointSlice* restart) override {
    if (restart) open_.restore(restart->header.open);
    else s.set_owned(open_.start(s.particles(), s.owned(), s.comm().sum(static_cast<std::int64_t>(s.owned()))));
  }
  void started(const Diagnostics& d) override { open_.set_initial_mass(d.mass, d.fluid_mass); }
  std::int64_t next_id() const override { return open_.next_id(); }

  void step_start(StepState<D>& s) override {
    bool changed = false;
    s.set_owned(open_.classify(s.particles(), s.owned(), s.comm(), changed, s.shared_id_counter()));
    // daughters removed with the stream leave their mothers' mass too (at the bookkeeping that
    // follows the edit, before any checkpoint)
    if (AdaptiveRefinement<D>* apr = s.adaptive_refinement()) apr->remove_from_families(open_.take_family_losses());
    if (changed) s.particles_changed();  // on every rank
  }
  void after_lists(StepState<D>& s) override {
    ParticleSet<D>& p = s.particles();
    s.ensure_lists();
    s.domain().refresh_state_halos(p);
    if (!s.comm().serial()) s.domain().refresh(p, field::OpenRole{});
    const int n_all = static_cast<int>(p.size());
    with_eos<D>(s.scene(), [&](auto eos) { update_pressure<D>(eos, p.get(field::Density{}), p.get(field::Pressure{}), n_all); });
    PassContext<D> c = s.context();
    c.end = s.owned();
    c.R = s.R();  // level 0's: the particles near the open boundaries are coarse
    s.scheme().open_samples(c, open_.facet_points(), p.get(field::OpenRole{}), open_.facet_sums());
    open_.update_facets(open_.last_dt(), s.comm());
    with_eos<D>(s.scene(), [&](auto eos) { open_.apply_state(eos, s.scene().rho0, s.scene().c0, p, s.owned()); });
    s.domain().halos_stale();
  }
  void after_evaluation(StepState<D>& s) override { open_.zero_rates(s.particles(), s.owned()); }
  void shifted(StepState<D>& s, const ShiftedState<D>& v) override {
    open_.keep_buffers(s.particles(), v.first, v.end, v.x, v.u, v.rho);
  }
  void step_end(StepState<D>&, double dt) override { open_.set_last_dt(dt); }
  void save(const Communicator&, CheckpointHeader& h) const override { h.open = open_.save(); }

 private:
  OpenBoundaries<D> open_;
};

}  // namespace ondine
