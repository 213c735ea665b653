#pragma once
// SPHERIC Test 2 (reference.type: spheric_test2): the series of its sensors P1, P3 (probes) and
// H2, H4 (wave gauges), posted by ProbeSeries and WaveGaugeSeries, against the measured file
// (reference/SensorSeries.hpp).
#include <algorithm>

#include "observers/Observer.hpp"
#include "reference/SensorSeries.hpp"

namespace ondine {

template <int D>
class SphericTest2Sensors : public Observer<D> {
 public:
  explicit SphericTest2Sensors(const Scene& scene)
      : file_(scene.reference.file), length_(scene.reference.length), duration_(scene.duration) {
    auto is_sensor = [&](const std::string& n) { return std::find(names_.begin(), names_.end(), n) != names_.end(); };
    for (std::size_t k = 0; k < scene.probes.size(); ++k)
      if (is_sensor(scene.probes[k].name)) probe_column_[scene.probes[k].name] = 2 + k * (2 + D);  // pressure
    for (std::size_t k = 0; k < scene.wave_gauges.size(); ++k)
      if (is_sensor(scene.wave_gauges[k].name)) gauge_column_[scene.wave_gauges[k].name] = 2 + k;
  }

  void record(OutputInstant<D>& now) override {
    for (const std::string& name : names_) {
      const auto v = now.posted.find(name);
      if (v != now.posted.end()) sensors_[name].emplace_back(now.sim.time(), v->second);
    }
  }

  void resume(double, ResumedRows& rows) override {
    auto take = [&](const std::map<std::string, std::size_t>& columns, const std::string& file) {
      for (const auto& row : rows[file])
        for (const auto& [name, c] : columns)
          if (row.size() > c) sensors_[name].emplace_back(row[0], row[c]);
    };
    take(probe_column_, "probes.csv");
    take(gauge_column_, "waves.csv");
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (end.diverged) return;
    const auto measured = reference::read_sensor_csv(file_, names_);
    for (const auto& [k, v] : reference::spheric_test2_errors(measured, sensors_, length_, duration_)) errors[k] = v;
  }

 private:
  const std::vector<std::string> names_ = {"P1", "P3", "H2", "H4"};  // the compared sensors (probes P, gauges H)
  std::string file_;
  double length_, duration_;
  std::map<std::string, std::size_t> probe_column_, gauge_column_;
  std::map<std::string, reference::Series> sensors_;  // (t, value)
};

}  // namespace ondine
