#pragma once
// The state check that stops a blown-up run.
#include <climits>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "kernels/StateCheck.hpp"
#include "parallel/Communicator.hpp"
#include "particles/HostRow.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// Thrown by Simulation::step() when the state blows up; the particles hold the last good
// state (the start of the failed step) when it is caught.
struct BlowUp : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Stops the run at the first step that produced a non-finite state or a density
// outside [0.5, 2] rho0, naming the step, time, particle and quantity; the state
// at the start of the step is put back so that the caller can write it.
template <int D>
void check_state(ParticleSet<D>& p, int n_own, const Scene& scene, const Communicator& comm, std::int64_t steps, double t,
                 double dt) {
  int first = INT_MAX;
  Kokkos::parallel_reduce("ondine::StateCheck", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                          FirstBadParticle<D>{p.get(field::Position{}), p.get(field::Velocity{}),
                                              p.get(field::Density{}), 0.5 * scene.rho0, 2.0 * scene.rho0},
                          Kokkos::Min<int>(first));
  // the lowest rank with a bad particle names it
  const std::int64_t bad_rank = comm.min(first == INT_MAX ? std::int64_t(comm.size()) : std::int64_t(comm.rank()));
  if (bad_rank == comm.size()) return;
  if (first == INT_MAX) first = 0;
  // what went wrong, read from the host for that one particle
  const auto x = row_to_host(p.get(field::Position{}), first);
  const auto u = row_to_host(p.get(field::Velocity{}), first);
  const auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.get(field::Density{}), first));
  const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.get(field::GlobalId{}), first));
  std::ostringstream m;
  m << "blow-up at step " << steps + 1 << ", t = " << t + dt << " s: particle " << id() << " (at";
  for (int k = 0; k < D; ++k) m << " " << x(k);
  m << ") has ";
  bool finite = std::isfinite(r());
  for (int k = 0; k < D; ++k) finite = finite && std::isfinite(x(k)) && std::isfinite(u(k));
  if (!finite) {
    m << "a non-finite state (density " << r() << ", velocity";
    for (int k = 0; k < D; ++k) m << " " << u(k);
    m << ")";
  } else {
    m << "density " << r() / scene.rho0 << " rho0, outside [0.5, 2] rho0";
  }
  Kokkos::deep_copy(p.get(field::Position{}), p.get(field::StagePosition{}));
  Kokkos::deep_copy(p.get(field::Velocity{}), p.get(field::StageVelocity{}));
  Kokkos::deep_copy(p.get(field::Density{}), p.get(field::StageDensity{}));
  if (p.has(field::MassRate{})) Kokkos::deep_copy(p.get(field::Mass{}), p.get(field::StageMass{}));
  throw BlowUp(comm.broadcast(m.str(), static_cast<int>(bad_rank)));
}

}  // namespace ondine
