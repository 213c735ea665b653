#pragma once
// One particle's row of a per-particle [n][D] field, read on the host. A row of a device
// view is strided, and Kokkos cannot deep-copy a strided view between memory spaces
// ("no available copy mechanism" on CUDA): the row is gathered on the device first.
#include "kernels/Fields.hpp"

namespace ondine {

template <class V>
Kokkos::View<typename V::non_const_value_type*, Kokkos::LayoutRight, Kokkos::HostSpace> row_to_host(const V& v, const int i) {
  using T = typename V::non_const_value_type;
  const int n = static_cast<int>(v.extent(1));
  Kokkos::View<T*, Kokkos::LayoutRight, MemSpace> row("ondine::HostRow", n);
  Kokkos::parallel_for("ondine::HostRow", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int k) { row(k) = v(i, k); });
  Kokkos::View<T*, Kokkos::LayoutRight, Kokkos::HostSpace> h("ondine::HostRow::host", n);
  Kokkos::deep_copy(h, row);
  return h;
}

}  // namespace ondine
