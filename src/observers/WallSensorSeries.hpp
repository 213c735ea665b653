#pragma once
// wall_sensors.csv: the pressure of each wall sensor (wall_sensors:), the NFM wall state's
// pressure P_f (4.30)-(4.32) averaged over the sensor's face (solver/measures/WallLoads.hpp);
// posts each as "wall_sensor:NAME" for the observers after it.
#include "observers/SeriesObserver.hpp"

namespace ondine {

template <int D>
class WallSensorSeries : public SeriesObserver<D> {
  using SeriesObserver<D>::csv_;
 public:
  WallSensorSeries(const Scene& scene, const std::string& out_dir, bool writer)
      : SeriesObserver<D>(out_dir, "wall_sensors.csv", writer), sensors_(scene.wall_sensors) {
    csv_.text() << "time,step";
    for (const WallSensor& w : sensors_) csv_.text() << "," << w.name << ".pressure";
    csv_.text() << "\n";
  }

  static std::string posted_name(const std::string& sensor) { return "wall_sensor:" + sensor; }

  void record(OutputInstant<D>& now) override {
    const std::vector<double> p = wall_sensor_pressures(now.sim);
    std::ostringstream& row = this->row(now.sim);
    for (std::size_t k = 0; k < p.size(); ++k) {
      now.posted[posted_name(sensors_[k].name)] = p[k];
      row << "," << p[k];
    }
    this->end_row();
  }

 private:
  std::vector<WallSensor> sensors_;
};

}  // namespace ondine
