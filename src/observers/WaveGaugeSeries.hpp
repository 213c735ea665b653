#pragma once
// waves.csv: the free-surface elevation at each wave gauge (kernels/WaveGauge.hpp); posts each
// gauge's elevation as "NAME" for the observers after it.
#include "observers/SeriesObserver.hpp"

namespace ondine {

template <int D>
class WaveGaugeSeries : public SeriesObserver<D> {
  using SeriesObserver<D>::csv_;
 public:
  WaveGaugeSeries(const Scene& scene, const std::string& out_dir, bool writer)
      : SeriesObserver<D>(out_dir, "waves.csv", writer), gauges_(scene.wave_gauges) {
    csv_.text() << "time,step";
    for (const WaveGauge& g : gauges_) csv_.text() << "," << g.name << ".elevation";
    csv_.text() << "\n";
  }

  void record(OutputInstant<D>& now) override {
    const auto levels = wave_elevations(now.sim);
    std::ostringstream& row = this->row(now.sim);
    for (std::size_t k = 0; k < levels.size(); ++k) {
      now.posted[gauges_[k].name] = levels[k];
      row << "," << levels[k];
    }
    this->end_row();
  }

 private:
  std::vector<WaveGauge> gauges_;
};

}  // namespace ondine
