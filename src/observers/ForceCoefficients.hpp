#pragma once
// The cylinder's force coefficients (reference.type: cylinder): C_D, C_L amplitude and
// Strouhal number of the body's wall (reference.wall) from its force series, posted by
// WallForceSeries, against the literature (reference/ForceCoefficients.hpp). The drag is also
// split into its pressure part (the wall pressure of 4.14 integrated, 4.22's reaction) and its
// viscous part (4.85's), each averaged over the same lift periods: cd_pressure_mean,
// cd_viscous_mean.
#include <array>
#include <cmath>

#include "observers/Observer.hpp"
#include "observers/WallForceSeries.hpp"
#include "reference/ForceCoefficients.hpp"
#include "reference/References.hpp"

namespace ondine {

template <int D>
class ForceCoefficientObserver : public Observer<D> {
 public:
  explicit ForceCoefficientObserver(const Scene& scene)
      : body_(scene.reference.wall), U_(scene.reference.velocity), diameter_(scene.reference.length), rho0_(scene.rho0),
        from_(scene.reference.from), column_(WallForceSeries<D>::pressure_fx_column(scene, body_)) {}

  void record(OutputInstant<D>& now) override {
    const auto fx = now.posted.find(body_ + ".fx"), fy = now.posted.find(body_ + ".fy"), px = now.posted.find(body_ + ".pressure_fx");
    if (fx != now.posted.end() && fy != now.posted.end() && px != now.posted.end())
      force_.push_back({now.sim.time(), fx->second, fy->second, px->second});
  }

  void resume(double, ResumedRows& rows) override {
    for (const auto& row : rows["walls.csv"])
      if (row.size() >= column_ + 2 * D)
        force_.push_back({row[0], row[column_] + row[column_ + D], row[column_ + 1] + row[column_ + D + 1], row[column_]});
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (end.diverged) return;
    std::vector<double> t, fx, fy, px;
    for (const auto& r : force_) {
      t.push_back(r[0]);
      fx.push_back(r[1]);
      fy.push_back(r[2]);
      px.push_back(r[3]);
    }
    const auto c = reference::force_coefficients(t, fx, fy, diameter_, U_, rho0_, from_);
    // the pressure part over the same whole lift periods (the window is the lift's)
    const auto p = reference::force_coefficients(t, px, fy, diameter_, U_, rho0_, from_);
    errors["cd_mean"] = c.cd_mean;
    errors["cd_pressure_mean"] = p.cd_mean;
    errors["cd_viscous_mean"] = c.cd_mean - p.cd_mean;
    errors["cl_amplitude"] = c.cl_amplitude;
    errors["strouhal"] = c.strouhal;
    errors["shedding_periods"] = c.periods;
    errors["cd_error"] = std::abs(c.cd_mean / reference::kCylinderRe100Cd - 1);
    if (c.periods > 0) {
      errors["strouhal_error"] = std::abs(c.strouhal / reference::kCylinderRe100St - 1);
      errors["cl_amplitude_error"] = std::abs(c.cl_amplitude / reference::kCylinderRe100ClAmplitude - 1);
    }
  }

 private:
  std::string body_;
  double U_, diameter_, rho0_, from_;
  std::size_t column_;  // the body's pressure_fx in walls.csv
  std::vector<std::array<double, 4>> force_;  // (t, F_x, F_y, the pressure part of F_x) of the body's wall
};

}  // namespace ondine
