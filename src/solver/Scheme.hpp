#pragma once
// The one dispatch point: a scene's runtime choices (dimension, smoothing kernel, flux
// terms, wall terms and wall options, refinement) become one compiled scheme, a set of
// pass functions instantiated for the scene's kernel, chosen once when the simulation
// starts (make_scheme, below: the only with_kernel call of the solver outside the
// refinement's own kernels). Every pass takes one named context, PassContext, filled by
// the part that calls it; it reads the members its kernel needs.
#include <cstdint>

#include "kernels/CellList.hpp"
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/FluxArgs.hpp"
#include "kernels/NeighbourList.hpp"
#include "kernels/OpenBoundary.hpp"
#include "kernels/WallFluxPass.hpp"
#include "kernels/WallPressure.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/apr/RefinementZones.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D>
struct PassContext {
  // the particles [first, end) of one level, its radius and spacing, its lists
  int first = 0, end = 0;
  double R = 0, dx = 0;
  NeighbourList<D> list;
  CellList<D> cells;       // the particle cell list (observers that start from a point)
  CellList<D> wall_cells;  // the wall points binned at R
  PeriodicBox<D> box;
  PeriodicBox<D> wrap_box;  // the integrator's box, which wraps moved positions (shifting)
  // the state
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::DensityGradient, D> grad_rho;
  VelocityGradientRows<D> grad_u;  // Riemann-SPH with MUSCL: written by the density-gradient pass
  field_view_t<field::ShepardGamma, D> gamma;
  field_view_t<field::DensityRate, D> drho;
  field_view_t<field::FreeSurface, D> free_surface;
  field_view_t<field::TransportCorrection, D> du0;  // scheme.transport: ale, written by transport_velocity
  double u_char = 0;                                  // U_char = Ma c0 of (2.113)
  bool ale_project = true;                            // scheme.ale.cut_supports: tangential
  // walls
  WallPoints<D> wall;
  WallFacets<D> facets;  // segments (2D) or triangles (3D)
  FacetCells<D> facet_cells;  // the facets near each cell
  LaplacianWeightView<D> weights;  // the consistent Laplacian's, next to no-slip walls
  WallEos eos;
  double nu = 0, rho0 = 0;
  double morris_factor = 1;
  bool velocity_muscl = false;
  // refinement zones (observers read each SPH particle with its level's radius)
  RefinementZones<D> zones;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprGuard, D> guard;
  field_view_t<field::AprMother, D> mother;
};

template <int D>
struct CompiledScheme {
  using Pass = void (*)(const PassContext<D>&);
  FluxFunction<D> flux = nullptr;           // the pair terms (FluxDispatch.hpp)
  WallFluxFunction<D> wall_flux = nullptr;  // the wall terms (WallFluxDispatch.hpp), with walls
  Pass density_gradient = nullptr;          // and the consistent Laplacian's weights next to no-slip walls
  Pass renormalised_continuity = nullptr;   // scheme.renormalised_continuity
  Pass free_surface = nullptr;              // (4.86)-(4.87) into ctx.free_surface
  Pass transport_velocity = nullptr;        // Oger's law (2.112)-(2.115), (4.89) into ctx.du0; its surface flags must be fresh
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
};

// The compiled scheme of a scene (SchemePasses.hpp).
template <int D>
CompiledScheme<D> make_scheme(const Scene& scene);

}  // namespace ondine
