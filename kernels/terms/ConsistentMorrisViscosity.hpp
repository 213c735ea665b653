#pragma once
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/PairData.hpp"
namespace ondine::term {
// The Morris Laplacian (2.31) with the direction-dependent weight s_i(x_ij) of
// kernels/ConsistentLaplacian.hpp, exact for linear and quadratic fields:
// nu w_j (rho_i + rho_j)/rho_i W'(r)/r s_i(x_ij) u_ij. Chosen for viscous scenes with
// no-slip NFM walls (src/solver/FluxDispatch.hpp); the weights (A_i, b_i) come from
// DensityGradientPass. Not antisymmetric: momentum is conserved to the consistency error.
template <int D>
struct ConsistentMorrisViscosity {
  static constexpr const char* name = "consistent_morris_viscosity";
  static ConsistentMorrisViscosity from(const PassContext<D>& c) { return ConsistentMorrisViscosity{c.nu_pair, c.weights}; }
  double nu;
  LaplacianWeightView<D> weights;
  // forced inline: GCC kept it a call per pair (19 % of the refined cylinder's profile)
  KOKKOS_FORCEINLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    const double f = nu * q.omega_j * (q.rho_i + q.rho_j) * q.inv_rho_i * q.dWdr / q.r *
                     LaplacianBasis<D>::weight(weights, q.i, q.xij);
    s.du += f * (q.u_i - q.u_j);
  }
};
}  // namespace ondine::term
