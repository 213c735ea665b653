#pragma once
// A liquid wedge driven at U into a plane wall (reference.type: wedge_impact; thesis §5.6.2.1):
// with no gravity the flow is self-similar in s = U (t - t0), so the wall pressure is
// rho U^2 P(eta) with eta the distance along the wall from the contact point over s, and the
// wall's force per unit width is C_F rho U^2 s, C_F the integral of P. P comes from
// scripts/wedge_similarity.py (potential flow, the similarity solution; docs/validation.md).
#include <map>
#include <string>
#include <vector>

#include "reference/SensorSeries.hpp"

namespace ondine::reference {

// The similarity profile (eta, P) of a CSV file with the columns eta and pressure ('#'
// comments); throws std::runtime_error naming the file and line when it is not one (eta not
// increasing from 0, fewer than two rows).
Series read_wedge_profile(const std::string& path);

// The mean of the piecewise-linear profile over eta in [a, b] (0 beyond its last row); its
// value at a when b = a (a point sensor).
double profile_mean(const Series& profile, double a, double b);

// C_F: the profile's integral over eta (trapezoid rule).
double profile_force_coefficient(const Series& profile);

// One wall sensor's face along the wall: its centre's distance from the contact point and its
// size (m).
struct WedgeSensorFace {
  double centre, size;
};

// One output instant of the run: the time, the wall's force along its inward normal (N/m), and
// each face's pressure (Pa).
struct WedgeInstant {
  double t, force;
  std::vector<double> pressure;
};

// The run against the similarity solution, over the instants with s = U (t - t0) in
// [length / 2, length] (each face against the profile's mean over its own span in eta at that s):
// (an instant whose faces all lie beyond the wetted wall, max_j P_j <= 0, is left out)
//   pressure_peak_ratio: the mean over the instants of max_j p_j / max_j P_j rho U^2, and
//     pressure_peak_relative_error = |pressure_peak_ratio - 1|;
//   pressure_peak_position_error: the mean of |y_peak - y_peak,ref| / s, y the faces' centres;
//   pressure_profile_error: the RMS of (p_j - P_j rho U^2) over the faces and instants, over the
//     mean of max_j P_j rho U^2;
//   force_coefficient: the mean of F / (rho U^2 s), and force_coefficient_error = |C_F,run / C_F - 1|;
// and force_before_contact: the mean of F / (rho U^2 * 1 m) over the instants before t0 (the
// wall pushed through an air gap; 0 in the potential flow).
std::map<std::string, double> wedge_impact_errors(const Series& profile, const std::vector<WedgeSensorFace>& faces,
                                                  const std::vector<WedgeInstant>& run, double U, double rho, double t0,
                                                  double length);

}  // namespace ondine::reference
