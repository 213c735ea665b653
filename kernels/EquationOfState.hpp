#pragma once
// Equations of state: Tait (thesis 1.8, [V&I 10]) and linear (thesis 6.5).
#include "kernels/Fields.hpp"
#include "kernels/Math.hpp"

namespace ondine {

// p_b is a constant background pressure added to the law: it leaves the continuum
// pressure gradient unchanged but keeps P > 0 in flows without a free surface,
// which removes the tensile instability of G+ (Adami et al. 2013; thesis 2.105
// is the special case p_b = P_min(t)).
struct TaitEos {
  double rho0, c0, gamma, p_b;
  KOKKOS_INLINE_FUNCTION double pressure(double rho) const {
    return rho0 * c0 * c0 / gamma * (kmath::pow(rho / rho0, gamma) - 1.0) + p_b;
  }
  // (1.9): c = c0 (rho/rho0)^((gamma-1)/2)
  KOKKOS_INLINE_FUNCTION double sound_speed(double rho) const {
    return c0 * kmath::pow(rho / rho0, 0.5 * (gamma - 1.0));
  }
  // the inverse of pressure(), for p above the law's floor p_b - rho0 c0^2 / gamma (clamped at
  // 1e-3 rho0 below it: a tension the law cannot give)
  KOKKOS_INLINE_FUNCTION double density(double p) const {
    const double q = 1.0 + gamma * (p - p_b) / (rho0 * c0 * c0);
    return rho0 * kmath::pow(q > 1e-21 ? q : 1e-21, 1.0 / gamma);
  }
};

struct LinearEos {
  double rho0, c0, p_b;
  KOKKOS_INLINE_FUNCTION double pressure(double rho) const { return c0 * c0 * (rho - rho0) + p_b; }
  KOKKOS_INLINE_FUNCTION double sound_speed(double) const { return c0; }
  KOKKOS_INLINE_FUNCTION double density(double p) const { return rho0 + (p - p_b) / (c0 * c0); }
};

// P_i = EOS(rho_i) for all particles.
template <int D, class Eos>
void update_pressure(const Eos& eos, const field_view_t<field::Density, D>& rho,
                     const field_view_t<field::Pressure, D>& P, int n) {
  Kokkos::parallel_for("ondine::EquationOfState", Kokkos::RangePolicy<ExecSpace>(0, n),
                       KOKKOS_LAMBDA(const int i) { P(i) = eos.pressure(rho(i)); });
}

}  // namespace ondine
