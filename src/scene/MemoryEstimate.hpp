#pragma once
// What a case will need in memory on this machine, from its scene alone (before anything is
// allocated): the particles of the fluid blocks, the most particles its refinement zones can
// add, and the wall quadrature points every rank holds, at the bytes per particle measured on
// the solver (docs/parallel.md, "Memory"). The case-file check refuses a case that does not fit.
#include <string>

#include "scene/Scene.hpp"

namespace ondine {

struct MemoryEstimate {
  double particles = 0;          // the fluid blocks' lattice points (before walls clip them)
  double refined_particles = 0;  // the most the refinement zones can hold: daughters and guards
  double wall_points = 0;        // quadrature points of the walls (3D: one per (dx/2)^2 of area)
  double bytes_per_particle = 0, bytes_per_refined_particle = 0;
  int ranks = 1, ranks_here = 1;  // in the run, and on this machine (Open MPI's environment)
  double bytes_here = 0;          // all the ranks on this machine
  double machine_bytes = 0;       // physical memory of this machine
  std::string breakdown() const;  // particles x bytes, ..., ranks
  std::string summary() const;    // one line for the run's header
};

// measured (perf/README.md, "Memory"): peak resident size over particles, R = 3 dx
inline constexpr double kBytesPerParticle2D = 500, kBytesPerParticle3D = 1000;
inline constexpr double kBytesPerRefinedParticle2D = 900, kBytesPerRefinedParticle3D = 4200;
inline constexpr double kBytesPerWallPoint = 100;
inline constexpr double kBytesPerRank = 64.0 * 1048576.0;  // Kokkos, MPI, HDF5 and the code

MemoryEstimate estimate_memory(const Scene& s);

}  // namespace ondine
