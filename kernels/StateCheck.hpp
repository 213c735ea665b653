#pragma once
// A cheap per-step guard: the first particle whose state is not finite or whose
// density left [rho_lo, rho_hi] (a blow-up in a weakly compressible run).
#include <climits>

#include "kernels/Math.hpp"
#include "kernels/PeriodicBox.hpp"

namespace ondine {

template <int D>
struct FirstBadParticle {
  using value_type = int;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  double rho_lo, rho_hi;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& first) const {
    bool bad = !(rho(i) >= rho_lo && rho(i) <= rho_hi);  // also catches NaN
    for (int k = 0; k < D; ++k) bad = bad || !kmath::isfinite(x(i, k)) || !kmath::isfinite(u(i, k));
    if (bad && i < first) first = i;
  }
};

}  // namespace ondine
