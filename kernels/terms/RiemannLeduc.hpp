#pragma once
// Riemann-SPH of Leduc et al. (no mass flux; thesis 2.90-2.101, with NFM walls 4.26-4.29):
//   drho_i/dt = -2 rho_i w_j (u_E n_ij - u_i) . grad_i W_ij       (from d(w_i)/dt of 2.92, d(w rho)/dt = 0)
//   du_i/dt  += -(2/rho_i) w_j P_E grad_i W_ij                       (2.97)
// with (u_E, P_E) the linearised (acoustic) Riemann solution (2.100) along n_ij = (x_j - x_i)/r
// between the states of i and j at the pair's midpoint, reconstructed by MUSCL (2.78) from the
// renormalised gradients of DensityGradientPass and limited pair by pair (2.81)-(2.83) (see
// muscl_midpoint). P_E and u_E n_ij are symmetric in the pair, so momentum is conserved to
// round-off; the masses are constant, so mass is exactly.
#include "kernels/Fields.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/Math.hpp"
#include "kernels/PairData.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallPressure.hpp"

namespace ondine {

// The value of phi_i reconstructed towards the midpoint of (i, j), phi_i + grad_i . (x_mid - x_i)
// (2.78), limited pair by pair as printed (2.81)-(2.83): theta = grad_i . (x_mid - x_i) / (phi_j -
// phi_i), phi_i^ = phi_i + minmod(1, theta) (phi_j - phi_i), minmod(1, theta) = max(0, min(1,
// theta)). The state lies between phi_i and phi_j (no new extremum); a linear field gives theta =
// 1/2, the exact midpoint value, from either side. Across a jump both states may reach the other
// side's value. A bound of 1/2 instead (the states never cross) was tried and is worse: on smooth
// fields theta scatters about 1/2, so that bound clips one side of half the pairs, and the bias
// made still water sink onto the floor of the 2D tank (pressure L-inf 0.063 at 6 s against 0.007
// with (2.83) as printed; docs/design.md).
KOKKOS_INLINE_FUNCTION double muscl_midpoint(double phi_i, double phi_j, double slope_half) {
  const double jump = phi_j - phi_i;
  if (jump == 0.0) return phi_i;
  const double theta = slope_half / jump;
  return phi_i + (theta < 0.0 ? 0.0 : theta > 1.0 ? 1.0 : theta) * jump;
}

// The acoustic Riemann solver (2.100), one-dimensional along n_ij: left state i, right state j,
// velocities projected on n_ij (pointing from i to j). Returns (u_E, P_E).
struct AcousticRiemann {
  double u, P;
};
KOKKOS_INLINE_FUNCTION AcousticRiemann acoustic_riemann(double Z_L, double U_L, double P_L, double Z_R, double U_R,
                                                        double P_R) {
  const double inv = 1.0 / (Z_L + Z_R);
  return {(Z_L * U_L + Z_R * U_R + P_L - P_R) * inv, (Z_R * P_L + Z_L * P_R + Z_L * Z_R * (U_L - U_R)) * inv};
}

// The low-dissipation variant of Zhang, Hu & Adams (2017, J. Comput. Phys. 335): the
// pressure's dissipation Z_L Z_R (U_L - U_R) / (Z_L + Z_R) of (2.100) becomes
// (1/2) rho_bar beta (U_L - U_R), beta = min(eta max(U_L - U_R, 0), c_bar): none where the pair
// separates, proportional to the approach speed where it closes (eta = 3 in that paper). u_E
// keeps (2.100). Not in the seed; scheme.riemann.dissipation: low.
KOKKOS_INLINE_FUNCTION AcousticRiemann low_dissipation_riemann(double rho_L, double c_L, double U_L, double P_L, double rho_R,
                                                               double c_R, double U_R, double P_R, double eta) {
  const double Z_L = rho_L * c_L, Z_R = rho_R * c_R, inv = 1.0 / (Z_L + Z_R);
  const double dU = U_L - U_R, c_bar = 0.5 * (c_L + c_R);
  const double beta_raw = eta * (dU > 0.0 ? dU : 0.0);
  const double beta = beta_raw < c_bar ? beta_raw : c_bar;
  return {(Z_L * U_L + Z_R * U_R + P_L - P_R) * inv, (Z_R * P_L + Z_L * P_R) * inv + 0.25 * (rho_L + rho_R) * beta * dU};
}

namespace term {

// Muscl = false: first order (the particle states themselves, thesis 2.73-2.77 with constant states).
template <int D, bool Muscl>
struct RiemannLeduc {
  static constexpr const char* name = Muscl ? "riemann_leduc_muscl" : "riemann_leduc";
  static RiemannLeduc from(const PassContext<D>& c) {
    if constexpr (Muscl) return RiemannLeduc{c.eos, c.riemann_eta, c.grad_rho, c.grad_u};
    else return RiemannLeduc{c.eos, c.riemann_eta, {}, {}};
  }
  WallEos eos;  // c(rho) of (1.9); P(rho^) = P_i + c_i^2 (rho^ - rho_i), exact for the linear law
  double eta = 0;  // > 0: the low-dissipation pressure of Zhang et al. (low_dissipation_riemann)
  field_view_t<field::DensityGradient, D> grad_rho;  // Muscl only
  VelocityGradientRows<D> grad_u;                    // Muscl only

