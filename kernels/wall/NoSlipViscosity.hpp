#pragma once
// NFM no-slip wall term of the Laplacian (4.85): du_i += 2 nu s_q (u_i - u_q) / d_n W_iq,
// d_n = (x_i - x_q).n_out on the fluid side (at most -min_dn, kernels/WallPressure.hpp),
// at no-slip wall points only. Consistent: times the weight s_i(x_iq) of the Laplacian
// exact for linear and quadratic fields (kernels/ConsistentLaplacian.hpp), as the fluid
// pairs carry it.
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/wall/WallPointData.hpp"

namespace ondine::wall {

template <int D, bool Consistent>
struct NoSlipViscosity {
  static constexpr const char* name = Consistent ? "wall_no_slip_consistent" : "wall_no_slip";
  static NoSlipViscosity from(const PassContext<D>& c) { return NoSlipViscosity{c.nu, 0.05 * c.R, c.wall.no_slip, c.weights}; }
  double nu;
  double min_dn;                        // 0.05 R
  Kokkos::View<int*, MemSpace> no_slip;  // per wall point: 1 no-slip, 0 slip
  LaplacianWeightView<D> weights;       // (A_i, b_i) of the consistent Laplacian (Consistent only)
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    if (!no_slip(w.q)) return;
    double k = 2.0 * w.Wq / fluid_side_dn<D>(w.xiq, w.n, min_dn);
    if constexpr (Consistent) k *= LaplacianBasis<D>::weight(weights, p.i, w.xiq);
    s.du += (nu * k) * (p.ui - w.uq);
  }
};

}  // namespace ondine::wall

namespace ondine::wall {

// The same no-slip term with a turbulence model and no wall function: the particle's
// nu + nu_T,i in place of nu (the fluid pairs carry nu + nu_T on each side,
// kernels/terms/EddyMorrisViscosity.hpp).
template <int D>
struct EddyNoSlipViscosity {
  static constexpr const char* name = "wall_no_slip_eddy";
  static EddyNoSlipViscosity from(const PassContext<D>& c) { return EddyNoSlipViscosity{c.nu, 0.05 * c.R, c.wall.no_slip, c.nu_T}; }
  double nu;
  double min_dn;                        // 0.05 R
  Kokkos::View<int*, MemSpace> no_slip;  // per wall point: 1 no-slip, 0 slip
  field_view_t<field::EddyViscosity, D> nu_T;
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    if (!no_slip(w.q)) return;
    const double k = 2.0 * w.Wq / fluid_side_dn<D>(w.xiq, w.n, min_dn);
    s.du += ((nu + nu_T(p.i)) * k) * (p.ui - w.uq);
  }
};

}  // namespace ondine::wall
