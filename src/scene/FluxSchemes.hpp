#pragma once
// The named flux schemes: the combinations of pair terms that Ondine compiles, as data. A
// scene's scheme keys (scheme.flux, scheme.riemann.variant and .reconstruction,
// scheme.delta_sph, scheme.viscous_term with scheme.consistent_laplacian, scheme.artificial_viscosity,
// scheme.background_pressure) select one key; the case reader refuses a key that is not in
// the table, naming the keys, and the solver (solver/FluxDispatch.hpp) instantiates one pair
// loop per row and per dimension and kernel, nothing else.
#include <array>
#include <string>

#include "scene/Scene.hpp"

namespace ondine {

// the pressure and continuity part: centred (2.47, 2.50), with delta-SPH (2.60), or Riemann-SPH
// in Leduc's form (2.90-2.101) or Vila's ALE form (2.84-2.89), first order or with MUSCL (2.78)
enum class FluxBase { Centred, CentredDeltaSph, Leduc, LeducMuscl, Vila, VilaMuscl };
// the fluid viscous term: Morris (2.54), its consistent form next to no-slip walls, Monaghan-Gingold (2.56),
// Morris with the eddy viscosity nu + nu_T of a turbulence model (V&I §4.1.1)
enum class PairViscosity { None, Morris, ConsistentMorris, MonaghanGingold, EddyMorris };

struct FluxKey {
  FluxBase base = FluxBase::Centred;
  PairViscosity viscosity = PairViscosity::None;
  bool artificial_viscosity = false;  // (2.58)
  bool background_pressure = false;   // (2.105)
  constexpr bool operator==(const FluxKey& o) const {
    return base == o.base && viscosity == o.viscosity && artificial_viscosity == o.artificial_viscosity &&
           background_pressure == o.background_pressure;
  }
};

struct NamedFluxScheme {
  const char* name;
  FluxKey key;
};

// The built schemes: those the shipped cases, the validation runs (under every --flux and
// --transport: `ondine validate --dry-run`) and the tests use, out of the 96 combinations of
// the keys. Adding a row adds its pair loop to the build (6 per row: 2 dimensions x 3 kernels).
inline constexpr std::array<NamedFluxScheme, 31> flux_schemes{{
    {"centred", {FluxBase::Centred, PairViscosity::None, false, false}},
    {"centred+morris", {FluxBase::Centred, PairViscosity::Morris, false, false}},
    {"centred+consistent_morris", {FluxBase::Centred, PairViscosity::ConsistentMorris, false, false}},
    {"centred+monaghan_gingold+background_pressure", {FluxBase::Centred, PairViscosity::MonaghanGingold, false, true}},
    {"delta_sph", {FluxBase::CentredDeltaSph, PairViscosity::None, false, false}},
    {"delta_sph+av", {FluxBase::CentredDeltaSph, PairViscosity::None, true, false}},
    {"delta_sph+morris", {FluxBase::CentredDeltaSph, PairViscosity::Morris, false, false}},
    {"delta_sph+morris+av", {FluxBase::CentredDeltaSph, PairViscosity::Morris, true, false}},
    {"delta_sph+morris+background_pressure", {FluxBase::CentredDeltaSph, PairViscosity::Morris, false, true}},
    {"delta_sph+morris+av+background_pressure", {FluxBase::CentredDeltaSph, PairViscosity::Morris, true, true}},
    {"delta_sph+consistent_morris", {FluxBase::CentredDeltaSph, PairViscosity::ConsistentMorris, false, false}},
    {"delta_sph+consistent_morris+background_pressure", {FluxBase::CentredDeltaSph, PairViscosity::ConsistentMorris, false, true}},
    {"delta_sph+eddy_morris", {FluxBase::CentredDeltaSph, PairViscosity::EddyMorris, false, false}},
    {"delta_sph+eddy_morris+av", {FluxBase::CentredDeltaSph, PairViscosity::EddyMorris, true, false}},
    {"delta_sph+monaghan_gingold+av", {FluxBase::CentredDeltaSph, PairViscosity::MonaghanGingold, true, false}},
    {"riemann+av", {FluxBase::Leduc, PairViscosity::None, true, false}},
    {"riemann+monaghan_gingold+av", {FluxBase::Leduc, PairViscosity::MonaghanGingold, true, false}},
    {"riemann_muscl", {FluxBase::LeducMuscl, PairViscosity::None, false, false}},
    {"riemann_muscl+av", {FluxBase::LeducMuscl, PairViscosity::None, true, false}},
    {"riemann_muscl+morris", {FluxBase::LeducMuscl, PairViscosity::Morris, false, false}},
    {"riemann_muscl+morris+background_pressure", {FluxBase::LeducMuscl, PairViscosity::Morris, false, true}},
    {"riemann_muscl+consistent_morris", {FluxBase::LeducMuscl, PairViscosity::ConsistentMorris, false, false}},
    {"riemann_muscl+consistent_morris+background_pressure", {FluxBase::LeducMuscl, PairViscosity::ConsistentMorris, false, true}},
    {"riemann_muscl+monaghan_gingold", {FluxBase::LeducMuscl, PairViscosity::MonaghanGingold, false, false}},
    {"vila+monaghan_gingold", {FluxBase::Vila, PairViscosity::MonaghanGingold, false, false}},
    {"vila_muscl", {FluxBase::VilaMuscl, PairViscosity::None, false, false}},
    {"vila_muscl+av", {FluxBase::VilaMuscl, PairViscosity::None, true, false}},
    {"vila_muscl+morris", {FluxBase::VilaMuscl, PairViscosity::Morris, false, false}},
    {"vila_muscl+morris+background_pressure", {FluxBase::VilaMuscl, PairViscosity::Morris, false, true}},
    {"vila_muscl+consistent_morris", {FluxBase::VilaMuscl, PairViscosity::ConsistentMorris, false, false}},
    {"vila_muscl+consistent_morris+background_pressure", {FluxBase::VilaMuscl, PairViscosity::ConsistentMorris, false, true}},
}};

// the key of a scene's scheme options
FluxKey flux_key(const Scene& s);
// the key in the case file's words ("scheme.flux: riemann, scheme.riemann.reconstruction: muscl, ...")
std::string describe(const FluxKey& k);
// the row of the key in flux_schemes, or -1
int flux_scheme_index(const FluxKey& k);
// every row's name and keys, one per line, for messages and docs
std::string list_flux_schemes();

}  // namespace ondine
