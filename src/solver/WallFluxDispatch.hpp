#pragma once
// The wall-side counterpart of FluxDispatch.hpp: the pack of NFM wall terms folded by the
// generic wall loop (kernels/WallFluxPass.hpp) is assembled once from the scene's options,
// so a term the scene does not use is absent from the compiled loop:
//   wall::PressureFlux (4.22, 4.14, with the 2 P_min of 2.105) and wall::Continuity (4.25)
//   always; wall::NoSlipViscosity (4.85) in viscous scenes, in its consistent form with
//   the consistent Laplacian (kernels/ConsistentLaplacian.hpp); with a turbulence model's log-law
//   wall function wall::WallFunction in its place, without one wall::EddyNoSlipViscosity (nu + nu_T).
#include "kernels/PassContext.hpp"
#include "kernels/WallFluxPass.hpp"
#include "kernels/wall/Continuity.hpp"
#include "kernels/wall/NoSlipViscosity.hpp"
#include "kernels/wall/PressureFlux.hpp"
#include "kernels/wall/WallFunction.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// theta_q of the level's wall points (kernels/wall/WallContact.hpp), from every particle of the
// context's cell list within the level's R (with refinement zones guards and mothers count too:
// theta is a presence, capped at 1)
template <int D, class Kernel>
Kokkos::View<double*, MemSpace> wall_contact(const PassContext<D>& c) {
  const int nq = static_cast<int>(c.wall.x.extent(0));
  Kokkos::View<double*, MemSpace> theta(Kokkos::view_alloc(Kokkos::WithoutInitializing, "ondine::NFM::wall_contact"), nq);
  Kokkos::parallel_for("ondine::NFM::wall_contact", Kokkos::RangePolicy<ExecSpace>(0, nq),
                       WallContactPass<D, Kernel>{c.wall, c.cells, c.facets, c.facet_cells, c.box, Kernel(c.R), c.R, c.x, c.rho, c.m, theta});
  return theta;
}

namespace detail {

template <int D, class Kernel, class... T>
void run_wall_flux(const PassContext<D>& c) {
  using Pack = WallTerms<T...>;
  WallFluxPass<D, Kernel, Pack> pass(c, Pack(T::from(c)...));
  if (c.wall_contact) pass.contact = wall_contact<D, Kernel>(c);
  Kokkos::parallel_for("ondine::NFM::wall_flux", Kokkos::RangePolicy<ExecSpace>(c.first, c.end), pass);
}

}  // namespace detail

// The wall flux pass for this scene's walls (kernel type fixed by the caller).
template <int D, class Kernel>
PassFunction<D> select_wall_flux(const Scene& s) {
  using detail::run_wall_flux;
  if (s.turbulence.wall_function != WallLaw::None)
    return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity, wall::WallFunction<D>>;
  if (s.turbulence.eddy_viscous())  // no wall function: (4.85) with nu + nu_T of the particle
    return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity, wall::EddyNoSlipViscosity<D>>;
  if (uses_consistent_laplacian(s))
    return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity, wall::NoSlipViscosity<D, true>>;
  if (s.viscous_term != ViscousTerm::None)
    return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity, wall::NoSlipViscosity<D, false>>;
  return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity>;
}

}  // namespace ondine
