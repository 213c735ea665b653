#pragma once
// The one named context of every pass over a level's particles: the pair loop and its terms,
// the wall loop and its terms, the gradient, surface, transport, shifting and observer passes.
// Filled by the solver (Simulation::pass_context); each pass and each term takes what it
// needs from it (a term's `from`, e.g. kernels/terms/MorrisViscosity.hpp).
#include "kernels/CellList.hpp"
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/NeighbourList.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/turbulence/EddyViscosityPass.hpp"
#include "kernels/turbulence/KEpsilon.hpp"
#include "kernels/turbulence/Langevin.hpp"
#include "kernels/apr/RefinementZones.hpp"
#include "kernels/wall/WallShear.hpp"

namespace ondine {

template <int D>
struct PairScatter;  // kernels/SymmetricFluxPass.hpp

template <int D>
struct PassContext {
  // the particles [first, end) of one level, its radius and spacing, its lists
  int first = 0, end = 0;
  double R = 0, dx = 0;
  NeighbourList<D> list;
  NeighbourList<D> half_list;          // scheme.pair_list: half: each pair of the level once
  PairScatter<D>* scatter = nullptr;   // its scattered sums (set with the half list only)
  CellList<D> cells;       // the particle cell list (observers that start from a point)
  CellList<D> wall_cells;  // the wall points binned at R
  PeriodicBox<D> box;
  PeriodicBox<D> wrap_box;  // the integrator's box, which wraps moved positions (shifting)
  Vec<D> body;              // gravity + body force
  // the state and its rates
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;
  VelocityGradientRows<D> grad_u;  // Riemann-SPH with MUSCL, the wall's velocity MUSCL state: written by the density-gradient pass
  field_view_t<field::ShepardGamma, D> gamma;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  field_view_t<field::MassRate, D> dm;  // Vila's ALE form: dm/dt, written by the flux pass
  field_view_t<field::FreeSurface, D> free_surface;
  field_view_t<field::TransportCorrection, D> du0;  // scheme.transport: ale, written by transport_velocity
  double u_char = 0;                                  // U_char = Ma c0 of (2.113)
  bool ale_project = true;                            // scheme.ale.cut_supports: tangential
  // the pair terms' coefficients at this level's radius
  double nu_pair = 0;        // the fluid viscous term's nu (Morris: times the lattice factor)
  double delta_coeff = 0;    // delta c0 R (2.60)
  bool delta_hydrostatic = false;  // scheme.delta_sph_form: hydrostatic
  Vec<D> rho_hydrostatic;          // its rho0 g / c0^2: the hydrostatic density gradient at rho0
  double av_alpha_R_c0 = 0;  // alpha R c0 (2.58)
  double P_min = 0;          // background pressure (2.105)
  double riemann_eta = 0;    // Riemann-SPH: > 0 the low-dissipation pressure (kernels/terms/RiemannLeduc.hpp)
  // walls
  WallPoints<D> wall;
  WallFacets<D> facets;       // segments (2D) or triangles (3D)
  FacetCells<D> facet_cells;  // the facets near each cell
  LaplacianWeightView<D> weights;  // the consistent Laplacian's, next to no-slip walls
  WallEos eos{1, 1, 1};            // c(rho) of (1.9): the wall pressure (4.14) and Riemann-SPH
  double nu = 0, rho0 = 0;         // the scene's viscosity (the wall terms have their own quadrature)
  double morris_factor = 1;
  double shift_coefficient = 0.5;  // c of the shift x += -c R^2 grad C (2.109)
  // turbulence (src/solver/hooks/EddyViscosity.hpp): nu_T, and with the wall function u_* and y+
  field_view_t<field::EddyViscosity, D> nu_T;
  field_view_t<field::FrictionVelocity, D> u_star;
  field_view_t<field::YPlus, D> y_plus;
  MixingLength<D> mixing_length;  // L(x) of the model at this level's spacing
  LogLaw log_law;
  field_view_t<field::TurbulentKineticEnergy, D> k;  // k-epsilon: the transported k and epsilon, their next values
  field_view_t<field::DissipationRate, D> eps;
  field_view_t<field::TurbulentKineticEnergyNext, D> k_next;
  field_view_t<field::DissipationRateNext, D> eps_next;
  KEpsilonConstants k_eps;
  field_view_t<field::GlobalId, D> id;               // the Langevin model: its random stream's counter,
  field_view_t<field::MeanVelocity, D> mean_u;       // <u> and the velocity after the step's increment
  field_view_t<field::LangevinVelocity, D> u_langevin;
  field_view_t<field::LangevinOffset, D> langevin_offset;
  field_view_t<field::LangevinDrift, D> langevin_drift;
  LangevinGradientRows<D> langevin_gradient;         // its path-averaged gradient (mean_gradient: averaged)
  LangevinConstants langevin;
  double clearance = 0;            // dx / 2 of the level: the wall-ward correction acts closer than this
  bool velocity_muscl = false;     // scheme.wall_velocity_reconstruction: the MUSCL state of u (4.30)
  bool wall_state_only = false;    // wall tractions: the MUSCL state's pressure alone, no rho c u_n (wall sensors)
  bool wall_contact = false;       // scheme.wall_contact: u_n of the wall's acoustic terms times theta_q (kernels/wall/WallContact.hpp)
  WallShear wall_shear = WallShear::Molecular;  // the no-slip wall term's shear stress, as the wall flux applies it
  // refinement zones (observers read each SPH particle with its level's radius)
  RefinementZones<D> zones;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprGuard, D> guard;
  field_view_t<field::AprMother, D> mother;
};

// a pass over the particles [c.first, c.end) of one level
template <int D>
using PassFunction = void (*)(const PassContext<D>&);

}  // namespace ondine