  // c (1.9) without pow for the usual Tait exponent 7 and the linear law (gamma 1)
  KOKKOS_INLINE_FUNCTION double sound_speed(double rho) const {
    if (eos.eos_gamma == 7.0) {
      const double x = rho / eos.rho0;
      return eos.c0 * (x * x * x);
    }
    if (eos.eos_gamma == 1.0) return eos.c0;
    return kmath::sqrt(eos.c2(rho));
  }

  // The pair's Riemann problem along n_ij: the states of i (L) and j (R) at the midpoint,
  // reconstructed by MUSCL with Muscl, and its solution (2.100) or the low-dissipation one
  struct Solution {
    Vec<D> n;                   // from i to j
    double rho_L, rho_R, P_L, P_R, c_L, c_R;
    Vec<D> u_L, u_R;
    AcousticRiemann E;          // u_E along n, P_E
  };
  KOKKOS_INLINE_FUNCTION Solution solve(const PairData<D>& q) const {
    Solution z;
    z.n = (-1.0 / q.r) * q.xij;
    z.rho_L = q.rho_i;
    z.rho_R = q.rho_j;
    z.u_L = q.u_i;
    z.u_R = q.u_j;
    if constexpr (Muscl) {
      // x_mid - x_i = -x_ij / 2, x_mid - x_j = +x_ij / 2
      double sr_i = 0.0, sr_j = 0.0;
      for (int b = 0; b < D; ++b) {
        sr_i -= 0.5 * grad_rho(q.i, b) * q.xij[b];
        sr_j += 0.5 * grad_rho(q.j, b) * q.xij[b];
      }
      z.rho_L = muscl_midpoint(q.rho_i, q.rho_j, sr_i);
      z.rho_R = muscl_midpoint(q.rho_j, q.rho_i, sr_j);
      for (int k = 0; k < D; ++k) {
        double su_i = 0.0, su_j = 0.0;
        for (int b = 0; b < D; ++b) {
          su_i -= 0.5 * grad_u(q.i, k, b) * q.xij[b];
          su_j += 0.5 * grad_u(q.j, k, b) * q.xij[b];
        }
        z.u_L[k] = muscl_midpoint(q.u_i[k], q.u_j[k], su_i);
        z.u_R[k] = muscl_midpoint(q.u_j[k], q.u_i[k], su_j);
      }
    }
    z.c_L = sound_speed(q.rho_i);
    z.c_R = sound_speed(q.rho_j);
    z.P_L = q.P_i + z.c_L * z.c_L * (z.rho_L - q.rho_i);
    z.P_R = q.P_j + z.c_R * z.c_R * (z.rho_R - q.rho_j);
    z.E = eta > 0.0 ? low_dissipation_riemann(z.rho_L, z.c_L, dot(z.u_L, z.n), z.P_L, z.rho_R, z.c_R, dot(z.u_R, z.n), z.P_R, eta)
                    : acoustic_riemann(z.rho_L * z.c_L, dot(z.u_L, z.n), z.P_L, z.rho_R * z.c_R, dot(z.u_R, z.n), z.P_R);
    return z;
  }

  KOKKOS_INLINE_FUNCTION void pair(const PairData<D>& q, FluxSum<D>& s) const {
    const Solution z = solve(q);
    s.du += (-2.0 * q.omega_j * z.E.P * q.inv_rho_i) * q.gradW;
    s.drho -= 2.0 * q.rho_i * q.omega_j * (z.E.u * dot(z.n, q.gradW) - dot(q.u_i, q.gradW));
  }
};

}  // namespace term
}  // namespace ondine
