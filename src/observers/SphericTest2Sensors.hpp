#pragma once
// SPHERIC Test 2 (reference.type: spheric_test2): the series of its sensors P1, P3 and H2, H4
// (wave gauges) against the measured file (reference/SensorSeries.hpp). P1 and P3 are the
// wall sensors of those names where the case has them (WallSensorSeries), each probe of the
// same name then compared too, as P1_probe and P3_probe; otherwise the probes (ProbeSeries).
#include <algorithm>

#include "observers/Observer.hpp"
#include "observers/WallSensorSeries.hpp"
#include "reference/SensorSeries.hpp"

namespace ondine {

template <int D>
class SphericTest2Sensors : public Observer<D> {
 public:
  explicit SphericTest2Sensors(const Scene& scene)
      : file_(scene.reference.file), length_(scene.reference.length), duration_(scene.duration) {
    for (const char* p : {"P1", "P3"}) {
      const auto w = std::find_if(scene.wall_sensors.begin(), scene.wall_sensors.end(), [&](const WallSensor& s) { return s.name == p; });
      const auto q = std::find_if(scene.probes.begin(), scene.probes.end(), [&](const Probe& s) { return s.name == p; });
      const std::string probe_key = w != scene.wall_sensors.end() ? std::string(p) + "_probe" : std::string(p);
      if (w != scene.wall_sensors.end())
        sources_.push_back({p, WallSensorSeries<D>::posted_name(p), "wall_sensors.csv",
                            2 + static_cast<std::size_t>(w - scene.wall_sensors.begin())});
      if (q != scene.probes.end())
        sources_.push_back({probe_key, p, "probes.csv", 2 + static_cast<std::size_t>(q - scene.probes.begin()) * (2 + D)});  // pressure
    }
    for (std::size_t k = 0; k < scene.wave_gauges.size(); ++k)
      for (const char* h : {"H2", "H4"})
        if (scene.wave_gauges[k].name == h) sources_.push_back({h, h, "waves.csv", 2 + k});
  }

  void record(OutputInstant<D>& now) override {
    for (const Source& s : sources_) {
      const auto v = now.posted.find(s.posted);
      if (v != now.posted.end()) sensors_[s.key].emplace_back(now.sim.time(), v->second);
    }
  }

  void resume(double, ResumedRows& rows) override {
    for (const Source& s : sources_)
      for (const auto& row : rows[s.file])
        if (row.size() > s.column) sensors_[s.key].emplace_back(row[0], row[s.column]);
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (end.diverged) return;
    const auto measured = reference::read_sensor_csv(file_, {"P1", "P3", "H2", "H4"});
    for (const auto& [k, v] : reference::spheric_test2_errors(measured, sensors_, length_, duration_)) errors[k] = v;
    // the probes beside the wall sensors: the same figures, named P1_probe_..., P3_probe_...
    std::map<std::string, reference::Series> probes;
    for (const char* p : {"P1", "P3"}) {
      const auto s = sensors_.find(std::string(p) + "_probe");
      if (s != sensors_.end()) probes[p] = s->second;
    }
    if (probes.empty()) return;
    for (const auto& [k, v] : reference::spheric_test2_errors(measured, probes, length_, duration_))
      errors[k.substr(0, 2) + "_probe" + k.substr(2)] = v;
  }

 private:
  struct Source {
    std::string key;     // the series' name in the comparison (P1, P1_probe, H2, ...)
    std::string posted;  // what its observer posts
    std::string file;    // its CSV (a restart reads it back)
    std::size_t column;
  };
  std::vector<Source> sources_;
  std::string file_;
  double length_, duration_;
  std::map<std::string, reference::Series> sensors_;  // (t, value)
};

}  // namespace ondine
