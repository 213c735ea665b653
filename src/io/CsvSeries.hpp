#pragma once
// Text time series of a run (diagnostics, probes, walls, front) kept in memory and
// rewritten whole through a temporary name at each output; a restarted run first
// takes back the rows of the earlier run up to the restart time.
#include <sstream>
#include <string>
#include <vector>

namespace ondine {

class CsvSeries {
 public:
  CsvSeries(std::string path, bool writer) : path_(std::move(path)), writer_(writer) { text_.precision(12); }
  std::ostringstream& text() { return text_; }
  void flush() const;  // the writer rank only
  // restart: the header and the rows of the existing file whose first column is <= t
  // (false, and nothing kept, when there is no such file)
  bool resume(double t);
  // the numeric rows kept by resume(), for figures over the whole run
  const std::vector<std::vector<double>>& resumed_rows() const { return rows_; }

 private:
  std::string path_;
  bool writer_;
  std::ostringstream text_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace ondine
