#pragma once
// Particle and pair counts (solver/Measures.hpp).
#include "kernels/NeighbourLoops.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
std::int64_t global_size(const Simulation<D>& sim) {
  return sim.comm().sum(static_cast<std::int64_t>(sim.size()));
}

template <int D>
std::int64_t sph_particles(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  if (!sim.refinement_on()) return n_own;
  long g = 0;
  Kokkos::parallel_reduce("ondine::APR::count_guards", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                          apr::CountGuards{p.get(field::AprGuard{})}, g);
  return n_own - g;
}

template <int D>
std::int64_t pair_count(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  // pairs within R, both ways, from the current list (skin pairs excluded)
  if (!sim.domain().lists_valid()) return 0;
  if (sim.refinement_on()) return sim.comm().sum(static_cast<std::int64_t>(sim.refinement().symmetric_list().total()));  // L. pairs within R + skin
  const auto x = p.get(field::Position{});
  const auto list = sim.domain().list();
  const auto box = sim.domain().box();
  const double R2 = sim.R() * sim.R();
  std::int64_t total = 0;
  Kokkos::parallel_reduce("ondine::PairCount", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                          KOKKOS_LAMBDA(const int i, std::int64_t& acc) {
                            for_each_neighbour_within<D>(list, box, x, i, load<D>(x, i), R2,
                                                         [&](const int, const Vec<D>&, const double) { ++acc; });
                          },
                          total);
  return sim.comm().sum(total);
}

}  // namespace ondine
