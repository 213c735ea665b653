#pragma once
// The log law of the wall (V&I §4.1.1; the constants of docs/case-file.md "turbulence"):
//   smooth wall:  u_t / u_* = ln(y u_* / nu) / kappa + B    (B = 5.2), u_t / u_* = y u_* / nu below y+_c
//   rough wall:   u_t / u_* = ln(y / k_s) / kappa + B_r     (B_r = 8.5, Nikuradse)
// inverted for the friction velocity u_* from the tangential speed u_t at a distance y from the
// wall, as the seed does "for complex flows".
#include <Kokkos_Core.hpp>

#include "kernels/Math.hpp"

namespace ondine {

struct LogLaw {
  double kappa = 0.41, nu = 1e-6, B = 5.2;
  bool rough = false;
  double ks = 0, Br = 8.5;
  double yc = 11.06;  // y+_c: set by init()

  // the constants of a smooth (ks = 0) or rough wall, with y+_c solved
  static LogLaw make(double kappa, double nu, double B, double ks, double Br) {
    LogLaw l{kappa, nu, B, ks > 0, ks, Br};
    l.yc = l.crossover();
    return l;
  }

  // y+_c where the linear sublayer u+ = y+ meets the log law (11.06 for kappa 0.41, B 5.2)
  KOKKOS_INLINE_FUNCTION double crossover() const {
    double yp = 11.0;
    for (int k = 0; k < 50; ++k) {  // Newton on y+ - ln(y+)/kappa - B
      const double f = yp - kmath::log(yp) / kappa - B, df = 1.0 - 1.0 / (kappa * yp);
      yp -= f / df;
    }
    return yp;
  }

  // u_* of the law at distance y > 0 with tangential speed u_t >= 0
  KOKKOS_INLINE_FUNCTION double friction_velocity(const double ut, const double y) const {
    if (!(ut > 0.0)) return 0.0;
    if (rough) {  // a particle closer than k_s reads the law at k_s
      const double yr = y > ks ? y : ks;
      return ut / (kmath::log(yr / ks) / kappa + Br);
    }
    const double u_lam = kmath::sqrt(nu * ut / y);  // the linear sublayer
    if (y * u_lam / nu <= yc) return u_lam;
    // f(u) = u (ln(y u / nu) / kappa + B) - u_t: increasing and convex for y u / nu > e^(-1 - kappa B);
    // from u_lam (f < 0 there) Newton's first step lands above the root, then decreases to it
    double us = u_lam;
    for (int k = 0; k < 60; ++k) {
      const double lg = kmath::log(y * us / nu) / kappa + B;
      const double step = (us * lg - ut) / (lg + 1.0 / kappa);
      us -= step;
      if (kmath::fabs(step) <= 1e-14 * us) break;
    }
    return us;
  }

  // u_t of the law at distance y for friction velocity u_* (the inverse, for tests and references)
  KOKKOS_INLINE_FUNCTION double speed(const double us, const double y) const {
    if (rough) {
      const double yr = y > ks ? y : ks;
      return us * (kmath::log(yr / ks) / kappa + Br);
    }
    const double yp = y * us / nu;
    return yp <= yc ? us * yp : us * (kmath::log(yp) / kappa + B);
  }
};

}  // namespace ondine
