#pragma once
// Gathers a field into a new order: out(i) = in(perm(i)), i < perm.extent(0).
// Used to reorder particles by cell for memory locality, and to drop particles
// (a shorter perm).
#include <string>

#include "kernels/Fields.hpp"

namespace ondine {

template <class V>
V permuted(const V& in, const Kokkos::View<int*, MemSpace>& perm) {
  const int n = static_cast<int>(perm.extent(0));
  V out(in.label(), n);
  if constexpr (V::rank == 1) {
    Kokkos::parallel_for("ondine::Reorder::gather", Kokkos::RangePolicy<ExecSpace>(0, n),
                         KOKKOS_LAMBDA(const int i) { out(i) = in(perm(i)); });
  } else {
    const int c = static_cast<int>(in.extent(1));
    Kokkos::parallel_for("ondine::Reorder::gather", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < c; ++k) out(i, k) = in(perm(i), k);
    });
  }
  return out;
}

}  // namespace ondine
