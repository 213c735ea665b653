#pragma once
#include "kernels/Fields.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/PairData.hpp"
#include "kernels/PeriodicBox.hpp"
namespace ondine::term {
// delta-SPH density diffusion (Antuono et al.; thesis 2.60, 2.63):
//   + delta c0 R w_j Psi_ij . grad_i W_ij,
//   Psi_ij = 2 (rho_j - rho_i) (x_j - x_i)/|x_ij|^2 - (<grad rho>_i + <grad rho>_j),
// with the renormalised gradients of DensityGradientPass; or, with scheme.delta_sph_form:
// hydrostatic (Fourtakas et al. 2019, Comput. Fluids 190: 346-361), from the density less its
// hydrostatic part, the EOS's first order about rho0 (rho0 g / c0^2, within 1 % of the Tait
// difference for g R / c0^2 < 0.01):
//   Psi_ij = 2 (rho_j - rho_i - rho0 g.(x_j - x_i) / c0^2) (x_j - x_i)/|x_ij|^2,
// which vanishes in hydrostatic equilibrium at a free surface as well (the renormalised
// gradients' term does not where the support is cut).
template <int D>
struct DeltaSphDiffusion {
  static constexpr const char* name = "delta_sph";
  static DeltaSphDiffusion from(const PassContext<D>& c) {
    return DeltaSphDiffusion{c.delta_coeff, c.grad_rho, c.delta_hydrostatic, c.rho_hydrostatic};
  }
  double coeff;  // delta c0 R
  field_view_t<field::DensityGradient, D> grad_rho;
  bool hydrostatic;
  Vec<D> rho_h;  // rho0 g / c0^2
  KOKKOS_INLINE_FUNCTION double psi_dot_gradW(const PairData<D>& q) const {
    const double r2 = q.r * q.r;
    double psi_dot = 0.0;
    if (hydrostatic) {
      // x_ij = x_i - x_j: rho0 g.(x_j - x_i) / c0^2 = -rho_h . x_ij
      const double dynamic = (q.rho_j - q.rho_i) + dot(rho_h, q.xij);
      for (int k = 0; k < D; ++k) psi_dot += -2.0 * dynamic * q.xij[k] / r2 * q.gradW[k];
      return psi_dot;
    }
    for (int k = 0; k < D; ++k) {
      const double psi = -2.0 * (q.rho_j - q.rho_i) * q.xij[k] / r2 - (grad_rho(q.i, k) + grad_rho(q.j, k));
      psi_dot += psi * q.gradW[k];
    }
    return psi_dot;
  }
  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    s.drho += coeff * q.omega_j * psi_dot_gradW(q);
  }
  // both sides: Psi_ji = Psi_ij and grad_j W_ji = -grad_i W_ij
  KOKKOS_INLINE_FUNCTION void pair_both(const PairData<D>& q, FluxSum<D>& si, FluxSum<D>& sj) const {
    const double f = coeff * psi_dot_gradW(q);
    si.drho += q.omega_j * f;
    sj.drho -= q.omega_i * f;
  }
};
}  // namespace ondine::term
