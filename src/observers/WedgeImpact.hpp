#pragma once
// A liquid wedge against a plane wall (reference.type: wedge_impact): the wall sensors along the
// wall (WallSensorSeries) and the wall's force (WallForceSeries) against the similarity solution
// (reference/WedgeImpact.hpp), over s = U (t - t0) from length / 2 to length.
#include <cmath>

#include "observers/Observer.hpp"
#include "observers/WallForceSeries.hpp"
#include "observers/WallSensorSeries.hpp"
#include "reference/WedgeImpact.hpp"

namespace ondine {

template <int D>
class WedgeImpactObserver : public Observer<D> {
 public:
  explicit WedgeImpactObserver(const Scene& scene)
      : file_(scene.reference.file), wall_(scene.reference.wall), U_(scene.reference.velocity), rho0_(scene.rho0),
        t0_(scene.reference.from), length_(scene.reference.length) {
    for (const WallSensor& w : scene.wall_sensors) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) d2 += (w.position[k] - scene.reference.origin[k]) * (w.position[k] - scene.reference.origin[k]);
      faces_.push_back({std::sqrt(d2), w.size});
      names_.push_back(WallSensorSeries<D>::posted_name(w.name));
    }
    for (int k = 0; k < 2; ++k) normal_[k] = scene.wall_sensors.front().normal[k];  // n_out: into the wall
    force_column_ = WallForceSeries<D>::pressure_fx_column(scene, wall_);
  }

  void record(OutputInstant<D>& now) override {
    const auto fx = now.posted.find(wall_ + ".fx"), fy = now.posted.find(wall_ + ".fy");
    if (fx == now.posted.end() || fy == now.posted.end()) return;
    reference::WedgeInstant r{now.sim.time(), fx->second * normal_[0] + fy->second * normal_[1], {}};
    for (const std::string& n : names_) {
      const auto p = now.posted.find(n);
      if (p == now.posted.end()) return;
      r.pressure.push_back(p->second);
    }
    run_.push_back(r);
  }

  void resume(double, ResumedRows& rows) override {
    const auto& forces = rows["walls.csv"];
    const auto& sensors = rows["wall_sensors.csv"];
    for (std::size_t i = 0; i < forces.size() && i < sensors.size(); ++i) {
      const auto& f = forces[i];
      if (f.size() < force_column_ + 2 * D || sensors[i].size() < 2 + names_.size()) continue;
      reference::WedgeInstant r{f[0], (f[force_column_] + f[force_column_ + D]) * normal_[0] +
                                          (f[force_column_ + 1] + f[force_column_ + D + 1]) * normal_[1], {}};
      for (std::size_t j = 0; j < names_.size(); ++j) r.pressure.push_back(sensors[i][2 + j]);
      run_.push_back(r);
    }
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (end.diverged) return;
    const auto profile = reference::read_wedge_profile(file_);
    for (const auto& [k, v] : reference::wedge_impact_errors(profile, faces_, run_, U_, rho0_, t0_, length_)) errors[k] = v;
  }

 private:
  std::string file_, wall_;
  double U_, rho0_, t0_, length_;
  double normal_[2] = {0, 0};
  std::size_t force_column_ = 2;  // the wall's pressure_fx in walls.csv
  std::vector<reference::WedgeSensorFace> faces_;
  std::vector<std::string> names_;
  std::vector<reference::WedgeInstant> run_;
};

}  // namespace ondine
