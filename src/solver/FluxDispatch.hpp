#pragma once
// The one place where the scene's runtime choices become template arguments:
// the term pack of the flux pass is assembled from the scheme options, so a
// term the scene does not enable is absent from the compiled pair loop.
// Instantiated in FluxDispatch_<D>d_<kernel>.cpp, one translation unit per
// (dimension, kernel) so that the build parallelises.
#include <type_traits>

#include "kernels/FluxArgs.hpp"
#include "kernels/FluxPass.hpp"
#include "kernels/terms/ArtificialViscosity.hpp"
#include "kernels/terms/BackgroundPressure.hpp"
#include "kernels/terms/ConsistentMorrisViscosity.hpp"
#include "kernels/terms/Continuity.hpp"
#include "kernels/terms/DeltaSphDiffusion.hpp"
#include "kernels/terms/MonaghanGingoldViscosity.hpp"
#include "kernels/terms/MorrisViscosity.hpp"
#include "kernels/terms/PressureGradient.hpp"
#include "kernels/terms/RiemannLeduc.hpp"
#include "kernels/terms/RiemannVila.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <class... T>
struct TypeList {};

namespace detail {

template <int D, class T>
T make_term(const FluxArgs<D>& a) {
  if constexpr (std::is_same<T, term::DeltaSphDiffusion<D>>::value) return T{a.delta_coeff, a.grad_rho};
  else if constexpr (std::is_same<T, term::MorrisViscosity>::value) return T{a.nu};
  else if constexpr (std::is_same<T, term::ConsistentMorrisViscosity<D>>::value) return T{a.nu, a.laplacian_weights};
  else if constexpr (std::is_same<T, term::MonaghanGingoldViscosity>::value) return T{a.nu};
  else if constexpr (std::is_same<T, term::ArtificialViscosity>::value) return T{a.av_alpha_R_c0, 0.01 * a.R * a.R};
  else if constexpr (std::is_same<T, term::BackgroundPressure>::value) return T{a.P_min};
  else if constexpr (std::is_same<T, term::RiemannLeduc<D, true>>::value) return T{a.eos, a.riemann_eta, a.grad_rho, a.grad_u};
  else if constexpr (std::is_same<T, term::RiemannLeduc<D, false>>::value) return T{a.eos, a.riemann_eta, {}, {}};
  else if constexpr (std::is_same<T, term::RiemannVila<D, true>>::value)
    return T{make_term<D, term::RiemannLeduc<D, true>>(a), a.m, a.du0};
  else if constexpr (std::is_same<T, term::RiemannVila<D, false>>::value)
    return T{make_term<D, term::RiemannLeduc<D, false>>(a), a.m, a.du0};
  else return T{};
}

template <int D, class Kernel, class... T>
void run_flux(const FluxArgs<D>& a) {
  using Pack = Terms<T...>;
  FluxPass<D, Kernel, Pack> pass{a.list, a.box, Kernel(a.R), a.R * a.R, a.body, a.x, a.u, a.rho, a.P, a.m,
                                 a.du, a.drho, Pack(make_term<D, T>(a)...), a.dm};
  pass.run(a.first, a.first + a.n);
}

template <int D, class Kernel, class... T>
FluxFunction<D> with_bg(const Scene& s, TypeList<T...>) {
  if (s.background_pressure) return &run_flux<D, Kernel, T..., term::BackgroundPressure>;
  return &run_flux<D, Kernel, T...>;
}
template <int D, class Kernel, class... T>
FluxFunction<D> with_av(const Scene& s, TypeList<T...>) {
  if (s.artificial_viscosity > 0) return with_bg<D, Kernel>(s, TypeList<T..., term::ArtificialViscosity>{});
  return with_bg<D, Kernel>(s, TypeList<T...>{});
}
template <int D, class Kernel, class... T>
FluxFunction<D> with_viscous(const Scene& s, TypeList<T...>) {
  switch (s.viscous_term) {
    case ViscousTerm::Morris:
      // no-slip NFM walls: the second-order consistent operator (kernels/ConsistentLaplacian.hpp)
      if (uses_consistent_laplacian(s)) return with_av<D, Kernel>(s, TypeList<T..., term::ConsistentMorrisViscosity<D>>{});
      return with_av<D, Kernel>(s, TypeList<T..., term::MorrisViscosity>{});
    case ViscousTerm::MonaghanGingold: return with_av<D, Kernel>(s, TypeList<T..., term::MonaghanGingoldViscosity>{});
    case ViscousTerm::None: break;
  }
  return with_av<D, Kernel>(s, TypeList<T...>{});
}

}  // namespace detail

// The flux pass for this scene's scheme (kernel type fixed by the caller).
template <int D, class Kernel>
FluxFunction<D> select_flux(const Scene& s) {
  using Base = TypeList<term::PressureGradient, term::Continuity>;
  // Riemann-SPH replaces the centred pressure gradient and continuity (and delta-SPH)
  if (s.flux == FluxScheme::Riemann && s.riemann_variant == RiemannVariant::Vila) {
    if (s.riemann_muscl) return detail::with_viscous<D, Kernel>(s, TypeList<term::RiemannVila<D, true>>{});
    return detail::with_viscous<D, Kernel>(s, TypeList<term::RiemannVila<D, false>>{});
  }
  if (s.flux == FluxScheme::Riemann) {
    if (s.riemann_muscl) return detail::with_viscous<D, Kernel>(s, TypeList<term::RiemannLeduc<D, true>>{});
    return detail::with_viscous<D, Kernel>(s, TypeList<term::RiemannLeduc<D, false>>{});
  }
  if (s.delta_sph > 0)
    return detail::with_viscous<D, Kernel>(s, TypeList<term::PressureGradient, term::Continuity, term::DeltaSphDiffusion<D>>{});
  return detail::with_viscous<D, Kernel>(s, Base{});
}

}  // namespace ondine
