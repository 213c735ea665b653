#pragma once
// HDF5 particle snapshots with an XDMF index that ParaView opens as a time series.
// One file per snapshot, <dir>/<case>_<NNNNNN>.h5, holding one dataset per
// allocated field (vectors as N x 3, z = 0 in 2D, so ParaView sees XYZ), and
// attributes time, step, dimension. The index <dir>/<case>.xmf is rewritten after
// each snapshot. Both go through a temporary name and a rename. On several ranks
// the file is written collectively (io/H5Collective.hpp), each rank its owned
// particles, and rank 0 writes the index: the same files as a one-rank run.
#include <string>
#include <vector>

#include "parallel/Communicator.hpp"
#include "particles/ParticleSet.hpp"

namespace ondine {

struct SnapshotEntry {
  std::string file;  // relative to the output folder
  double time;
  std::int64_t step;
  std::size_t particles;
  std::vector<std::pair<std::string, int>> fields;  // name, components (1 or 3)
};

class SnapshotWriter {
 public:
  SnapshotWriter(std::string dir, std::string case_name, Communicator comm = Communicator());

  // the first `owned` particles of p (all of them by default)
  template <int D>
  void write(const ParticleSet<D>& p, double time, std::int64_t step, std::int64_t owned = -1);
  // a restarted run: takes the first `count` snapshots already in the folder as its
  // own, and removes the later ones (written after the checkpoint)
  void resume(std::size_t count);
  // removes this case's snapshots numbered `first` or more from the folder, so that
  // a folder never mixes the snapshots of two runs (a new run calls it with 0)
  void remove_from(std::size_t first) const;

  const std::vector<SnapshotEntry>& entries() const { return entries_; }
  std::string index_path() const;
  // the snapshot numbered `index`: <case>_NNNNNN.h5
  std::string file_name(std::size_t index) const;

 private:
  void write_index() const;
  std::string dir_, name_;
  Communicator comm_;
  std::vector<SnapshotEntry> entries_;
};

// Reads one snapshot back (for tests and restarts): every dataset as N x c doubles.
struct SnapshotData {
  double time = 0;
  std::int64_t step = 0;
  int dimension = 0;
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  // row-major N x components
  std::vector<int> components;
  std::size_t particles = 0;
};
SnapshotData read_snapshot(const std::string& path, bool with_values = true);  // false: names and shapes only

}  // namespace ondine
