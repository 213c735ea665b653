#pragma once
// Compile-time composition of flux terms: a term the scene does not use is
// absent from the pack, so the pair loop carries no branch for it.
#include <string>

#include "kernels/PairData.hpp"

namespace ondine {

template <class... T>
struct Terms : T... {
  Terms() = default;
  explicit Terms(const T&... t) : T(t)... {}
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    (T::pair(q, s), ...);
  }
  static std::string names() {
    std::string n;
    ((n += (n.empty() ? "" : "+") + std::string(T::name)), ...);
    return n;
  }
};

}  // namespace ondine
