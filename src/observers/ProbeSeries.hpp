#pragma once
// probes.csv: at each probe (probes:) the Shepard-interpolated pressure, density and velocity
// (2.40-2.41); posts each probe's pressure as "NAME" for the observers after it.
#include "observers/SeriesObserver.hpp"

namespace ondine {

template <int D>
class ProbeSeries : public SeriesObserver<D> {
  using SeriesObserver<D>::csv_;
 public:
  ProbeSeries(const Scene& scene, const std::string& out_dir, bool writer)
      : SeriesObserver<D>(out_dir, "probes.csv", writer), probes_(scene.probes) {
    csv_.text() << "time,step";
    for (const Probe& p : probes_) {
      csv_.text() << "," << p.name << ".pressure," << p.name << ".density";
      for (int k = 0; k < D; ++k) csv_.text() << "," << p.name << ".u" << "xyz"[k];
    }
    csv_.text() << "\n";
  }

  void record(OutputInstant<D>& now) override {
    const auto samples = sample_probes(now.sim);
    std::ostringstream& row = this->row(now.sim);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      now.posted[probes_[k].name] = samples[k].pressure;
      row << "," << samples[k].pressure << "," << samples[k].density;
      for (int c = 0; c < D; ++c) row << "," << samples[k].velocity[c];
    }
    this->end_row();
  }

 private:
  std::vector<Probe> probes_;
};

}  // namespace ondine
