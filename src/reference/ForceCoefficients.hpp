#pragma once
// The force coefficients of a body in a steady stream, from the series of the fluid's force
// on it: C_D = F_x / (1/2 rho U^2 D), C_L = F_y / (1/2 rho U^2 D) (per unit span in 2D), and
// the Strouhal number St = f D / U of the lift's oscillation (vortex shedding).
#include <vector>

namespace ondine::reference {

struct ForceCoefficients {
  double cd_mean = 0;       // over the whole lift periods ending at the last sample (over [from, end] without two)
  double cl_mean = 0;
  double cl_amplitude = 0;  // of the lift's fundamental (0 with fewer than two periods)
  double strouhal = 0;      // 0 with fewer than two periods
  int periods = 0;          // whole lift periods in [from, end] (0 with a lift amplitude below 1e-3: no shedding)
};

// t, fx, fy: the samples (t increasing); D the body's width across the stream, U the stream's
// speed, rho the density; the samples with t >= from count. The lift's frequency is the peak of
// its periodogram for 0.05 <= St <= 0.5; the means and the fundamental's amplitude are taken
// over the whole periods that end at the last sample. The acoustic noise of a weakly
// compressible run (frequencies of c0 / D) does not enter St or the amplitude, nor, over whole
// periods, much of the means.
ForceCoefficients force_coefficients(const std::vector<double>& t, const std::vector<double>& fx, const std::vector<double>& fy,
                                     double D, double U, double rho, double from);

// Published figures for the circular cylinder at Re = 100 (2D, laminar shedding), each with
// its source (docs/validation.md, "Cylinder at Re = 100"): the means of the values quoted
// there for the drag (Braza et al. 1986 1.364, Calhoun 2002 1.33, Ng et al. 2009 1.368,
// Marrone et al. 2013 1.36, Chiron 2017 uniform fine 1.345) and the Strouhal number (Marrone
// et al. 0.168, Chiron 0.1682), and Calhoun's lift amplitude 0.298.
constexpr double kCylinderRe100Cd = (1.364 + 1.33 + 1.368 + 1.36 + 1.345) / 5;
constexpr double kCylinderRe100St = (0.168 + 0.1682) / 2;
constexpr double kCylinderRe100ClAmplitude = 0.298;

}  // namespace ondine::reference
