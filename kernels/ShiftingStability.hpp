#pragma once
// Linear stability of the particle shift (2.109)-(2.110) on the particle lattice (host, once
// per run). A shift x_i += -c R^2 grad C_i applied at every step acts on a small displacement
// field dx_j = a e^{i k.x_j} of the lattice as
//   dx_i <- (I - c R^2 M(k)) dx_i,   M(k) = sum_{j != i} w_j H(x_ij) (1 - cos(k.x_ij)),
// H the Hessian of W (the linearised grad C of (2.110), without the anti-clumping part). The
// shift damps every mode only while c R^2 lambda_max < 2, lambda_max the largest eigenvalue of
// M over the Brillouin zone; beyond, the fastest mode grows by |1 - c R^2 lambda_max| per step.
// The thesis' c = 0.5 is beyond: Wendland C2 in 2D at R/dx = 3, lambda_max = 1.19 / dx^2, a
// gain of -4.4 per step (round-off grows to 1e-4 dx in about 60 steps, where it saturates).
// c = 1 / (lambda_max R^2) damps the fastest mode in one step, and every other mode
// monotonically (gain in [0, 1)).
#include <algorithm>
#include <cmath>
#include <vector>

namespace ondine {

namespace shifting_detail {

// the largest eigenvalue of a symmetric D x D matrix (D = 2: closed form; D = 3: the
// trigonometric form of the cubic's roots, Smith 1961)
template <int D>
double largest_eigenvalue(const double m[3][3]) {
  if constexpr (D == 2) {
    const double h = 0.5 * (m[0][0] + m[1][1]), d = 0.5 * (m[0][0] - m[1][1]);
    return h + std::sqrt(d * d + m[0][1] * m[0][1]);
  } else {
    const double p1 = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
    const double q = (m[0][0] + m[1][1] + m[2][2]) / 3.0;
    const double p2 = (m[0][0] - q) * (m[0][0] - q) + (m[1][1] - q) * (m[1][1] - q) + (m[2][2] - q) * (m[2][2] - q) + 2.0 * p1;
    const double p = std::sqrt(p2 / 6.0);
    if (p == 0.0) return q;
    double b[3][3];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) b[a][c] = (m[a][c] - (a == c ? q : 0.0)) / p;
    const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                       b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
    const double r = std::clamp(det / 2.0, -1.0, 1.0);
    return q + 2.0 * p * std::cos(std::acos(r) / 3.0);
  }
}

}  // namespace shifting_detail

// lambda_max R^2 of the lattice of spacing dx for the kernel W of radius R, over a grid of
// `samples` wavenumbers per axis in [0, pi / dx] (M(k) is even in each component)
template <int D, class Kernel>
double shifting_mode_rate(const Kernel& W, double R, double dx, int samples = 33) {
  const int n = static_cast<int>(std::ceil(R / dx));
  const double w = std::pow(dx, D);
  const double h = 1e-6 * R;  // W'' by a centred difference of W'
  struct Offset {
    double x[3], H[3][3];
  };
  std::vector<Offset> offsets;
  const int nz = D == 3 ? n : 0;
  int k[3];
  for (k[2] = -nz; k[2] <= nz; ++k[2])
    for (k[1] = -n; k[1] <= n; ++k[1])
      for (k[0] = -n; k[0] <= n; ++k[0]) {
        Offset o{};
        double r2 = 0.0;
        for (int a = 0; a < D; ++a) {
          o.x[a] = k[a] * dx;
          r2 += o.x[a] * o.x[a];
        }
        if (r2 == 0.0 || r2 >= R * R) continue;
        const double r = std::sqrt(r2);
        const double d1 = W.derivative(r);
        const double d2 = (W.derivative(std::min(r + h, R)) - W.derivative(r - h)) / (std::min(r + h, R) - (r - h));
        // H = W'' e e^T + (W' / r) (I - e e^T)
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) {
            const double ee = o.x[a] * o.x[b] / r2;
            o.H[a][b] = d2 * ee + (d1 / r) * ((a == b ? 1.0 : 0.0) - ee);
          }
        offsets.push_back(o);
      }
  const double pi = std::acos(-1.0);
  double lambda = 0.0;
  const int sz = D == 3 ? samples : 1;
  int s[3];
  for (s[2] = 0; s[2] < sz; ++s[2])
    for (s[1] = 0; s[1] < samples; ++s[1])
      for (s[0] = 0; s[0] < samples; ++s[0]) {
        double kv[3] = {0, 0, 0};
        for (int a = 0; a < D; ++a) kv[a] = pi / dx * s[a] / (samples - 1);
        double m[3][3] = {};
        for (const Offset& o : offsets) {
          double phase = 0.0;
          for (int a = 0; a < D; ++a) phase += kv[a] * o.x[a];
          const double f = w * (1.0 - std::cos(phase));
          for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b) m[a][b] += f * o.H[a][b];
        }
        lambda = std::max(lambda, shifting_detail::largest_eigenvalue<D>(m));
      }
  return lambda * R * R;
}

}  // namespace ondine
