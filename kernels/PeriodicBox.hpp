#pragma once
// Domain box with optional periodicity per axis: minimum-image pair vectors and
// wrapping of positions. A periodic axis must be at least twice the cut-off long,
// so that at most one image of a particle lies within it.
#include "kernels/Fields.hpp"
#include "kernels/Math.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

template <int D>
struct PeriodicBox {
  double lo[D], len[D];
  bool periodic[D];

  // forced inline: GCC left it out of line in the pair loops (7 % of a refined run in the call)
  KOKKOS_FORCEINLINE_FUNCTION Vec<D> delta(const Vec<D>& a, const Vec<D>& b) const {
    Vec<D> d = a - b;
    for (int k = 0; k < D; ++k)
      if (periodic[k]) {
        if (d[k] > 0.5 * len[k]) d[k] -= len[k];
        else if (d[k] < -0.5 * len[k]) d[k] += len[k];
      }
    return d;
  }
  KOKKOS_INLINE_FUNCTION double wrap(double x, int k) const {
    if (!periodic[k]) return x;
    const double s = (x - lo[k]) / len[k];
    return x - kmath::floor(s) * len[k];
  }
};

template <int D, class V>
KOKKOS_INLINE_FUNCTION Vec<D> load(const V& v, int i) {
  Vec<D> r;
  for (int k = 0; k < D; ++k) r[k] = v(i, k);
  return r;
}
template <int D, class V>
KOKKOS_INLINE_FUNCTION void store(const V& v, int i, const Vec<D>& r) {
  for (int k = 0; k < D; ++k) v(i, k) = r[k];
}

}  // namespace ondine
