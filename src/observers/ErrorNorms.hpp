#pragma once
// Error figures of a run against the analytic solution or the published data its scene
// names (reference.type; docs/validation.md), read from the state of a Simulation at its
// current time: mass drift, momentum balance (fully periodic), Taylor-Green (2D),
// start-up Poiseuille and Couette, Ghia et al.'s cavity centrelines, hydrostatic pressure,
// the open channel's developed flow, wall leaks; and the buoyancy of submerged bodies from the
// wall forces. The solutions themselves are in reference/References.hpp; this file only measures against them.
#include <map>
#include <string>
#include <vector>

#include "solver/Simulation.hpp"

namespace ondine {

// the error figures of the scene's reference at the simulation's current time (collective)
template <int D>
std::map<std::string, double> reference_errors(const Simulation<D>& sim);

// Still water: the force on a body (a closed wall with the fluid outside) lying wholly under
// the surface y = origin_y + H is Archimedes' -rho0 g A. Returns the largest, over such
// bodies, of |F_pressure + F_viscous - (-rho0 g A)| / (rho0 |g| A); -1 when there is none.
double buoyancy_error(const Scene& scene, const std::vector<WallForce>& forces);

extern template std::map<std::string, double> reference_errors(const Simulation<2>&);
extern template std::map<std::string, double> reference_errors(const Simulation<3>&);

}  // namespace ondine
