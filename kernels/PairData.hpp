#pragma once
// What every flux term sees of a pair (i, j) within the support: geometry, the
// kernel gradient grad_i W_ij (points from i to j) and the fields that all
// weakly-compressible schemes read. A term needing more holds its own Views.
#include "kernels/Vec.hpp"

namespace ondine {

template <int D>
struct PairData {
  int i, j;
  Vec<D> xij;      // x_i - x_j (minimum image)
  double r;        // |x_ij| > 0
  double dWdr;     // W'(r) <= 0
  Vec<D> gradW;    // grad_i W_ij = W'(r) x_ij / r
  double rho_i, rho_j, inv_rho_i;
  double P_i, P_j;
  double omega_j;  // m_j / rho_j
  Vec<D> u_i, u_j;
  // read only by the half-list pass (kernels/SymmetricFluxPass.hpp), which fills them
  double omega_i, inv_rho_j;
};

// Per-particle accumulator of the flux pass: du/dt and drho/dt, and dm/dt for the terms with
// mass fluxes (Vila's Riemann-SPH in ALE form).
template <int D>
struct FluxSum {
  Vec<D> du;
  double drho;
  double dm = 0.0;
};

}  // namespace ondine
