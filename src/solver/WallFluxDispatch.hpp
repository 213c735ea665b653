#pragma once
// The wall-side counterpart of FluxDispatch.hpp: the pack of NFM wall terms folded by the
// generic wall loop (kernels/WallFluxPass.hpp) is assembled once from the scene's options,
// so a term the scene does not use is absent from the compiled loop:
//   wall::PressureFlux (4.22, 4.14, with the 2 P_min of 2.105) and wall::Continuity (4.25)
//   always; wall::NoSlipViscosity (4.85) in viscous scenes, in its consistent form with
//   the consistent Laplacian (kernels/ConsistentLaplacian.hpp).
#include <type_traits>

#include "kernels/WallFluxPass.hpp"
#include "kernels/wall/Continuity.hpp"
#include "kernels/wall/NoSlipViscosity.hpp"
#include "kernels/wall/PressureFlux.hpp"
#include "scene/Scene.hpp"

namespace ondine {

namespace detail {

template <int D, class T>
T make_wall_term(const WallFluxArgs<D>& a) {
  if constexpr (std::is_same<T, wall::PressureFlux>::value) return T{a.fluid.P_min};
  else if constexpr (std::is_same<T, wall::NoSlipViscosity<D, true>>::value || std::is_same<T, wall::NoSlipViscosity<D, false>>::value)
    return T{a.nu, 0.05 * a.fluid.R, a.wall.no_slip, a.weights};
  else return T{};
}

template <int D, class Kernel, class... T>
void run_wall_flux(const WallFluxArgs<D>& a) {
  using Pack = WallTerms<T...>;
  Kokkos::parallel_for("ondine::NFM::wall_flux", Kokkos::RangePolicy<ExecSpace>(a.fluid.first, a.fluid.first + a.fluid.n),
                       WallFluxPass<D, Kernel, Pack>(a, Pack(make_wall_term<D, T>(a)...)));
}

}  // namespace detail

// The wall flux pass for this scene's walls (kernel type fixed by the caller).
template <int D, class Kernel>
WallFluxFunction<D> select_wall_flux(const Scene& s) {
  using detail::run_wall_flux;
  if (uses_consistent_laplacian(s))
    return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity, wall::NoSlipViscosity<D, true>>;
  if (s.viscous_term != ViscousTerm::None)
    return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity, wall::NoSlipViscosity<D, false>>;
  return &run_wall_flux<D, Kernel, wall::PressureFlux, wall::Continuity>;
}

}  // namespace ondine
