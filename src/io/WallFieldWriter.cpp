#include "io/WallFieldWriter.hpp"

#include <filesystem>
#include <iomanip>
#include <sstream>

#include "io/AtomicFile.hpp"
#include "io/H5Collective.hpp"
#include "io/XdmfSeries.hpp"

namespace ondine {

WallFieldWriter::WallFieldWriter(std::string dir, std::string case_name, Communicator comm)
    : dir_(std::move(dir)), name_(std::move(case_name)), comm_(comm) {}

std::string WallFieldWriter::index_path() const { return dir_ + "/" + name_ + "_walls.xmf"; }

// relative to the output folder: in its walls/ subfolder, so that no pattern of the particle
// snapshots (<name>_NNNNNN.h5) picks them up
std::string WallFieldWriter::file_name(std::size_t index) const {
  std::ostringstream f;
  f << "walls/" << name_ << "_" << std::setw(6) << std::setfill('0') << index << ".h5";
  return f.str();
}

void WallFieldWriter::write(const WallLoadField& f, double time, std::int64_t step) {
  const std::string fname = file_name(entries_.size());
  const bool root = comm_.rank() == 0;
  if (entries_.empty()) {
    if (root) std::filesystem::create_directories(dir_ + "/walls");
    comm_.barrier();
  }
  const std::int64_t rows = root ? static_cast<std::int64_t>(f.points()) : 0;
  auto mine = [&](const std::vector<double>& v) { return root ? v : std::vector<double>(); };
  H5CollectiveFile file(dir_ + "/" + fname, comm_, rows);
  file.attribute("time", time);
  file.attribute("step", step);
  file.dataset("position", mine(f.position), 3);
  file.dataset("normal", mine(f.normal), 3);
  file.dataset("pressure", mine(f.pressure), 1);
  file.dataset("traction", mine(f.traction), 3);
  file.dataset("area", mine(f.area), 1);
  file.dataset("wall", mine(f.wall), 1);
  file.commit();
  entries_.push_back({fname, time, f.points()});
  if (root) write_index();
}

void WallFieldWriter::remove_from(std::size_t first) const {
  if (comm_.rank() == 0) {
    remove_numbered_files(dir_ + "/walls", name_ + "_", first);
    if (first == 0) std::filesystem::remove(index_path());
  }
  comm_.barrier();
}

void WallFieldWriter::resume(std::size_t count) {
  remove_from(count);
  entries_.clear();
  for (std::size_t k = 0; k < count; ++k) {
    const std::string fname = file_name(k);
    if (!std::filesystem::exists(dir_ + "/" + fname)) break;  // a run written before the walls' files existed
    H5CollectiveReader r(dir_ + "/" + fname, comm_);
    std::int64_t rows = 0;
    int comps = 0;
    r.shape("pressure", rows, comps);
    entries_.push_back({fname, r.attribute_double("time"), static_cast<std::size_t>(rows)});
  }
}

void WallFieldWriter::write_index() const {
  std::vector<XdmfPointSet> sets;
  for (const Entry& e : entries_)
    sets.push_back({e.file, e.time, e.points, {{"normal", 3}, {"pressure", 1}, {"traction", 3}, {"area", 1}, {"wall", 1}}});
  write_text_atomically(index_path(), xdmf_point_series(name_ + "_walls", "walls", sets));
}

}  // namespace ondine
