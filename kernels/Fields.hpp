#pragma once
// Particle fields as tag types (named, never numbered; see docs/design.md).
// A field's storage is one Kokkos View per field, LayoutLeft so that each
// component is contiguous (structure of arrays).
#include <Kokkos_Core.hpp>
#include <cstdint>
#include <type_traits>

namespace ondine {

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
// the particles live on the host (OpenMP, Serial), not on a GPU
inline constexpr bool host_backend = Kokkos::SpaceAccessibility<MemSpace, Kokkos::HostSpace>::accessible;

namespace field {
#define ONDINE_FIELD_(Name, label_, value_t, vector_, output_) \
  struct Name {                                               \
    static constexpr const char* label = label_;              \
    using value_type = value_t;                               \
    static constexpr bool is_vector = vector_;                \
    static constexpr bool output = output_;                   \
  }
#define ONDINE_FIELD(Name, label_, value_t, vector_) ONDINE_FIELD_(Name, label_, value_t, vector_, true)
ONDINE_FIELD(Position, "position", double, true);
ONDINE_FIELD(Velocity, "velocity", double, true);
ONDINE_FIELD(Density, "density", double, false);
ONDINE_FIELD(Pressure, "pressure", double, false);
ONDINE_FIELD(Mass, "mass", double, false);
ONDINE_FIELD(GlobalId, "id", std::int64_t, false);
ONDINE_FIELD(Acceleration, "acceleration", double, true);  // du/dt
ONDINE_FIELD(DensityRate, "density_rate", double, false);  // drho/dt
// Renormalised density gradient, thesis (2.42)-(2.44), read by the delta-SPH term (2.63).
ONDINE_FIELD(DensityGradient, "density_gradient", double, true);
// Rows of the renormalised velocity gradient <grad u_k>_i (2.42-2.44), one vector field per
// component k, read by the MUSCL reconstruction of Riemann-SPH (2.78); recomputed at every stage.
ONDINE_FIELD_(VelocityGradientX, "velocity_gradient_x", double, true, false);
ONDINE_FIELD_(VelocityGradientY, "velocity_gradient_y", double, true, false);
ONDINE_FIELD_(VelocityGradientZ, "velocity_gradient_z", double, true, false);
// The transport-velocity correction du_i of Oger et al.'s law (2.113): the particles move with
// u0 = u + du (scheme.transport: ale); recomputed at every stage.
ONDINE_FIELD(TransportCorrection, "transport_correction", double, true);
// d(m_i)/dt of Vila's Riemann-SPH in ALE form (2.86): the masses change by the mass fluxes.
ONDINE_FIELD_(MassRate, "mass_rate", double, false, false);
// Shepard factor gamma_i of the NFM walls (thesis 4.17, 4.52): 1 away from walls.
ONDINE_FIELD(ShepardGamma, "shepard_gamma", double, false);
// Free-surface flag from the NFM renormalisation matrix and normal (4.86)-(4.87): 1 on the surface.
ONDINE_FIELD(FreeSurface, "free_surface", double, false);
// Turbulence (src/solver/hooks/EddyViscosity.hpp): the eddy viscosity nu_T of the model
// (V&I §4.1.1), and next to no-slip walls with the log-law wall function the friction velocity
// u_* and y+ = y u_* / nu of the nearest wall point; recomputed at every stage.
ONDINE_FIELD(EddyViscosity, "eddy_viscosity", double, false);
ONDINE_FIELD(FrictionVelocity, "friction_velocity", double, false);
ONDINE_FIELD(YPlus, "y_plus", double, false);
// k-epsilon: the turbulent kinetic energy k and its dissipation rate epsilon, carried by the
// particles, and their values at the step's end before the wall function's (scratch, not written)
ONDINE_FIELD(TurbulentKineticEnergy, "k", double, false);
ONDINE_FIELD(DissipationRate, "epsilon", double, false);
ONDINE_FIELD_(TurbulentKineticEnergyNext, "k_next", double, false, false);
ONDINE_FIELD_(DissipationRateNext, "epsilon_next", double, false, false);
// The Langevin model (kernels/turbulence/Langevin.hpp): the kernel-filtered mean velocity <u>
// [V&I 17] of the step's end, the velocity after the step's Langevin increment and the support's
// centroid offset, then the corrected mean (scratch)
ONDINE_FIELD(MeanVelocity, "mean_velocity", double, true);
ONDINE_FIELD_(LangevinVelocity, "langevin_velocity", double, true, false);
ONDINE_FIELD_(LangevinOffset, "langevin_offset", double, true, false);
// turbulence.langevin.drift_mean: removed: the step's deterministic increment (scratch)
ONDINE_FIELD_(LangevinDrift, "langevin_drift", double, true, false);
// turbulence.langevin.mean_gradient: averaged: the gradient of the means averaged along the
// particle's path over the model's turnover time k / epsilon, one row per field (a state field:
// in checkpoints)
ONDINE_FIELD_(LangevinGradientX, "langevin_gradient_x", double, true, false);
ONDINE_FIELD_(LangevinGradientY, "langevin_gradient_y", double, true, false);
ONDINE_FIELD_(LangevinGradientZ, "langevin_gradient_z", double, true, false);
// Integrator stage storage (not written to snapshots): the state y0 at the start
// of the step and the RK4 weighted sum of the stage derivatives. Particle fields,
// so that they follow a particle that changes rank in the middle of a step.
// Adaptive particle refinement (thesis 5.4, docs/apr.md), allocated only when the
// scene has refinement zones: the birth level n^B (the level whose spacing and
// radius the particle has, 0 = coarse), the current level n^C (depth of the zones
// at its position), the guard flag (1: Omega_x, interpolated by 5.24; 0: an SPH
// particle of Omega_.) and the mother flag (1: it has daughters).
ONDINE_FIELD(AprLevel, "level", int, false);
ONDINE_FIELD(AprBirthLevel, "birth_level", int, false);
ONDINE_FIELD(AprGuard, "guard", int, false);
ONDINE_FIELD(AprMother, "mother", int, false);
// Open boundaries (kernels/OpenBoundary.hpp): 0 for a fluid particle, b + 1 for a particle of
// the buffer layer of open boundary b (its state imposed or extrapolated, not integrated).
ONDINE_FIELD(OpenRole, "open_role", int, false);
// global id of a daughter's mother (-1 at level 0): a mother's daughters leave with it
ONDINE_FIELD_(AprParent, "parent_id", std::int64_t, false, false);
ONDINE_FIELD_(StagePosition, "stage_position", double, true, false);
ONDINE_FIELD_(StageVelocity, "stage_velocity", double, true, false);
ONDINE_FIELD_(StageDensity, "stage_density", double, false, false);
ONDINE_FIELD_(StageMass, "stage_mass", double, false, false);
ONDINE_FIELD_(StageMassSum, "stage_mass_sum", double, false, false);
ONDINE_FIELD_(StagePositionSum, "stage_position_sum", double, true, false);
ONDINE_FIELD_(StageVelocitySum, "stage_velocity_sum", double, true, false);
ONDINE_FIELD_(StageDensitySum, "stage_density_sum", double, false, false);
// Local time stepping (refinement.local_time_stepping): a level's state at the end of its
// current step, while the finer levels take theirs (their guards read the coarse state
// interpolated in time between the step's start, the stage storage, and this end).
ONDINE_FIELD_(LevelEndPosition, "level_end_position", double, true, false);
ONDINE_FIELD_(LevelEndVelocity, "level_end_velocity", double, true, false);
ONDINE_FIELD_(LevelEndDensity, "level_end_density", double, false, false);
#undef ONDINE_FIELD
#undef ONDINE_FIELD_
}  // namespace field

template <class Tag, int D>
using field_view_t =
    std::conditional_t<Tag::is_vector,
                       Kokkos::View<typename Tag::value_type* [D], Kokkos::LayoutLeft, MemSpace>,
                       Kokkos::View<typename Tag::value_type*, MemSpace>>;

}  // namespace ondine
