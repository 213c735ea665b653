#pragma once
// Compile-time composition of flux terms: a term the scene does not use is
// absent from the pack, so the pair loop carries no branch for it. A pack whose every term
// has pair_both (both sides of a pair from one evaluation) can run on the half neighbour list
// (kernels/SymmetricFluxPass.hpp).
#include <string>
#include <type_traits>
#include <utility>

#include "kernels/PairData.hpp"

namespace ondine {

namespace detail {
template <class T, int D, class = void>
struct HasPairBoth : std::false_type {};
template <class T, int D>
struct HasPairBoth<T, D,
                   std::void_t<decltype(std::declval<const T&>().pair_both(std::declval<const PairData<D>&>(),
                                                                          std::declval<FluxSum<D>&>(),
                                                                          std::declval<FluxSum<D>&>()))>>
    : std::true_type {};
}  // namespace detail

template <class... T>
struct Terms : T... {
  Terms() = default;
  explicit Terms(const T&... t) : T(t)... {}
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    (T::pair(q, s), ...);
  }
  // every term antisymmetric enough to be evaluated once per pair
  template <int D>
  static constexpr bool symmetric = (detail::HasPairBoth<T, D>::value && ...);
  template <int D>
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    (T::pair_both(q, si, sj), ...);
  }
  static std::string names() {
    std::string n;
    ((n += (n.empty() ? "" : "+") + std::string(T::name)), ...);
    return n;
  }
};

}  // namespace ondine
