#pragma once
// Checkpoints: the state fields of every particle (position, velocity, density,
// mass, id) in one HDF5 file written by all ranks together, with the time, the
// step and what a restart needs to go on as if never stopped (the initial mass
// and momentum the drift figures refer to, the snapshot count), and a checksum
// of the state. Written under a temporary name and renamed, so that the file
// under its name is always complete; read back on any number of ranks, each
// reading an equal share before the particles migrate to their owners.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "parallel/Communicator.hpp"

namespace ondine {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CheckpointHeader {
  std::string case_name;
  int dimension = 0;
  double dx = 0;
  double time = 0;
  std::int64_t step = 0;
  std::int64_t particles = 0;  // all ranks
  std::int64_t snapshots = 0;  // snapshots written before this checkpoint
  double initial_mass = 0;
  double initial_momentum[3] = {0, 0, 0};
  std::uint64_t checksum = 0;  // of the state fields (kernels/StateHash.hpp)
};

// The state fields, in this order, with their components (D for vectors).
inline const std::vector<std::string>& checkpoint_fields() {
  static const std::vector<std::string> f = {"position", "velocity", "density", "mass", "id"};
  return f;
}

struct CheckpointSlice {
  CheckpointHeader header;
  std::int64_t rows = 0;                              // this rank's share
  std::map<std::string, std::vector<double>> fields;  // name -> rows x components, row-major
};

// `fields`: this rank's rows of each state field (name -> rows, components).
void write_checkpoint(const std::string& path, const CheckpointHeader& header, std::int64_t local_rows,
                      const std::map<std::string, std::pair<std::vector<double>, int>>& fields, const Communicator& comm);

// This rank's share of a checkpoint; throws CheckpointError naming the file and
// what is wrong (unreadable, truncated, a missing field, a count that does not add up).
CheckpointSlice read_checkpoint(const std::string& path, const Communicator& comm);

}  // namespace ondine
