#pragma once
// The log-law wall function on NFM no-slip walls (V&I §4.1.1; turbulence.wall_function): the
// no-slip term (4.85) with its estimate of the wall shear stress nu (u_i - u_q) / |d_n| replaced
// by the law's u_*^2 along the tangential slip t = (u_i - u_q)_t / |(u_i - u_q)_t|:
//   du_i += -2 u_*,i^2 t s_q W_iq,
// u_*,i the particle's friction velocity (kernels/turbulence/EddyViscosityPass.hpp). In the
// linear sublayer u_*^2 = nu u_t / y and the term is (4.85)'s tangential part.
#include "kernels/PassContext.hpp"
#include "kernels/wall/WallPointData.hpp"

namespace ondine::wall {

template <int D>
struct WallFunction {
  static constexpr const char* name = "wall_function";
  static WallFunction from(const PassContext<D>& c) { return WallFunction{c.wall.no_slip, c.u_star}; }
  Kokkos::View<int*, MemSpace> no_slip;  // per wall point: 1 no-slip, 0 slip
  field_view_t<field::FrictionVelocity, D> u_star;
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    if (!no_slip(w.q)) return;
    const Vec<D> rel = p.ui - w.uq;
    const Vec<D> ut = rel - dot(rel, w.n) * w.n;
    const double mag = kmath::sqrt(norm2(ut));
    if (!(mag > 0.0)) return;
    const double us = u_star(p.i);
    s.du -= (2.0 * us * us * w.Wq / mag) * ut;
  }
};

}  // namespace ondine::wall
