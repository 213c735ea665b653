#pragma once
// Ids gathered from every rank, sorted, on the device: the rank-independent order in which
// new particles get their global ids (APR daughters, open-boundary particles), so that a run
// numbers its particles the same on any number of ranks.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/Fields.hpp"
#include "parallel/Communicator.hpp"

namespace ondine {

inline Kokkos::View<std::int64_t*, MemSpace> sorted_on_every_rank(const Kokkos::View<std::int64_t*, MemSpace>& local,
                                                                  const Communicator& comm, const std::string& label) {
  std::vector<std::int64_t> mine(local.extent(0));
  Kokkos::deep_copy(Kokkos::View<std::int64_t*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(mine.data(), mine.size()), local);
  std::vector<std::int64_t> all = comm.gather_all(mine);
  std::sort(all.begin(), all.end());
  Kokkos::View<std::int64_t*, MemSpace> out(label, all.size());
  Kokkos::deep_copy(out, Kokkos::View<const std::int64_t*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(all.data(), all.size()));
  return out;
}

}  // namespace ondine
