#pragma once
// Device maths from Kokkos: Kokkos::Experimental in 3.4-3.6, Kokkos:: from 3.7 on.
#include <Kokkos_Core.hpp>

namespace ondine {
#if KOKKOS_VERSION >= 30700
namespace kmath = ::Kokkos;
#else
namespace kmath = ::Kokkos::Experimental;
#endif
}  // namespace ondine
