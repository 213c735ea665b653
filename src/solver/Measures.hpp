#pragma once
// What an observer reads of a simulation (LAMMPS' Compute): integral diagnostics, probes,
// wave gauges, wall forces and leaks, the dam-break front, counts and checksums. Free
// functions over a simulation, each computed by Kokkos reductions over the owned particles
// and summed over the ranks (collective); none changes the state. Those that take a
// non-const simulation bring its lists and halos up to date first. Definitions in
// solver/measures/, instantiated for 2D and 3D in Measures2d.cpp and Measures3d.cpp.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/Checkpoint.hpp"
#include "io/WallFieldWriter.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D>
class Simulation;

// Integral quantities of the particle set.
struct Diagnostics {
  double mass = 0;
  double fluid_mass = 0;  // with open boundaries: the fluid region's (buffer layers excluded); = mass otherwise
  Vec3 momentum{0, 0, 0};
  double kinetic_energy = 0;
  double potential_energy = 0;  // -sum m g.x (gravity), from the coordinates' origin
  double max_speed = 0;
  double rho_min = 0, rho_max = 0;
  std::int64_t outside_domain = 0;  // particles beyond a non-periodic domain face
  bool finite = true;               // no NaN/Inf in positions, velocities, densities
};

struct ProbeSample {
  double pressure = 0, density = 0;
  Vec3 velocity{0, 0, 0};
  double shepard = 0;  // sum_j w_j W: 0 means no fluid around the probe
};

// Force of the fluid on one wall (the reaction of the wall terms of 4.22 and 4.85).
struct WallForce {
  std::string name;
  Vec3 pressure{0, 0, 0}, viscous{0, 0, 0};  // N (per metre of span in 2D)
  Vec3 moment{0, 0, 0};  // of pressure + viscous about the wall's moment_centre, N m (2D: z only, N m per metre)
};

// owned rows of the checkpoint's fields on the host: name -> (rows, components)
using StateRows = std::map<std::string, std::pair<std::vector<double>, int>>;

// measures/Diagnostics.hpp: mass, momentum, kinetic energy (with zones over the leaves),
// speed and density bounds, particles outside the domain, finiteness
template <int D>
Diagnostics diagnostics(const Simulation<D>& sim);
// measures/Probes.hpp: Shepard interpolation at points (2.40-2.41); at the scene's probes
template <int D>
std::vector<ProbeSample> sample_at(const Simulation<D>& sim, const std::vector<Vec3>& points);
template <int D>
std::vector<ProbeSample> sample_probes(const Simulation<D>& sim);
// free-surface elevation at each of the scene's wave gauges (kernels/WaveGauge.hpp)
template <int D>
std::vector<double> wave_elevations(Simulation<D>& sim);
// x of the leading edge of the fluid (max x + dx/2), for the dam-break front
template <int D>
double front_position(const Simulation<D>& sim);
// measures/WallLoads.hpp: the force and moment on each wall, the load point by point; the particles on the solid
// side of a wall or closer than `clearance` (0.1 dx where negative) to one
template <int D>
std::vector<WallForce> wall_forces(Simulation<D>& sim);
template <int D>
WallLoadField wall_load_field(Simulation<D>& sim);
// the pressure of each of the scene's wall sensors (wall_sensors:), averaged over its face
template <int D>
std::vector<double> wall_sensor_pressures(Simulation<D>& sim);
template <int D>
std::int64_t wall_leaks(const Simulation<D>& sim, double clearance = -1);
// measures/Counts.hpp: particles of all ranks; SPH particles (guards excluded) on this
// rank; pairs within R (both ways) at the last list build
template <int D>
std::int64_t global_size(const Simulation<D>& sim);
template <int D>
std::int64_t sph_particles(const Simulation<D>& sim);
template <int D>
std::int64_t pair_count(const Simulation<D>& sim);
// measures/StateRows.hpp: the rows a checkpoint carries (io/Checkpoint.hpp), the
// order-independent checksum of the state fields (position, velocity, density, mass, id),
// and with zones the APR state and the checksum of its fields (kernels/StateHash.hpp)
template <int D>
StateRows state_rows(const Simulation<D>& sim);
template <int D>
std::uint64_t state_checksum(const Simulation<D>& sim);
template <int D>
CheckpointRefinement refinement_state(const Simulation<D>& sim);
template <int D>
std::uint64_t refinement_checksum(const Simulation<D>& sim);
// the checksum of each other field a checkpoint carries (open roles, k, epsilon, the Langevin
// model's averaged gradient), by label
template <int D>
std::map<std::string, std::uint64_t> field_checksums(const Simulation<D>& sim);

}  // namespace ondine
