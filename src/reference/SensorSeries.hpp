#pragma once
// Measured time series of sensors (pressure probes, wave gauges) and the errors of a run's
// series against them: the first impact's peak and its time on a pressure sensor, and the
// RMS difference of a level over a time window. Used by reference.type spheric_test2
// (Kleefsman et al. 2005; cases/reference/spheric_test2_kleefsman2005.csv).
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ondine::reference {

using Series = std::vector<std::pair<double, double>>;  // (t, value)

// The columns of a CSV file ('#' comments; a header line of names, the first column the
// time in s), by name. Throws std::runtime_error naming the file and line when it cannot
// be read, or when a name in `wanted` is missing.
std::map<std::string, Series> read_sensor_csv(const std::string& path, const std::vector<std::string>& wanted);

// SPHERIC Test 2 errors of a run's sensors (P1, P3: pressure in Pa; H2, H4: water level in
// m) against the measured ones, over 0 <= t <= t_end:
//   P1_peak_relative_error, P3_peak_relative_error: |max_sim - max_exp| / max_exp over the
//     first impact (t <= 0.8 s); P1_peak_time_error, P3_peak_time_error: |t_sim - t_exp| (s);
//   P1_impulse_relative_error, P3_...: |I_sim - I_exp| / I_exp, I the integral of P over
//     0.35-0.60 s (trapezoid rule, the ends interpolated; only when the run reaches 0.60 s);
//   P1_rms_error, P3_rms_error: the RMS of P_sim(t) - P_exp(t) at the run's output times in
//     0.3-2 s, over the measured first-impact peak;
//   H2_rms_error, H4_rms_error: the RMS of H_sim(t) - H_exp(t) at the run's output times,
//     over `height` (the water column's height).
std::map<std::string, double> spheric_test2_errors(const std::map<std::string, Series>& measured,
                                                   const std::map<std::string, Series>& simulated, double height, double t_end);

}  // namespace ondine::reference
