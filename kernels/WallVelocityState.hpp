#pragma once
// MUSCL state of the velocity at a wall point (thesis 4.30), for the normal flux (4.14), from
// the renormalised gradient <grad u>_i of kernels/VelocityGradientSum.hpp:
//   (u_f - u_q).n = (u_i - u_q).n + n . <grad u>_i (x_q - x_i)           (4.30)
// (4.30) reconstructs the whole state phi = (rho, rho u); without the velocity part the
// impedance term rho c u_f.n of (4.14) reads the velocity of a particle d ~ dx/2 from the
// wall as if it were on it. In a flow that stretches along a wall (the dam-break surge:
// du/dx > 0 on the floor, so dv/dy < 0) that velocity is -(du/dx) d, and rho c (du/dx) d is
// a spurious wall pressure proportional to c0 that holds the flow back. Measured on the
// dam break at 20 x 40 (docs/validation.md): the front at c0 = 1480 m/s lagged the c0 = 15
// m/s front by 4.7 %, 1.1 % at T = 3.15 with this reconstruction; at 50 x 100 it does not
// help (3.1 % with it in both runs, 2.81 % without).
//
// Limiter (not in the seed; the seed's 4.32 only bounds |u.n| by 0.1 c): minmod cannot use a
// state beyond the wall (the seed's remark), but the wall's own normal velocity is known,
// u_p.n = u_q.n (4.14), so the reconstructed (u_f - u_q).n is kept between 0 and the
// particle's (u_i - u_q).n: the reconstruction may only reduce the impedance term, never
// reverse or enlarge it. Unlimited, the dam break at c0 = 1480 m/s blew up (a front particle
// whose one-sided gradient reversed the sign of u_f.n was pulled into the floor).
// Opt-in (scheme.wall_velocity_reconstruction, off by default): measured variants in
// docs/validation.md (stability_dam_break_real_sound_speed). A free-surface test (first order
// where the fluid's Shepard sum is below 0.7 or 0.9 gamma_i, or faded out between 0.5 and 0.9)
// was tried and dropped: at 0.7 a surge-tip particle ran ahead at 20 x 40 (front speed 29 %
// off), at 0.9 and faded the c0 = 1480 lag came back (10.3 %, 10.6 % at 10 x 20). Without it,
// the violent impact at 40 per length leaves one spray particle 0.09 dx from the ceiling
// (wall_leaks 1), which is why the reconstruction is not the default.
#include "kernels/Math.hpp"
#include "kernels/VelocityGradientSum.hpp"

namespace ondine {

// (u_f - u_q).n at the wall point q (xiq = x_i - x_q), reconstructed by (4.30) and limited
// between 0 and (u_i - u_q).n (see the head of this file)
template <int D>
KOKKOS_INLINE_FUNCTION double wall_normal_velocity(const Mat<D>& grad_u, const Vec<D>& xiq, const Vec<D>& ui,
                                                   const Vec<D>& uq, const Vec<D>& n) {
  const double un_i = dot(ui - uq, n);
  double dun = 0.0;  // n . <grad u>_i (x_q - x_i)
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) dun -= n[a] * grad_u.a[a][b] * xiq[b];
  const double un_f = un_i + dun;
  return un_i > 0.0 ? kmath::fmax(0.0, kmath::fmin(un_f, un_i)) : kmath::fmin(0.0, kmath::fmax(un_f, un_i));
}

}  // namespace ondine
