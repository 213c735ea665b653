#pragma once
// Quadrature factor of the Morris Laplacian on the particle lattice (host, once per run).
// The discrete operator L(f)_i = sum_j w_j 2 W'(r)/r (f_i - f_j) (2.31) is exact for
// quadratic fields only as far as its discrete second moment is: for f = |x - x_i|^2,
// L(f)_i = -2 sum_j w_j W'(r) r, against 2 D exactly (the continuous integral gives 2 D by
// parts). On the initial Cartesian lattice at a fixed R/dx the sum misses by a fixed
// amount (Wendland C2, 2D: -0.26 % at R/dx = 3, -0.08 % at R/dx = 4), which caps the
// convergence of every viscous flow at that relative error (Poiseuille at L/25..L/100:
// docs/validation.md). The Morris term is scaled by
//   kappa = D / (-sum_{lattice j != i} dx^D W'(r_j) r_j),
// a constant, so the pair term stays antisymmetric and momentum is conserved exactly.
// The lattice sum is over offsets (not particles): (2 ceil(R/dx) + 1)^D terms.
#include <cmath>

namespace ondine {

template <int D, class Kernel>
double morris_lattice_factor(const Kernel& W, double R, double dx) {
  const int n = static_cast<int>(std::ceil(R / dx));
  double moment = 0.0;
  const int nz = D == 3 ? n : 0;
  int k[3];
  for (k[2] = -nz; k[2] <= nz; ++k[2])
    for (k[1] = -n; k[1] <= n; ++k[1])
      for (k[0] = -n; k[0] <= n; ++k[0]) {
        double r2 = 0.0;
        for (int a = 0; a < D; ++a) r2 += (k[a] * dx) * (k[a] * dx);
        if (r2 == 0.0 || r2 >= R * R) continue;
        const double r = std::sqrt(r2);
        moment -= std::pow(dx, D) * W.derivative(r) * r;
      }
  return D / moment;
}

}  // namespace ondine
