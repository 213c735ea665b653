#pragma once
// Maxima read by the time-step limits (Simulation<D>::time_step):
// dt = min(CFL_a R / c_max (2.102), CFL_nu R^2 / nu (2.103), CFL_f sqrt(R / |a|_max) [V&I 11]).
#include "kernels/Fields.hpp"
#include "kernels/PeriodicBox.hpp"

namespace ondine {

// c_max = max_i c(rho_i), c from the equation of state (1.9), for (2.102); with Kokkos::Max.
template <int D, class Eos>
struct MaxSoundSpeed {
  using value_type = double;
  Eos eos;
  field_view_t<field::Density, D> rho;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mx) const {
    const double c = eos.sound_speed(rho(i));
    if (c > mx) mx = c;
  }
};

// max_i |v_i|^2 of a vector field (|a|_max^2 for [V&I 11]); with Kokkos::Max.
template <int D, class VectorView>
struct MaxNorm2 {
  using value_type = double;
  VectorView v;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mx) const {
    const double a2 = norm2(load<D>(v, i));
    if (a2 > mx) mx = a2;
  }
};

}  // namespace ondine

namespace ondine {
// max_i v(i, k)
template <int D>
struct MaxComponent {
  using value_type = double;
  field_view_t<field::Position, D> v;
  int k;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mx) const {
    if (v(i, k) > mx) mx = v(i, k);
  }
};
}  // namespace ondine

namespace ondine {
// max_i v(i) of a scalar field (the eddy viscosity's bound on the step)
template <class ScalarView>
struct MaxValue {
  using value_type = double;
  ScalarView v;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double& mx) const {
    if (v(i) > mx) mx = v(i);
  }
};
}  // namespace ondine
