#include "reference/WedgeImpact.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace ondine::reference {

Series read_wedge_profile(const std::string& path) {
  if (!std::ifstream(path)) throw std::runtime_error("cannot open the similarity profile '" + path + "'");
  const auto columns = read_sensor_csv(path, {"pressure"});
  const auto found = columns.find("pressure");
  const Series p = found != columns.end() ? found->second : Series{};
  if (p.size() < 2) throw std::runtime_error(path + ": expected at least two rows of (eta, pressure)");
  if (p.front().first != 0.0) throw std::runtime_error(path + ": expected the first row at eta = 0 (the contact point)");
  for (std::size_t k = 1; k < p.size(); ++k)
    if (!(p[k].first > p[k - 1].first))
      throw std::runtime_error(path + ": expected eta increasing, row " + std::to_string(k + 1) + " of the data is not");
  return p;
}

namespace {

// the integral of the piecewise-linear profile over [0, b]
double profile_integral_to(const Series& p, double b) {
  double sum = 0;
  for (std::size_t k = 1; k < p.size() && p[k - 1].first < b; ++k) {
    const double x0 = p[k - 1].first, x1 = std::min(p[k].first, b);
    const double y0 = p[k - 1].second, y1 = y0 + (p[k].second - y0) * (x1 - x0) / (p[k].first - x0);
    sum += 0.5 * (y0 + y1) * (x1 - x0);
  }
  return sum;
}

// the piecewise-linear profile at x (0 beyond its last row and below eta = 0)
double profile_at(const Series& p, double x) {
  if (x < p.front().first || x > p.back().first) return 0.0;
  std::size_t k = 1;
  while (k + 1 < p.size() && p[k].first < x) ++k;
  return p[k - 1].second + (p[k].second - p[k - 1].second) * (x - p[k - 1].first) / (p[k].first - p[k - 1].first);
}

}  // namespace

double profile_mean(const Series& profile, double a, double b) {
  if (!(b - a > 1e-12)) return profile_at(profile, a);  // a point sensor
  return (profile_integral_to(profile, std::max(b, 0.0)) - profile_integral_to(profile, std::max(a, 0.0))) / (b - a);
}

double profile_force_coefficient(const Series& profile) { return profile_integral_to(profile, profile.back().first); }

std::map<std::string, double> wedge_impact_errors(const Series& profile, const std::vector<WedgeSensorFace>& faces,
                                                  const std::vector<WedgeInstant>& run, double U, double rho, double t0,
                                                  double length) {
  const double P0 = rho * U * U, cf = profile_force_coefficient(profile);
  double ratio = 0, position = 0, squares = 0, peaks = 0, force = 0, before = 0;
  int n = 0, nb = 0, samples = 0;
  for (const WedgeInstant& r : run) {
    const double s = U * (r.t - t0);
    if (s <= 0) {
      before += r.force / (P0 * 1.0);
      ++nb;
      continue;
    }
    if (s < 0.5 * length - 1e-12 || s > length + 1e-12) continue;
    std::size_t jr = 0, js = 0;
    double ref_max = -1e300;
    std::vector<double> ref(faces.size());
    for (std::size_t j = 0; j < faces.size(); ++j) {
      ref[j] = P0 * profile_mean(profile, (faces[j].centre - 0.5 * faces[j].size) / s, (faces[j].centre + 0.5 * faces[j].size) / s);
      if (ref[j] > ref_max) ref_max = ref[j], jr = j;
      if (r.pressure[j] > r.pressure[js]) js = j;
    }
    if (!(ref_max > 0)) continue;  // every face beyond the wetted wall: no peak to compare
    for (std::size_t j = 0; j < faces.size(); ++j) squares += (r.pressure[j] - ref[j]) * (r.pressure[j] - ref[j]);
    samples += static_cast<int>(faces.size());
    ratio += r.pressure[js] / ref_max;
    peaks += ref_max;
    position += std::abs(faces[js].centre - faces[jr].centre) / s;
    force += r.force / (P0 * s);
    ++n;
  }
  std::map<std::string, double> e;
  if (nb > 0) e["force_before_contact"] = before / nb;
  if (n == 0) return e;
  e["pressure_peak_ratio"] = ratio / n;
  e["pressure_peak_relative_error"] = std::abs(ratio / n - 1);
  e["pressure_peak_position_error"] = position / n;
  e["pressure_profile_error"] = std::sqrt(squares / samples) / (peaks / n);
  e["force_coefficient"] = force / n;
  e["force_coefficient_error"] = std::abs(force / n / cf - 1);
  return e;
}

}  // namespace ondine::reference
