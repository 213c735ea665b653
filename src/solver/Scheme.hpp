#pragma once
// The one dispatch point: a scene's runtime choices (dimension, smoothing kernel, flux
// terms, wall terms and wall options, refinement) become one compiled scheme, a set of
// pass functions instantiated for the scene's kernel, chosen once when the simulation
// starts (make_scheme, below: the only with_kernel call of the solver outside the
// refinement's own kernels). Every pass takes the one named context, PassContext
// (kernels/PassContext.hpp), filled by the part that calls it; it reads the members it needs.
#include <cstdint>

#include "kernels/CellList.hpp"
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/NeighbourList.hpp"
#include "kernels/OpenBoundary.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/WallFluxPass.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/apr/RefinementZones.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D>
struct CompiledScheme {
  using Pass = PassFunction<D>;
  Pass flux = nullptr;                      // the pair terms of the named scheme (FluxDispatch.hpp)
  Pass wall_flux = nullptr;                 // the wall terms (WallFluxDispatch.hpp), with walls
  Pass density_gradient = nullptr;          // and the consistent Laplacian's weights next to no-slip walls
  Pass renormalised_continuity = nullptr;   // scheme.renormalised_continuity
  Pass free_surface = nullptr;              // (4.86)-(4.87) into ctx.free_surface
  Pass transport_velocity = nullptr;        // Oger's law (2.112)-(2.115), (4.89) into ctx.du0; its surface flags must be fresh
  Pass eddy_viscosity = nullptr;            // turbulence: nu_T (and u_*, y+ with the wall function) into ctx.nu_T
  Pass k_epsilon_step = nullptr;            // k-epsilon: k and epsilon over ctx.k_eps.dt into ctx.k_next, ctx.eps_next
  Pass langevin_mean = nullptr;             // Langevin: the kernel-filtered means <u> into ctx.mean_u
  Pass langevin_step = nullptr;             // Langevin: k, epsilon and the velocity after the step's increment
  Pass langevin_drift_mean = nullptr;       // Langevin, drift_mean: removed: the deterministic increments' kernel mean taken off
  double (*wall_stiffness)(const PassContext<D>&) = nullptr;  // max kappa_i of (4.85), with viscous walls
  // particle shifting (2.107)-(2.111) from ctx's state into (x_out, u_out, rho_out)
  void (*shifting)(const PassContext<D>&, const field_view_t<field::Position, D>&, const field_view_t<field::Velocity, D>&,
                   const field_view_t<field::Density, D>&, double max_shift) = nullptr;
  // Shepard sums at a point over the owned particles [0, ctx.end): what = 0 the sum of
  // w W, 1 of w W P, 2 of w W rho, 3 + k of w W u_k
  double (*probe_sum)(const PassContext<D>&, const Vec<D>& point, int what) = nullptr;
  // the Shepard sum of each wave-gauge sample point
  void (*gauge_sums)(const PassContext<D>&, const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& points,
                     const Kokkos::View<double*, MemSpace>& sums) = nullptr;
  // open boundaries: the fluid's Shepard sums at each facet's sample point over the owned
  // fluid particles [0, ctx.end) (kernels/OpenBoundary.hpp, FacetSample)
  void (*open_samples)(const PassContext<D>&, const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& points,
                       const field_view_t<field::OpenRole, D>& role, const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& sums) = nullptr;
  // the pressure and viscous traction at each wall point (columns 0..D-1, D..2D-1)
  void (*wall_traction)(const PassContext<D>&, const Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace>& traction) = nullptr;
  // the guard spacing shifts of one level's guards [ctx.first, ctx.end) (refinement zones)
  long (*guard_spacing)(const PassContext<D>&, const Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace>& shift,
                        bool daughters, bool mothers) = nullptr;
  double morris_factor = 1;  // kappa of kernels/MorrisLatticeFactor.hpp (Morris viscosity only)
  double shift_coefficient = 0.5;  // c of the shift x += -c R^2 grad C (2.109) (Scene::shifting_coefficient)
};

// The compiled scheme of a scene (SchemePasses.hpp).
template <int D>
CompiledScheme<D> make_scheme(const Scene& scene);

}  // namespace ondine
