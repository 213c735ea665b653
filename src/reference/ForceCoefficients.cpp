#include "reference/ForceCoefficients.hpp"

#include <cmath>
#include <complex>

namespace ondine::reference {

namespace {

// int_{t0}^{t1} g(t) e^{-2 pi i f t} dt over the samples (trapezoids; linear between samples
// at the window's ends), with g = y / q - mean
std::complex<double> fourier(const std::vector<double>& t, const std::vector<double>& y, double q, double mean, double f, double t0,
                             double t1) {
  std::complex<double> acc = 0;
  const double w = 2 * M_PI * f;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double ta = std::max(t[k - 1], t0), tb = std::min(t[k], t1);
    if (tb <= ta) continue;
    const double h = t[k] - t[k - 1];
    const double ga = (y[k - 1] + (y[k] - y[k - 1]) * (ta - t[k - 1]) / h) / q - mean;
    const double gb = (y[k - 1] + (y[k] - y[k - 1]) * (tb - t[k - 1]) / h) / q - mean;
    acc += 0.5 * (ga * std::polar(1.0, -w * ta) + gb * std::polar(1.0, -w * tb)) * (tb - ta);
  }
  return acc;
}

// the mean of y / q over [t0, t1] (trapezoids)
double mean_of(const std::vector<double>& t, const std::vector<double>& y, double q, double t0, double t1) {
  const std::complex<double> s = fourier(t, y, q, 0.0, 0.0, t0, t1);
  return t1 > t0 ? s.real() / (t1 - t0) : 0.0;
}

}  // namespace

ForceCoefficients force_coefficients(const std::vector<double>& t, const std::vector<double>& fx, const std::vector<double>& fy,
                                     double D, double U, double rho, double from) {
  ForceCoefficients c;
  const double q = 0.5 * rho * U * U * D;
  if (t.size() < 2 || q <= 0 || t.back() <= from) return c;
  double t0 = std::max(from, t.front());
  const double t1 = t.back();
  c.cd_mean = mean_of(t, fx, q, t0, t1);
  c.cl_mean = mean_of(t, fy, q, t0, t1);
  // the lift's frequency: the periodogram's peak for St in [0.05, 0.5], on a grid, then refined
  auto power = [&](double f) { return std::norm(fourier(t, fy, q, c.cl_mean, f, t0, t1)); };
  const double f_lo = 0.05 * U / D, f_hi = 0.5 * U / D;
  const int grid = 400;
  double best_f = f_lo, best = -1;
  for (int k = 0; k <= grid; ++k) {
    const double f = f_lo + (f_hi - f_lo) * k / grid;
    const double p = power(f);
    if (p > best) {
      best = p;
      best_f = f;
    }
  }
  double a = best_f - (f_hi - f_lo) / grid, b = best_f + (f_hi - f_lo) / grid;
  for (int it = 0; it < 60; ++it) {  // golden-section search of the peak
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    const double m1 = b - g * (b - a), m2 = a + g * (b - a);
    if (power(m1) > power(m2)) b = m2;
    else a = m1;
  }
  const double f = 0.5 * (a + b);
  c.periods = static_cast<int>(std::floor((t1 - t0) * f));
  if (c.periods < 2) {  // too short a window for a frequency
    c.periods = 0;
    return c;
  }
  // whole periods ending at the last sample: the means, and the lift's amplitude as that of its
  // fundamental (the acoustic noise of a weakly compressible run, at higher frequencies, drops out)
  t0 = t1 - c.periods / f;
  c.strouhal = f * D / U;
  c.cd_mean = mean_of(t, fx, q, t0, t1);
  c.cl_mean = mean_of(t, fy, q, t0, t1);
  c.cl_amplitude = 2.0 * std::abs(fourier(t, fy, q, c.cl_mean, f, t0, t1)) / (t1 - t0);
  if (c.cl_amplitude < 1e-3) {  // no shedding: a steady wake
    c.periods = 0;
    c.strouhal = c.cl_amplitude = 0;
    c.cd_mean = mean_of(t, fx, q, std::max(from, t.front()), t1);
    c.cl_mean = mean_of(t, fy, q, std::max(from, t.front()), t1);
  }
  return c;
}

}  // namespace ondine::reference
