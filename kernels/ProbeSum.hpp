#pragma once
// Shepard interpolation at a probe x_p (thesis 2.40-2.41): the sums
//   sum_j w_j W(|x_p - x_j|) f_j,  w_j = m_j / rho_j,
// for f = 1 (the Shepard normalisation) and for each sampled field f; a sum
// reduction over all particles (probes are sampled at output times only).
#include "kernels/Fields.hpp"
#include "kernels/Math.hpp"
#include "kernels/PeriodicBox.hpp"

namespace ondine {

namespace probe_value {
struct One {
  KOKKOS_INLINE_FUNCTION double operator()(int) const { return 1.0; }
};
template <class View>
struct Scalar {  // f_j = v(j)
  View v;
  KOKKOS_INLINE_FUNCTION double operator()(int j) const { return v(j); }
};
template <class View>
struct Component {  // f_j = v(j, k)
  View v;
  int k;
  KOKKOS_INLINE_FUNCTION double operator()(int j) const { return v(j, k); }
};
}  // namespace probe_value

template <int D, class Kernel, class Value>
struct ProbeSum {
  using value_type = double;
  PeriodicBox<D> box;
  Kernel W;
  Vec<D> xp;
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  Value value;

  KOKKOS_INLINE_FUNCTION void operator()(const int j, double& a) const {
    const double r = kmath::sqrt(norm2(box.delta(xp, load<D>(x, j))));
    a += m(j) / rho(j) * W.value(r) * value(j);
  }
};

}  // namespace ondine
