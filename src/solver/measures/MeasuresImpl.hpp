#pragma once
// The measures' definitions (solver/Measures.hpp), and their instantiation for a dimension.
#include "solver/measures/Counts.hpp"
#include "solver/measures/Diagnostics.hpp"
#include "solver/measures/Probes.hpp"
#include "solver/measures/StateRows.hpp"
#include "solver/measures/WallLoads.hpp"

#define ONDINE_INSTANTIATE_MEASURES(D)                                                         \
  template Diagnostics diagnostics<D>(const Simulation<D>&);                                   \
  template std::vector<ProbeSample> sample_at<D>(const Simulation<D>&, const std::vector<Vec3>&); \
  template std::vector<ProbeSample> sample_probes<D>(const Simulation<D>&);                    \
  template std::vector<double> wave_elevations<D>(Simulation<D>&);                             \
  template double front_position<D>(const Simulation<D>&);                                     \
  template std::vector<WallForce> wall_forces<D>(Simulation<D>&);                              \
  template WallLoadField wall_load_field<D>(Simulation<D>&);                                   \
  template std::vector<double> wall_sensor_pressures<D>(Simulation<D>&);                      \
  template std::int64_t wall_leaks<D>(const Simulation<D>&, double);                           \
  template std::int64_t global_size<D>(const Simulation<D>&);                                  \
  template std::int64_t sph_particles<D>(const Simulation<D>&);                                \
  template std::int64_t pair_count<D>(const Simulation<D>&);                                   \
  template StateRows state_rows<D>(const Simulation<D>&);                                      \
  template std::uint64_t state_checksum<D>(const Simulation<D>&);                              \
  template CheckpointRefinement refinement_state<D>(const Simulation<D>&);                     \
  template std::uint64_t refinement_checksum<D>(const Simulation<D>&);                         \
  template std::map<std::string, std::uint64_t> field_checksums<D>(const Simulation<D>&);
