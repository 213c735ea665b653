#pragma once
// A checkpoint's rows and the state checksums (solver/Measures.hpp).
#include <algorithm>
#include <map>
#include <string>

#include "kernels/StateHash.hpp"
#include "solver/CheckpointFields.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
StateRows state_rows(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  StateRows out;
  Kokkos::View<int*, MemSpace> index("ondine::Checkpoint::index", n_own);
  Kokkos::parallel_for("ondine::Checkpoint::index", Kokkos::RangePolicy<ExecSpace>(0, n_own), Iota32{index});
  auto take = [&](auto tag) {
    using V = field_view_t<decltype(tag), D>;
    const int w = exchange::width_of<V>();
    exchange::Rows dev("ondine::Checkpoint::rows", n_own, w);
    exchange::PackRows<V, D> f{p.get(tag), index, Kokkos::View<int*, MemSpace>(), dev, 0, {}};
    Kokkos::parallel_for("ondine::Checkpoint::pack", Kokkos::RangePolicy<ExecSpace>(0, n_own), f);
    std::vector<double> rows(static_cast<std::size_t>(n_own) * w);
    Kokkos::deep_copy(Kokkos::View<double**, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(rows.data(), n_own, w), dev);
    out[decltype(tag)::label] = {std::move(rows), w};
  };
  for_each_checkpoint_field(p, sim.refinement_on(), take);
  return out;
}

template <int D>
CheckpointRefinement refinement_state(const Simulation<D>& sim) {
  CheckpointRefinement c;
  if (!sim.refinement_on()) return c;
  sim.refinement().save_state(c);
  c.guard_shifts = sim.comm().sum(sim.refinement().guard_shifts());  // a global count (each rank counts its own)
  c.guards_limited = sim.comm().sum(sim.refinement().guards_limited());
  for (const std::int64_t n : sim.level_steps()) c.level_steps.push_back(static_cast<double>(n));
  for (const double w : sim.level_particle_steps()) c.level_particle_steps.push_back(sim.comm().sum(w));
  c.checksum = refinement_checksum(sim);
  return c;
}

template <int D>
std::uint64_t refinement_checksum(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  if (!sim.refinement_on()) return 0;
  unsigned long long h = 0;
  Kokkos::parallel_reduce("ondine::AprStateHash", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                          AprStateHash<D>{p.get(field::GlobalId{}), p.get(field::AprBirthLevel{}), p.get(field::AprLevel{}),
                                          p.get(field::AprGuard{}), p.get(field::AprMother{}), p.get(field::AprParent{})},
                          h);
  return sim.comm().sum_u64(static_cast<std::uint64_t>(h));
}

template <int D>
std::uint64_t state_checksum(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  unsigned long long h = 0;
  Kokkos::parallel_reduce("ondine::StateHash", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                          StateHash<D>{p.get(field::Position{}), p.get(field::Velocity{}), p.get(field::Density{}),
                                       p.get(field::Mass{}), p.get(field::GlobalId{})},
                          h);
  return sim.comm().sum_u64(static_cast<std::uint64_t>(h));
}

// the checksum of each field a checkpoint carries beyond the state and the APR fields (those
// have theirs), by label
template <int D>
std::map<std::string, std::uint64_t> field_checksums(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  Kokkos::View<int*, MemSpace> index("ondine::Checkpoint::index", n_own);
  Kokkos::parallel_for("ondine::Checkpoint::index", Kokkos::RangePolicy<ExecSpace>(0, n_own), Iota32{index});
  const std::vector<std::string>& base = checkpoint_fields();
  const std::vector<std::string>& apr = checkpoint_refinement_fields();
  std::map<std::string, std::uint64_t> out;
  auto take = [&](auto tag) {
    using Tag = decltype(tag);
    const std::string label = Tag::label;
    if (std::find(base.begin(), base.end(), label) != base.end() || std::find(apr.begin(), apr.end(), label) != apr.end()) return;
    using V = field_view_t<Tag, D>;
    exchange::Rows dev("ondine::Checkpoint::rows", n_own, exchange::width_of<V>());
    Kokkos::parallel_for("ondine::Checkpoint::pack", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                         exchange::PackRows<V, D>{p.get(tag), index, Kokkos::View<int*, MemSpace>(), dev, 0, {}});
    std::uint64_t salt = 0xcbf29ce484222325ULL;  // FNV-1a of the label
    for (const char ch : label) salt = (salt ^ static_cast<unsigned char>(ch)) * 0x100000001b3ULL;
    unsigned long long f = 0;
    Kokkos::parallel_reduce("ondine::FieldRowsHash", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                            FieldRowsHash<D>{dev, p.get(field::GlobalId{}), salt}, f);
    out[label] = sim.comm().sum_u64(static_cast<std::uint64_t>(f));
  };
  for_each_checkpoint_field(p, sim.refinement_on(), take);
  return out;
}

}  // namespace ondine
