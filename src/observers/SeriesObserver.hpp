#pragma once
// An observer that owns one CSV series (io/CsvSeries.hpp): its row starts with the time and
// the step; at a restart it takes back its rows and leaves them, under its file's name, for
// the observers after it.
#include "io/CsvSeries.hpp"
#include "observers/Observer.hpp"

namespace ondine {

template <int D>
class SeriesObserver : public Observer<D> {
 public:
  SeriesObserver(const std::string& out_dir, const std::string& file, bool writer) : file_(file), csv_(out_dir + "/" + file, writer) {}

  void resume(double t_start, ResumedRows& rows) override {
    csv_.resume(t_start);
    rows[file_] = csv_.resumed_rows();
  }

 protected:
  // the row's first columns: time, step
  std::ostringstream& row(const Simulation<D>& sim) {
    csv_.text() << sim.time() << "," << sim.steps();
    return csv_.text();
  }
  // the row's end; the file is rewritten
  void end_row() {
    csv_.text() << "\n";
    csv_.flush();
  }

  std::string file_;
  CsvSeries csv_;
};

}  // namespace ondine
