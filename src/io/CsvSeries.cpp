#include "io/CsvSeries.hpp"

#include <cstdlib>
#include <fstream>

#include "io/AtomicFile.hpp"

namespace ondine {

void CsvSeries::flush() const {
  if (writer_) write_text_atomically(path_, text_.str());
}

bool CsvSeries::resume(double t) {
  std::ifstream in(path_);
  if (!in) return false;
  std::string line;
  if (!std::getline(in, line)) return false;
  std::ostringstream kept;
  kept << line << "\n";
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::size_t pos = 0;
    while (pos <= line.size()) {
      const std::size_t comma = line.find(',', pos);
      const std::string cell = line.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
      row.push_back(std::strtod(cell.c_str(), nullptr));
      if (comma == std::string::npos) break;
      pos = comma + 1;
    }
    if (row.empty() || row[0] > t * (1 + 1e-12) + 1e-300) break;
    kept << line << "\n";
    rows_.push_back(row);
  }
  text_.str("");
  text_ << kept.str();
  return true;
}

}  // namespace ondine
