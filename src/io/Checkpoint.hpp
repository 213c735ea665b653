#pragma once
// Checkpoints: the state fields of every particle (position, velocity, density,
// mass, id) in one HDF5 file written by all ranks together, with the time, the
// step and what a restart needs to go on as if never stopped (the initial mass
// and momentum the drift figures refer to, the snapshot count), and a checksum
// of the state. Written under a temporary name and renamed, so that the file
// under its name is always complete; read back on any number of ranks, each
// reading an equal share before the particles migrate to their owners.
// A run with refinement zones (docs/apr.md) also saves its APR fields and the
// state of its zones and bookkeeping (CheckpointRefinement); a uniform run's
// checkpoint has none of it.
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

// The APR state of a run with refinement zones (src/solver/AdaptiveRefinement.hpp):
// present only in a checkpoint of such a run.
struct CheckpointRefinement {
  bool present = false;
  std::string zones;                  // the zone definitions, one line per zone (compared with the case's at a restart)
  std::int64_t next_id = 0;           // global id of the next daughter
  std::int64_t refined = 0;           // mothers refined since t = 0
  std::int64_t deleted = 0;           // daughters deleted since t = 0
  std::int64_t families_moved = 0;    // families moved off a wall since t = 0 (DaughterWallClearance)
  std::int64_t adopted = 0;           // daughters adopted since t = 0 (kernels/apr/Adoption.hpp)
  std::int64_t orphans_deleted = 0;   // daughters inside their zone deleted for want of an adopter since t = 0
  std::int64_t outflow_daughters = 0; // daughters removed by an open boundary while their mother was one, since t = 0
  std::int64_t guard_shifts = 0;      // daughter guards shifted since t = 0, all ranks (GuardSpacing)
  std::int64_t guards_limited = 0;    // guard interpolations limited since t = 0, all ranks (GuardApply)
  std::vector<double> level_steps;    // local time stepping: the steps of each level since t = 0 (exact integers)
  std::vector<double> level_particle_steps;  // each level's SPH particles x steps since t = 0, all ranks
  double momentum_change[3] = {0, 0, 0};  // sum over refinements of sum_f m_f u_f - m_m u_m
  double momentum_scale = 0;              // sum over refinements of m_m |u_m|
  std::vector<double> offset;        // zones x 3: displacement of each zone from its case-file box (m)
  std::vector<double> lo_at_update;  // zones x 3: each zone's lower corner at the last bookkeeping (m)
  std::uint64_t checksum = 0;        // of the APR fields with the ids (kernels/StateHash.hpp)
};

// The open boundaries' state (solver/OpenBoundaries.hpp): the next global id, the counters and
// the facets' reference states; with it the checkpoint holds the field open_role.
struct CheckpointOpen {
  bool present = false;
  std::int64_t next_id = 0;
  std::vector<double> state;  // OpenBoundaries::save's layout
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
  std::map<std::string, std::uint64_t> field_checksums;  // of each field beyond the state and the APR ones (checksum_LABEL)
  double langevin_impulse[3] = {0, 0, 0};  // the Langevin increments' momentum since t = 0, all ranks (langevin.csv)
  std::int64_t wall_corrections = 0;  // impermeability corrections since t = 0, all ranks (kernels/WallImpermeability.hpp)
  // what the run has cost since t = 0 over every process that led to this checkpoint (the slowest
  // rank's wall seconds, rank 0's CPU seconds); 0 in a checkpoint written before they were recorded
  double run_wall_seconds = 0, run_cpu_seconds = 0;
  std::int64_t initial_particles = 0;  // all ranks at t = 0 (open boundaries and refinement change the count); 0: not recorded
  // the case's rho0 and domain box (min then max, 3 each), so that a restart with another case is
  // refused; rho0 0 and no box: a checkpoint written before they were recorded
  double rho0 = 0;
  std::vector<double> domain;
  CheckpointRefinement refinement;
  CheckpointOpen open;
};

// The state fields, in this order, with their components (D for vectors).
inline const std::vector<std::string>& checkpoint_fields() {
  static const std::vector<std::string> f = {"position", "velocity", "density", "mass", "id"};
  return f;
}

// The fields a run has where its model does (field labels of kernels/Fields.hpp): k-epsilon's k
// and epsilon (one value per particle), the Langevin model's path-averaged gradient (rows of D)
inline const std::vector<std::string>& optional_checkpoint_fields() {
  static const std::vector<std::string> f = {"k", "epsilon", "langevin_gradient_x", "langevin_gradient_y", "langevin_gradient_z"};
  return f;
}

// The APR fields (field labels of kernels/Fields.hpp), one value per particle,
// written and read only with refinement zones.
inline const std::vector<std::string>& checkpoint_refinement_fields() {
  static const std::vector<std::string> f = {"birth_level", "level", "guard", "mother", "parent_id"};
  return f;
}

struct CheckpointSlice {
  CheckpointHeader header;
  std::int64_t rows = 0;                              // this rank's share
  std::map<std::string, std::vector<double>> fields;  // name -> rows x components, row-major
};

// `fields`: this rank's rows of each state field (name -> rows, components), and
// of the APR fields when header.refinement.present.
void write_checkpoint(const std::string& path, const CheckpointHeader& header, std::int64_t local_rows,
                      const std::map<std::string, std::pair<std::vector<double>, int>>& fields, const Communicator& comm);

// This rank's share of a checkpoint; throws CheckpointError naming the file and
// what is wrong (unreadable, truncated, a missing field, a count that does not add up).
// The APR fields and state are read when the file has them (header.refinement.present).
CheckpointSlice read_checkpoint(const std::string& path, const Communicator& comm);

}  // namespace ondine
