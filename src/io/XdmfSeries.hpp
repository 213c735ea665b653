#pragma once
// What the snapshots and the wall load field share (io/SnapshotWriter.hpp,
// io/WallFieldWriter.hpp): the XDMF 2.0 index of a time series of point sets, and the
// removal of the numbered files of an earlier run.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ondine {

struct XdmfPointSet {
  std::string file;  // relative to the index
  double time;
  std::size_t points;
  std::vector<std::pair<std::string, int>> fields;  // name, components (1 or 3); "position" is the geometry
};

// A temporal collection `collection` of Polyvertex grids named `grid`: the geometry XYZ from
// <file>:/position, every other field a node-centred attribute (Vector for 3 components).
std::string xdmf_point_series(const std::string& collection, const std::string& grid, const std::vector<XdmfPointSet>& sets);

// Removes the files <dir>/<prefix>NNNNNN.h5 (six digits) numbered `first` or more.
void remove_numbered_files(const std::string& dir, const std::string& prefix, std::size_t first);

}  // namespace ondine
