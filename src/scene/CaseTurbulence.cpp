// turbulence: the eddy-viscosity models of Violeau & Issa (seed 000 §4.1.1) and the log-law
// wall function (docs/case-file.md "turbulence").
#include "scene/CaseSections.hpp"

namespace ondine::case_file {

void read_turbulence(const Reader& r, YAML::Node& root, Scene& s) {
  const YAML::Node t = root["turbulence"];
  if (!t) return;
  const int D = s.dimension;
  r.only_keys(t, "turbulence", {"model", "kappa", "mixing_length", "smagorinsky_constant", "wall_function", "roughness", "k_epsilon", "langevin"});
  Turbulence& m = s.turbulence;
  const std::string model = r.word(r.required(t, "turbulence", "model"), "turbulence.model", {"none", "mixing_length", "smagorinsky", "k_epsilon", "langevin"});
  m.model = model == "mixing_length" ? TurbulenceModel::MixingLength
            : model == "smagorinsky" ? TurbulenceModel::Smagorinsky
            : model == "k_epsilon"   ? TurbulenceModel::KEpsilon
            : model == "langevin"    ? TurbulenceModel::Langevin
                                     : TurbulenceModel::None;
  const bool uses_length = m.model == TurbulenceModel::MixingLength || m.model == TurbulenceModel::Langevin;
  if (t["kappa"]) {
    m.kappa = r.positive(t["kappa"], "turbulence.kappa", " (von Karman's constant)");
    if (m.kappa > 1) r.fail(t["kappa"], "turbulence.kappa", "expected a value in (0, 1] (0.41 in the log law)");
  }
  if (const YAML::Node l = t["mixing_length"]) {
    if (!uses_length) r.fail(l, "turbulence.mixing_length", "is read with turbulence.model: mixing_length or langevin only");
    r.only_keys(l, "turbulence.mixing_length", {"length", "axis", "bed", "depth", "half_width"});
    if (l["length"]) {
      if (l["axis"] || l["bed"] || l["depth"] || l["half_width"])
        r.fail(l["length"], "turbulence.mixing_length.length", "give a constant length or the channel's axis, bed and depth, not both");
      m.length = r.positive(l["length"], "turbulence.mixing_length.length", " (m)");
    } else {
      const YAML::Node axis = r.required(l, "turbulence.mixing_length", "axis");
      m.axis = static_cast<int>(r.integer(axis, "turbulence.mixing_length.axis", 0, D - 1));
      m.bed = r.number(r.required(l, "turbulence.mixing_length", "bed"), "turbulence.mixing_length.bed", "the bed's coordinate along axis (m)");
      if (l["half_width"]) {  // a plane channel between walls at bed and bed + 2 h: z from the nearer wall, H = h
        if (l["depth"]) r.fail(l["half_width"], "turbulence.mixing_length.half_width", "give the open channel's depth or the plane channel's half_width, not both");
        m.depth = r.positive(l["half_width"], "turbulence.mixing_length.half_width", " (m, half the distance between the walls)");
        m.plane = true;
      } else {
        m.depth = r.positive(r.required(l, "turbulence.mixing_length", "depth"), "turbulence.mixing_length.depth", " (m, the flow depth H)");
      }
    }
  } else if (uses_length) {
    r.fail(t, "turbulence.mixing_length",
           "is required with turbulence.model: " + model + ": {length: L}, the open channel's {axis: k, bed: z0, depth: H} "
           "or the plane channel's {axis: k, bed: z0, half_width: h} (L_m = kappa z sqrt(1 - z/H))");
  }
  if (const YAML::Node g = t["langevin"]) {
    if (m.model != TurbulenceModel::Langevin) r.fail(g, "turbulence.langevin", "is read with turbulence.model: langevin only");
    r.only_keys(g, "turbulence.langevin", {"c1", "c2", "c0", "seed", "mean_gradient", "drift_mean", "noise"});
    if (g["c1"]) m.langevin_c1 = r.positive(g["c1"], "turbulence.langevin.c1", " (the drift's return to isotropy)");
    if (g["c2"]) m.langevin_c2 = r.non_negative(g["c2"], "turbulence.langevin.c2", " (the drift's isotropisation of production)");
    if (g["c0"]) m.langevin_c0 = r.positive(g["c0"], "turbulence.langevin.c0", " (the diffusion's constant)");
    if (g["mean_gradient"])
      m.langevin_averaged = r.word(g["mean_gradient"], "turbulence.langevin.mean_gradient", {"filtered", "averaged"}) == "averaged";
    if (g["drift_mean"])
      m.langevin_drift_mean_removed = r.word(g["drift_mean"], "turbulence.langevin.drift_mean", {"kept", "removed"}) == "removed";
    if (g["noise"]) m.langevin_solenoidal = r.word(g["noise"], "turbulence.langevin.noise", {"white", "solenoidal"}) == "solenoidal";
    if (g["seed"]) m.seed = static_cast<std::uint64_t>(r.integer(g["seed"], "turbulence.langevin.seed", 0, 9007199254740991LL));
  }
  if (m.model == TurbulenceModel::Langevin) {
    // C0 of Pope's consistency relation with the mixing length's P = epsilon (kernels/turbulence/Langevin.hpp)
    if (!(m.langevin_c0 > 0)) m.langevin_c0 = 2.0 / D * (m.langevin_c1 - 1.0 + m.langevin_c2);
    if (!(m.langevin_c0 > 0))
      r.fail(t["langevin"], "turbulence.langevin", "C0 = (2/d) (c1 - 1 + c2) must be positive: expected c1 + c2 > 1, or give c0");
  }
  if (t["smagorinsky_constant"]) {
    if (m.model != TurbulenceModel::Smagorinsky)
      r.fail(t["smagorinsky_constant"], "turbulence.smagorinsky_constant", "is read with turbulence.model: smagorinsky only");
    m.smagorinsky_constant = r.positive(t["smagorinsky_constant"], "turbulence.smagorinsky_constant", " (C_s)");
  }
  if (const YAML::Node k = t["k_epsilon"]) {
    if (m.model != TurbulenceModel::KEpsilon) r.fail(k, "turbulence.k_epsilon", "is read with turbulence.model: k_epsilon only");
    r.only_keys(k, "turbulence.k_epsilon", {"initial_k", "initial_epsilon", "c_mu", "c1", "c2", "sigma_k", "sigma_epsilon"});
    m.initial_k = r.positive(r.required(k, "turbulence.k_epsilon", "initial_k"), "turbulence.k_epsilon.initial_k", " (m^2/s^2)");
    m.initial_epsilon =
        r.positive(r.required(k, "turbulence.k_epsilon", "initial_epsilon"), "turbulence.k_epsilon.initial_epsilon", " (m^2/s^3)");
    if (k["c_mu"]) m.c_mu = r.positive(k["c_mu"], "turbulence.k_epsilon.c_mu", "");
    if (k["c1"]) m.c1 = r.positive(k["c1"], "turbulence.k_epsilon.c1", "");
    if (k["c2"]) m.c2 = r.positive(k["c2"], "turbulence.k_epsilon.c2", "");
    if (k["sigma_k"]) m.sigma_k = r.positive(k["sigma_k"], "turbulence.k_epsilon.sigma_k", "");
    if (k["sigma_epsilon"]) m.sigma_e = r.positive(k["sigma_epsilon"], "turbulence.k_epsilon.sigma_epsilon", "");
  } else if (m.model == TurbulenceModel::KEpsilon) {
    r.fail(t, "turbulence.k_epsilon", "is required with turbulence.model: k_epsilon: {initial_k: k0, initial_epsilon: epsilon0}");
  }
  if (t["wall_function"]) {
    const std::string w = r.word(t["wall_function"], "turbulence.wall_function", {"none", "smooth", "rough"});
    m.wall_function = w == "smooth" ? WallLaw::Smooth : w == "rough" ? WallLaw::Rough : WallLaw::None;
    if (m.wall_function != WallLaw::None && !has_no_slip_wall(s))
      r.fail(t["wall_function"], "turbulence.wall_function", "acts on no-slip walls, and the case has none");
  }
  if (t["roughness"]) {
    if (m.wall_function != WallLaw::Rough) r.fail(t["roughness"], "turbulence.roughness", "is read with turbulence.wall_function: rough only");
    m.roughness = r.positive(t["roughness"], "turbulence.roughness", " (m, the equivalent sand roughness k_s)");
  } else if (m.wall_function == WallLaw::Rough) {
    r.fail(t, "turbulence.roughness", "is required with turbulence.wall_function: rough (the equivalent sand roughness k_s, m)");
  }
  if (!m.on()) {
    if (m.wall_function != WallLaw::None) r.fail(t["wall_function"], "turbulence.wall_function", "needs a turbulence.model");
    return;
  }
  const YAML::Node sc = root["scheme"];
  if (s.viscous_term != ViscousTerm::Morris)
    r.fail(sc ? sc : t, "scheme.viscous_term",
           "must be morris with a turbulence model: the eddy viscosity nu + nu_T enters the Morris Laplacian");
  if (!s.refinement_zones.empty() || root["refinement"])
    r.fail(t, "turbulence", "is not built with refinement zones (the eddy viscosity is not interpolated on the guards)");
  if (root["open_boundaries"]) r.fail(t, "turbulence", "is not built with open boundaries (the buffers carry no eddy viscosity)");
}

}  // namespace ondine::case_file
