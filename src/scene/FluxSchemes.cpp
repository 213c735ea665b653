#include "scene/FluxSchemes.hpp"

#include <sstream>

namespace ondine {

FluxKey flux_key(const Scene& s) {
  FluxKey k;
  if (s.flux == FluxScheme::Riemann) {
    const bool vila = s.riemann_variant == RiemannVariant::Vila;
    k.base = vila ? (s.riemann_muscl ? FluxBase::VilaMuscl : FluxBase::Vila) : (s.riemann_muscl ? FluxBase::LeducMuscl : FluxBase::Leduc);
  } else {
    k.base = s.delta_sph > 0 ? FluxBase::CentredDeltaSph : FluxBase::Centred;
  }
  switch (s.viscous_term) {
    case ViscousTerm::Morris:
      k.viscosity = s.turbulence.eddy_viscous()      ? PairViscosity::EddyMorris
                    : uses_consistent_laplacian(s) ? PairViscosity::ConsistentMorris
                                                   : PairViscosity::Morris;
      break;
    case ViscousTerm::MonaghanGingold: k.viscosity = PairViscosity::MonaghanGingold; break;
    case ViscousTerm::None: break;
  }
  k.artificial_viscosity = s.artificial_viscosity > 0;
  k.background_pressure = s.background_pressure;
  return k;
}

std::string describe(const FluxKey& k) {
  static const char* const base[] = {
      "scheme.flux: delta_sph, scheme.delta_sph: 0",
      "scheme.flux: delta_sph, scheme.delta_sph > 0",
      "scheme.flux: riemann, scheme.riemann.variant: leduc, scheme.riemann.reconstruction: none",
      "scheme.flux: riemann, scheme.riemann.variant: leduc, scheme.riemann.reconstruction: muscl",
      "scheme.flux: riemann, scheme.riemann.variant: vila, scheme.riemann.reconstruction: none",
      "scheme.flux: riemann, scheme.riemann.variant: vila, scheme.riemann.reconstruction: muscl"};
  static const char* const viscosity[] = {
      "scheme.viscous_term: none", "scheme.viscous_term: morris",
      "scheme.viscous_term: morris with scheme.consistent_laplacian: true and a no-slip wall",
      "scheme.viscous_term: monaghan_gingold", "scheme.viscous_term: morris with a turbulence.model"};
  std::ostringstream o;
  o << base[static_cast<int>(k.base)] << ", " << viscosity[static_cast<int>(k.viscosity)]
    << (k.artificial_viscosity ? ", scheme.artificial_viscosity > 0" : ", scheme.artificial_viscosity: 0")
    << ", scheme.background_pressure: " << (k.background_pressure ? "true" : "false");
  return o.str();
}

int flux_scheme_index(const FluxKey& k) {
  for (std::size_t i = 0; i < flux_schemes.size(); ++i)
    if (flux_schemes[i].key == k) return static_cast<int>(i);
  return -1;
}

std::string list_flux_schemes() {
  std::ostringstream o;
  for (const NamedFluxScheme& s : flux_schemes) o << "  " << s.name << ": " << describe(s.key) << "\n";
  return o.str();
}

}  // namespace ondine
