#pragma once
// Simulation<D>: open boundaries at a step start (kernels/OpenBoundary.hpp): the roles and
// the particles created and removed (OpenBoundaries::classify), then, on the lists of the
// new particle set, the fluid's state at each buffer particle's mirror point, the facets'
// reference states and the buffer particles' state. Included by SimulationImpl.hpp only.
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
  if (static_cast<int>(open_sample_.extent(0)) < n_own_)
    open_sample_ = decltype(open_sample_)("ondine::Open::sample", n_own_ + n_own_ / 8 + 16, D + 2);
  PassContext<D> c = pass_context(levels().front());
  c.end = n_own_;
  scheme_.open_samples(c, open_.planes(), p_.get(field::OpenRole{}), open_sample_);
  open_.update_references(open_sample_, p_, n_own_, open_.last_dt(), comm());
  with_eos<D>(scene_, [&](auto eos) { open_.apply_state(eos, scene_.rho0, scene_.c0, open_sample_, p_, n_own_); });
  domain_.halos_stale();
}

}  // namespace ondine
