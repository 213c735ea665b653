#include "reference/References.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ondine::reference {

double poiseuille_startup(double y, double t, double L, double F, double nu) {
  double u = F / (2 * nu) * y * (L - y);
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    const double term = 4 * F * L * L / (nu * M_PI * M_PI * M_PI * k * k * k) * std::sin(M_PI * y * k / L) *
                        std::exp(-k * k * M_PI * M_PI * nu * t / (L * L));
    u -= term;
    if (std::abs(term) < 1e-16 * (1 + std::abs(u))) break;
  }
  return u;
}

double duct_startup(double y, double z, double t, double L, double F, double nu) {
  double u = F / (2 * nu) * y * (L - y);
  for (int n = 1; n < 400; n += 2) {
    // cosh(a) / cosh(b) as exp(|a| - b) (1 + exp(-2|a|)) / (1 + exp(-2b)): no overflow for large n
    const double a = std::abs(n * M_PI * (z - 0.5 * L) / L), b = n * M_PI / 2;
    const double ratio = std::exp(a - b) * (1 + std::exp(-2 * a)) / (1 + std::exp(-2 * b));
    const double term = 4 * F * L * L / (nu * M_PI * M_PI * M_PI * n * n * n) * std::sin(n * M_PI * y / L) * ratio;
    u -= term;
    if (4 * F * L * L / (nu * M_PI * M_PI * M_PI * n * n * n) * ratio < 1e-16 * (1 + std::abs(u)) && n > 20) break;
  }
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double decay = std::exp(-(m * m + n * n) * M_PI * M_PI * nu * t / (L * L));
      if (decay < 1e-18) break;  // smaller still for larger n
      u -= 16 * F * L * L / (nu * std::pow(M_PI, 4) * m * n * (m * m + n * n)) * std::sin(m * M_PI * y / L) *
           std::sin(n * M_PI * z / L) * decay;
    }
  return u;
}

double couette_startup(double y, double t, double L, double V0, double nu) {
  double u = V0 * y / L;
  // the n-th term is bounded by 2 V0 / (n pi) exp(-n^2 pi^2 nu t / L^2): stop once that bound is
  // below 1e-16 V0 (at t = 0 the series is the Fourier series of -V0 y / L and converges only
  // like 1/n: 20000 terms leave 3e-5 V0 inside the gap)
  for (int n = 1; n <= 20000; ++n) {
    const double decay = std::exp(-n * n * M_PI * M_PI * nu * t / (L * L));
    const double bound = 2 / (n * M_PI) * decay;
    u += (n % 2 ? -1.0 : 1.0) * bound * V0 * std::sin(n * M_PI * y / L);
    if (bound < 1e-16) break;
  }
  return u;
}

const std::vector<std::pair<double, double>>& martin_moyce_front() {
  static const std::vector<std::pair<double, double>> data = {
      {0.0, 1.0},   {0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67}, {1.63, 1.89}, {1.83, 2.11},
      {1.98, 2.33}, {2.20, 2.56}, {2.32, 2.78}, {2.51, 3.00}, {2.65, 3.22}, {2.83, 3.44}, {2.98, 3.67}};
  return data;
}

namespace {
double ls_slope(const std::vector<std::pair<double, double>>& s, double lo, double hi, int& m) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  m = 0;
  for (const auto& [x, y] : s)
    if (x >= lo && x <= hi + 1e-9) {
      sx += x; sy += y; sxx += x * x; sxy += x * y;
      ++m;
    }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}
}  // namespace

double polygon_area(const std::vector<std::array<double, 2>>& points) {
  double a = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& p = points[k];
    const auto& q = points[(k + 1) % points.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::abs(a);
}

std::map<std::string, double> martin_moyce_errors(const std::vector<std::pair<double, double>>& front) {
  std::map<std::string, double> e;
  double worst = 0;
  int samples = 0;
  for (const auto& [T, Z] : front) {
    if (T > 3.0 + 1e-9 || T < 0.3) continue;
    const double Ze = interpolate(martin_moyce_front(), T);
    worst = std::max(worst, std::abs(Z - Ze) / Ze);
    ++samples;
  }
  if (samples > 0) e["front_max_relative_error"] = worst;
  int m = 0, me = 0;
  const double slope = ls_slope(front, 1.5, 3.0, m);
  const double se = ls_slope(martin_moyce_front(), 1.5, 3.0, me);
  if (m >= 3) {
    e["front_speed"] = slope;
    e["front_speed_relative_error"] = std::abs(slope - se) / se;
  }
  return e;
}

std::vector<std::vector<double>> read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open reference data " + path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream ls(line);
    std::vector<double> row;
    for (double v; ls >> v;) row.push_back(v);
    if (!row.empty() && ls.eof()) rows.push_back(row);  // the header line does not parse
  }
  return rows;
}

double front_relative_difference(const std::vector<std::pair<double, double>>& front,
                                 const std::vector<std::pair<double, double>>& contrast) {
  if (contrast.empty()) return NAN;
  double worst = 0;
  for (const auto& [T, Z] : front)
    if (T >= 0.3 && T <= 3) {
      const double Zc = interpolate(contrast, T);
      worst = std::max(worst, std::abs(Z - Zc) / Zc);
    }
  return worst;
}

double interpolate(const std::vector<std::pair<double, double>>& s, double x) {
  if (x <= s.front().first) return s.front().second;
  if (x >= s.back().first) return s.back().second;
  for (std::size_t k = 1; k < s.size(); ++k)
    if (x <= s[k].first) {
      const double w = (x - s[k - 1].first) / (s[k].first - s[k - 1].first);
      return (1 - w) * s[k - 1].second + w * s[k].second;
    }
  return s.back().second;
}

}  // namespace ondine::reference
