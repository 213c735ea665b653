#include "reference/SensorSeries.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "reference/References.hpp"

namespace ondine::reference {

std::map<std::string, Series> read_sensor_csv(const std::string& path, const std::vector<std::string>& wanted) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open the measured series '" + path + "'");
  std::vector<std::string> names;
  std::map<std::string, Series> out;
  std::string line;
  for (int ln = 1; std::getline(in, line); ++ln) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream ls(line);
    if (names.empty()) {  // the header
      for (std::string n; ls >> n;) names.push_back(n);
      for (const std::string& w : wanted)
        if (std::find(names.begin(), names.end(), w) == names.end())
          throw std::runtime_error(path + ":" + std::to_string(ln) + ": no column '" + w + "' in the header");
      continue;
    }
    std::vector<double> v;
    for (double x; ls >> x;) v.push_back(x);
    if (v.size() != names.size())
      throw std::runtime_error(path + ":" + std::to_string(ln) + ": expected " + std::to_string(names.size()) + " numbers, got " +
                               std::to_string(v.size()));
    for (std::size_t k = 1; k < names.size(); ++k) out[names[k]].emplace_back(v[0], v[k]);
  }
  if (names.empty()) throw std::runtime_error(path + ": no header line");
  return out;
}

namespace {

// the largest value over t <= t_max and its time
std::pair<double, double> peak(const Series& s, double t_max) {
  std::pair<double, double> best{0.0, -1e300};
  for (const auto& [t, v] : s)
    if (t <= t_max && v > best.second) best = {t, v};
  return best;
}

// the integral of s over [a, b]: the trapezoid rule on its samples, the ends interpolated
double integral(const Series& s, double a, double b) {
  double I = 0, tp = a, vp = interpolate(s, a);
  for (const auto& [t, v] : s) {
    if (t <= a) continue;
    if (t >= b) break;
    I += 0.5 * (v + vp) * (t - tp);
    tp = t;
    vp = v;
  }
  return I + 0.5 * (interpolate(s, b) + vp) * (b - tp);
}

}  // namespace

std::map<std::string, double> spheric_test2_errors(const std::map<std::string, Series>& measured,
                                                   const std::map<std::string, Series>& simulated, double height, double t_end) {
  std::map<std::string, double> e;
  constexpr double first_impact = 0.8;  // s: the water reaches the box at about 0.4 s
  constexpr double impulse_from = 0.35, impulse_to = 0.60;  // s: the first impact's impulse
  constexpr double rms_from = 0.3, rms_to = 2.0;             // s: the pressure's RMS difference
  for (const char* p : {"P1", "P3"}) {
    const auto m = measured.find(p), s = simulated.find(p);
    if (m == measured.end() || s == simulated.end() || s->second.empty()) continue;
    const auto pm = peak(m->second, first_impact), ps = peak(s->second, first_impact);
    e[std::string(p) + "_peak_relative_error"] = std::abs(ps.second - pm.second) / pm.second;
    e[std::string(p) + "_peak_time_error"] = std::abs(ps.first - pm.first);
    if (t_end >= impulse_to && s->second.back().first >= impulse_to) {
      const double Im = integral(m->second, impulse_from, impulse_to), Is = integral(s->second, impulse_from, impulse_to);
      e[std::string(p) + "_impulse_relative_error"] = std::abs(Is - Im) / Im;
    }
    double sq = 0;
    int n = 0;
    for (const auto& [t, v] : s->second) {
      if (t < rms_from) continue;
      if (t > std::min(t_end, rms_to)) break;
      const double d = v - interpolate(m->second, t);
      sq += d * d;
      ++n;
    }
    if (n > 0) e[std::string(p) + "_rms_error"] = std::sqrt(sq / n) / pm.second;
  }
  for (const char* h : {"H2", "H4"}) {
    const auto m = measured.find(h), s = simulated.find(h);
    if (m == measured.end() || s == simulated.end() || s->second.empty()) continue;
    double sq = 0;
    int n = 0;
    for (const auto& [t, v] : s->second) {
      if (t > t_end) break;
      const double d = v - interpolate(m->second, t);
      sq += d * d;
      ++n;
    }
    if (n > 0) e[std::string(h) + "_rms_error"] = std::sqrt(sq / n) / height;
  }
  return e;
}

}  // namespace ondine::reference
