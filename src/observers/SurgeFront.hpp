#pragma once
// front.csv: the dam-break surge front Z = (x_front - x_0) / a against Martin & Moyce's
// measurements in T = t sqrt(2 g / a) (reference.type: martin_moyce), and its errors.
#include <cmath>

#include "io/CsvSeries.hpp"
#include "observers/Observer.hpp"
#include "reference/References.hpp"

namespace ondine {

template <int D>
class SurgeFront : public Observer<D> {
 public:
  SurgeFront(const Scene& scene, const std::string& out_dir, bool writer)
      : a_(scene.reference.length), x0_(scene.reference.origin[0]),
        time_scale_(std::sqrt(2 * std::abs(scene.gravity[1]) / scene.reference.length)), csv_(out_dir + "/front.csv", writer) {
    csv_.text().precision(8);
    csv_.text() << "T,Z,Z_experiment\n";
  }

  void record(OutputInstant<D>& now) override {
    const double T = now.sim.time() * time_scale_;
    const double Z = (front_position(now.sim) - x0_) / a_;
    points_.emplace_back(T, Z);
    csv_.text() << T << "," << Z << "," << reference::interpolate(reference::martin_moyce_front(), T) << "\n";
    csv_.flush();
  }

  void resume(double t_start, ResumedRows&) override {
    if (csv_.resume(t_start * time_scale_))
      for (const auto& row : csv_.resumed_rows())
        if (row.size() >= 2) points_.emplace_back(row[0], row[1]);
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (end.diverged) return;
    for (const auto& [k, v] : reference::martin_moyce_errors(points_)) errors[k] = v;
  }

 private:
  double a_, x0_, time_scale_;
  CsvSeries csv_;
  std::vector<std::pair<double, double>> points_;  // (T, Z)
};

}  // namespace ondine
