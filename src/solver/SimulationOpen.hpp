#pragma once
// Simulation<D>: open boundaries at a step start (kernels/OpenBoundary.hpp): the roles and
// the particles created and removed (OpenBoundaries::classify), then, on the lists of the
// new particle set, the fluid's state at each facet's sample point, the facets' filtered
// invariants and the buffer particles' state. Included by SimulationImpl.hpp only.
#include "solver/KernelDispatch.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
void Simulation<D>::open_classify() {
  bool changed = false;
  n_own_ = open_.classify(p_, n_own_, comm(), changed, apr_on_ ? &apr_.id_counter() : nullptr);
  if (!changed) return;
  domain_.invalidate_lists();  // on every rank: particles were created or removed
  if (apr_on_) bookkeeping_due_ = true;  // the new particles sorted by level and role
}

template <int D>
void Simulation<D>::open_buffer_state() {
  ensure_neighbours();
  domain_.refresh_state_halos(p_);
  if (!comm().serial()) domain_.refresh(p_, field::OpenRole{});
  const int n_all = static_cast<int>(p_.size());
  with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), n_all); });
  PassContext<D> c = pass_context(levels().front());
  c.end = n_own_;
  c.R = R_;  // level 0's: the particles near the open boundaries are coarse
  scheme_.open_samples(c, open_.facet_points(), p_.get(field::OpenRole{}), open_.facet_sums());
  open_.update_facets(open_.last_dt(), comm());
  with_eos<D>(scene_, [&](auto eos) { open_.apply_state(eos, scene_.rho0, scene_.c0, p_, n_own_); });
  domain_.halos_stale();
}

}  // namespace ondine
