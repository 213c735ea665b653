#pragma once
// The one place where the scene's runtime choices become template arguments: each row of the
// named flux schemes (scene/FluxSchemes.hpp) becomes a term pack, so a term the scene does not
// enable is absent from its compiled pair loop, and only the table's rows are compiled.
// Instantiated in FluxDispatch_<D>d_<kernel>.cpp, one translation unit per (dimension,
// kernel) so that the build parallelises.
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "kernels/FluxPass.hpp"
#include "kernels/SymmetricFluxPass.hpp"
#include "kernels/PassContext.hpp"
#include "kernels/terms/ArtificialViscosity.hpp"
#include "kernels/terms/BackgroundPressure.hpp"
#include "kernels/terms/ConsistentMorrisViscosity.hpp"
#include "kernels/terms/Continuity.hpp"
#include "kernels/terms/DeltaSphDiffusion.hpp"
#include "kernels/terms/EddyMorrisViscosity.hpp"
#include "kernels/terms/MonaghanGingoldViscosity.hpp"
#include "kernels/terms/MorrisViscosity.hpp"
#include "kernels/terms/PressureGradient.hpp"
#include "kernels/terms/RiemannLeduc.hpp"
#include "kernels/terms/RiemannVila.hpp"
#include "scene/FluxSchemes.hpp"

namespace ondine {

template <class... T>
struct TypeList {};

namespace detail {

template <class... A, class... B, class... C, class... E>
TypeList<A..., B..., C..., E...> concat(TypeList<A...>, TypeList<B...>, TypeList<C...>, TypeList<E...>);

// the pressure and continuity part of a key (scene/FluxSchemes.hpp); Riemann-SPH replaces the
// centred pressure gradient and continuity
template <int D, FluxBase B>
struct BaseTerms {
  using type = TypeList<term::PressureGradient, term::Continuity>;
};
template <int D>
struct BaseTerms<D, FluxBase::CentredDeltaSph> {
  using type = TypeList<term::PressureGradient, term::Continuity, term::DeltaSphDiffusion<D>>;
};
template <int D>
struct BaseTerms<D, FluxBase::Leduc> {
  using type = TypeList<term::RiemannLeduc<D, false>>;
};
template <int D>
struct BaseTerms<D, FluxBase::LeducMuscl> {
  using type = TypeList<term::RiemannLeduc<D, true>>;
};
template <int D>
struct BaseTerms<D, FluxBase::Vila> {
  using type = TypeList<term::RiemannVila<D, false>>;
};
template <int D>
struct BaseTerms<D, FluxBase::VilaMuscl> {
  using type = TypeList<term::RiemannVila<D, true>>;
};

template <int D, PairViscosity V>
struct ViscousTerms {
  using type = TypeList<>;
};
template <int D>
struct ViscousTerms<D, PairViscosity::Morris> {
  using type = TypeList<term::MorrisViscosity>;
};
template <int D>
struct ViscousTerms<D, PairViscosity::ConsistentMorris> {  // no-slip NFM walls (kernels/ConsistentLaplacian.hpp)
  using type = TypeList<term::ConsistentMorrisViscosity<D>>;
};
template <int D>
struct ViscousTerms<D, PairViscosity::EddyMorris> {  // turbulence: nu + nu_T (kernels/terms/EddyMorrisViscosity.hpp)
  using type = TypeList<term::EddyMorrisViscosity<D>>;
};
template <int D>
struct ViscousTerms<D, PairViscosity::MonaghanGingold> {
  using type = TypeList<term::MonaghanGingoldViscosity>;
};

// the term pack of row I of the table: base, viscous term, artificial viscosity, background pressure
template <int D, std::size_t I>
using RowTerms = decltype(concat(typename BaseTerms<D, flux_schemes[I].key.base>::type{},
                                 typename ViscousTerms<D, flux_schemes[I].key.viscosity>::type{},
                                 std::conditional_t<flux_schemes[I].key.artificial_viscosity, TypeList<term::ArtificialViscosity>, TypeList<>>{},
                                 std::conditional_t<flux_schemes[I].key.background_pressure, TypeList<term::BackgroundPressure>, TypeList<>>{}));

// scheme.pair_list: half runs the packs whose every term has pair_both on the half list (the
// case reader keeps the full list for the others: resolve_pair_list)
template <int D, class Kernel, class... T>
void run_flux(const PassContext<D>& c) {
  using Pack = Terms<T...>;
  const FluxPass<D, Kernel, Pack> pass{c.list, c.box, Kernel(c.R), c.R * c.R, c.body, c.x, c.u, c.rho, c.P, c.m,
                                       c.du, c.drho, Pack(T::from(c)...), c.dm};
  if (c.scatter == nullptr) return pass.run(c.first, c.end);
  if constexpr (Pack::template symmetric<D>)
    SymmetricFluxPass<D, Kernel, Pack>{pass, c.half_list, c.scatter, c.first, c.end}.run();
  else
    throw std::logic_error("scheme.pair_list: half: the flux terms " + Pack::names() + " have no half-list form");
}

template <int D, class Kernel, class... T>
PassFunction<D> flux_of(TypeList<T...>) {
  return &run_flux<D, Kernel, T...>;
}

template <int D, class Kernel, std::size_t... I>
PassFunction<D> flux_row(int row, std::index_sequence<I...>) {
  static const PassFunction<D> rows[] = {flux_of<D, Kernel>(RowTerms<D, I>{})...};
  return rows[row];
}

}  // namespace detail

// The flux pass of this scene's named scheme (kernel type fixed by the caller); a scheme not in
// the table is refused, naming its keys (the case reader refuses it first, with the file's line).
template <int D, class Kernel>
PassFunction<D> select_flux(const Scene& s) {
  const FluxKey key = flux_key(s);
  const int row = flux_scheme_index(key);
  if (row < 0)
    throw std::invalid_argument("scheme: no built flux scheme has the keys " + describe(key) +
                                "; the built schemes (scene/FluxSchemes.hpp) are:\n" + list_flux_schemes());
  return detail::flux_row<D, Kernel>(row, std::make_index_sequence<flux_schemes.size()>{});
}

}  // namespace ondine
