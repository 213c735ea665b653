#include <algorithm>
#include <cmath>
#include <sstream>

#include "scene/CaseSections.hpp"
#include "scene/FluxSchemes.hpp"

#include "scene/MemoryEstimate.hpp"

namespace ondine::case_file {

namespace {

KernelType kernel_of(const std::string& s) {
  if (s == "quartic_spline") return KernelType::QuarticSpline;
  if (s == "cubic_spline") return KernelType::CubicSpline;
  return KernelType::WendlandC2;
}

}  // namespace

void read_name_and_dimension(const Reader& r, YAML::Node& root, const std::string& path, Scene& s) {
  if (root["name"]) {
    s.name = r.text(root["name"], "name", "a case name");
    if (s.name.find_first_of("/\\ ") != std::string::npos)
      r.fail(root["name"], "name", "expected a name without spaces or slashes");
  } else {
    const auto slash = path.find_last_of('/');
    std::string stem = path.substr(slash == std::string::npos ? 0 : slash + 1);
    s.name = stem.substr(0, stem.rfind('.'));
  }
  s.dimension = static_cast<int>(r.integer(r.required(root, "", "dimension"), "dimension", 2, 3));
}

void read_domain(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  const YAML::Node dom = r.required(root, "", "domain");
  r.only_keys(dom, "domain", {"min", "max", "periodic"});
  s.domain.min = r.vector(r.required(dom, "domain", "min"), "domain.min", D, " (m)");
  s.domain.max = r.vector(r.required(dom, "domain", "max"), "domain.max", D, " (m)");
  for (int k = 0; k < D; ++k)
    if (!(s.domain.max[k] > s.domain.min[k]))
      r.fail(dom["max"], "domain.max", "expected domain.max > domain.min in every axis");
  if (dom["periodic"]) s.periodic = r.flags(dom["periodic"], "domain.periodic", D);
}

void read_discretisation(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  const YAML::Node dom = root["domain"];
  const YAML::Node disc = r.required(root, "", "discretisation");
  r.only_keys(disc, "discretisation", {"dx", "kernel", "R_over_dx", "reorder_interval", "neighbour_skin",
                                       "wall_quadrature_spacing", "wall_quadrature_spacing_dx"});
  s.dx = r.positive(r.required(disc, "discretisation", "dx"), "discretisation.dx", " (m)");
  if (disc["kernel"])
    s.kernel = kernel_of(r.word(disc["kernel"], "discretisation.kernel", {"wendland_c2", "quartic_spline", "cubic_spline"}));
  if (disc["R_over_dx"]) {
    s.R_over_dx = r.positive(disc["R_over_dx"], "discretisation.R_over_dx", "");
    if (s.R_over_dx < 1.5 || s.R_over_dx > 6)
      r.fail(disc["R_over_dx"], "discretisation.R_over_dx", "expected a value in [1.5, 6] (the thesis uses 2.5 to 4)");
  }
  if (disc["reorder_interval"])
    s.reorder_interval = static_cast<int>(r.integer(disc["reorder_interval"], "discretisation.reorder_interval", 0, 1000000));
  if (disc["wall_quadrature_spacing"])
    s.wall_quadrature_spacing = r.positive(disc["wall_quadrature_spacing"], "discretisation.wall_quadrature_spacing", " (m)");
  if (disc["wall_quadrature_spacing_dx"]) {
    if (disc["wall_quadrature_spacing"])
      r.fail(disc["wall_quadrature_spacing_dx"], "discretisation.wall_quadrature_spacing_dx",
             "give the spacing either in metres (wall_quadrature_spacing) or in dx, not both");
    s.wall_quadrature_spacing_dx = r.positive(disc["wall_quadrature_spacing_dx"], "discretisation.wall_quadrature_spacing_dx", " (in dx)");
  }
  if (disc["neighbour_skin"]) s.neighbour_skin = r.non_negative(disc["neighbour_skin"], "discretisation.neighbour_skin", " (in dx)");
  for (int k = 0; k < D; ++k) {
    if (!s.periodic[k]) continue;
    const double L = s.domain.max[k] - s.domain.min[k];
    const double cut = s.R() + s.neighbour_skin * s.dx;
    if (L < 2 * cut)
      r.fail(dom["max"], "domain.max", "a periodic axis must be at least 2 (R + skin) = " + std::to_string(2 * cut) + " m long");
    if (std::abs(L / s.dx - std::round(L / s.dx)) > 1e-6 * (L / s.dx))
      r.fail(disc["dx"], "discretisation.dx", "expected a spacing that divides the periodic length " + std::to_string(L) +
                                                 " m of axis " + std::to_string(k) + " (a gap would open at the seam)");
  }
}

void read_fluid(const Reader& r, YAML::Node& root, Scene& s) {
  const YAML::Node fl = r.required(root, "", "fluid");
  r.only_keys(fl, "fluid", {"rho0", "sound_speed", "mach", "reference_velocity", "viscosity", "eos"});
  s.rho0 = r.positive(r.required(fl, "fluid", "rho0"), "fluid.rho0", " (kg/m^3)");
  if (fl["viscosity"]) s.nu = r.non_negative(fl["viscosity"], "fluid.viscosity", " (m^2/s)");
  if (fl["mach"]) {
    s.mach = r.positive(fl["mach"], "fluid.mach", "");
    if (s.mach > 0.3) r.fail(fl["mach"], "fluid.mach", "expected a Mach number <= 0.3 (weak compressibility, thesis 2.33-2.35)");
  }
  if (const YAML::Node e = fl["eos"]) {
    r.only_keys(e, "fluid.eos", {"law", "gamma", "background_pressure"});
    s.eos = r.word(r.required(e, "fluid.eos", "law"), "fluid.eos.law", {"tait", "linear"}) == "tait" ? EosLaw::Tait : EosLaw::Linear;
    if (e["gamma"]) s.tait_gamma = r.positive(e["gamma"], "fluid.eos.gamma", "");
    if (e["background_pressure"]) s.eos_background_pressure = r.non_negative(e["background_pressure"], "fluid.eos.background_pressure", " (Pa)");
  }
}

void read_forces(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  if (const YAML::Node f = root["forces"]) {
    r.only_keys(f, "forces", {"gravity", "body_force"});
    if (f["gravity"]) s.gravity = r.vector(f["gravity"], "forces.gravity", D, " (m/s^2)");
    if (f["body_force"]) s.body_force = r.vector(f["body_force"], "forces.body_force", D, " (m/s^2)");
  }
}

// scheme.flux and scheme.riemann, and the combinations Riemann-SPH does not support
static void read_flux(const Reader& r, const YAML::Node& sc, Scene& s) {
  if (sc["flux"]) s.flux = r.word(sc["flux"], "scheme.flux", {"delta_sph", "riemann"}) == "riemann" ? FluxScheme::Riemann : FluxScheme::DeltaSph;
  if (const YAML::Node rs = sc["riemann"]) {
    if (s.flux != FluxScheme::Riemann) r.fail(rs, "scheme.riemann", "is read with scheme.flux: riemann only");
    r.only_keys(rs, "scheme.riemann", {"variant", "reconstruction", "limiter", "dissipation"});
    if (rs["dissipation"])
      s.riemann_low_dissipation = r.word(rs["dissipation"], "scheme.riemann.dissipation", {"acoustic", "low"}) == "low";
    if (rs["variant"])
      s.riemann_variant = r.word(rs["variant"], "scheme.riemann.variant", {"leduc", "vila"}) == "vila" ? RiemannVariant::Vila : RiemannVariant::Leduc;
    if (rs["reconstruction"])
      s.riemann_muscl = r.word(rs["reconstruction"], "scheme.riemann.reconstruction", {"muscl", "none"}) == "muscl";
    if (rs["limiter"]) r.word(rs["limiter"], "scheme.riemann.limiter", {"minmod"});
  }
  if (s.flux != FluxScheme::Riemann) {
    if (s.ale)
      r.fail(sc["transport"], "scheme.transport",
             "ale is built on Riemann-SPH (thesis 2.84-2.89 and 2.101): set scheme.flux: riemann, or use shifting with delta_sph");
    return;
  }
  if (s.delta_sph > 0)
    r.fail(sc["delta_sph"], "scheme.delta_sph",
           "is the density diffusion of the delta_sph flux; with scheme.flux: riemann the Riemann solver (2.100) dissipates: remove it or set 0");
  if (s.renormalised_continuity)
    r.fail(sc["renormalised_continuity"], "scheme.renormalised_continuity",
           "replaces the centred continuity; with scheme.flux: riemann the density rate comes from the Riemann velocity (2.92): remove it");
  if (s.riemann_muscl && s.density_gradient_once_per_step)
    r.fail(sc["density_gradient"], "scheme.density_gradient",
           "step is not supported with scheme.flux: riemann and MUSCL, whose reconstruction (2.78) reads the gradients of every stage; use stage");
}

void read_scheme(const Reader& r, YAML::Node& root, Scene& s) {
  if (const YAML::Node sc = root["scheme"]) {
    r.only_keys(sc, "scheme", {"viscous_term", "delta_sph", "delta_sph_form", "artificial_viscosity", "background_pressure",
                               "time_integrator", "cfl", "shifting", "shifting_coefficient", "transport", "consistent_laplacian",
                               "wall_velocity_reconstruction", "wall_contact", "renormalised_continuity", "density_gradient", "flux",
                               "riemann", "ale", "pair_list"});
    if (sc["pair_list"]) s.half_pair_list = r.word(sc["pair_list"], "scheme.pair_list", {"full", "half"}) == "half";
    if (sc["renormalised_continuity"])
      s.renormalised_continuity = r.boolean(sc["renormalised_continuity"], "scheme.renormalised_continuity");
    if (sc["wall_contact"]) s.wall_contact = r.boolean(sc["wall_contact"], "scheme.wall_contact");
    if (sc["wall_velocity_reconstruction"])
      s.wall_velocity_reconstruction = r.boolean(sc["wall_velocity_reconstruction"], "scheme.wall_velocity_reconstruction");
    if (sc["viscous_term"]) {
      const std::string w = r.word(sc["viscous_term"], "scheme.viscous_term", {"none", "morris", "monaghan_gingold"});
      s.viscous_term = w == "morris" ? ViscousTerm::Morris : w == "monaghan_gingold" ? ViscousTerm::MonaghanGingold : ViscousTerm::None;
    }
    if (sc["delta_sph"]) {
      s.delta_sph = r.non_negative(sc["delta_sph"], "scheme.delta_sph", "");
      if (s.delta_sph >= 0.2) r.fail(sc["delta_sph"], "scheme.delta_sph", "expected 0 <= delta < 0.2 (stability bound of thesis 2.60)");
    }
    if (sc["delta_sph_form"]) {
      s.delta_sph_hydrostatic =
          r.word(sc["delta_sph_form"], "scheme.delta_sph_form", {"renormalised", "hydrostatic"}) == "hydrostatic";
      // (a delta_sph of 0 is accepted with it: an override that switches the term off, --flux riemann's)
      if (!sc["delta_sph"])
        r.fail(sc["delta_sph_form"], "scheme.delta_sph_form", "is the form of the delta-SPH term: set scheme.delta_sph > 0, or remove it");
    }
    if (sc["artificial_viscosity"]) s.artificial_viscosity = r.non_negative(sc["artificial_viscosity"], "scheme.artificial_viscosity", " (alpha)");
    if (sc["consistent_laplacian"]) s.consistent_laplacian = r.boolean(sc["consistent_laplacian"], "scheme.consistent_laplacian");
    if (sc["background_pressure"]) s.background_pressure = r.boolean(sc["background_pressure"], "scheme.background_pressure");
    // with a free surface the surface particles shift tangentially only; with NFM walls the
    // concentration gradient has its wall term (kernels/ShiftingPass.hpp)
    if (sc["shifting"]) s.shifting = r.boolean(sc["shifting"], "scheme.shifting");
    // scheme.transport: how the particles move; shifting: true is its older spelling
    if (const YAML::Node t = sc["transport"]) {
      const std::string w = r.word(t, "scheme.transport", {"lagrangian", "shifting", "ale"});
      if (sc["shifting"] && s.shifting != (w == "shifting"))
        r.fail(t, "scheme.transport", "disagrees with scheme.shifting; give one of the two");
      s.shifting = w == "shifting";
      s.ale = w == "ale";
    }
    // scheme.shifting_coefficient: c of (2.109), a number or stable (kernels/ShiftingStability.hpp);
    // read whatever the transport (an override may switch the shift off), used with shifting
    if (const YAML::Node c = sc["shifting_coefficient"]) {
      if (c.IsScalar() && c.Scalar() == "stable") {
        s.shifting_coefficient_stable = true;
      } else {
        s.shifting_coefficient = r.positive(c, "scheme.shifting_coefficient", " (c of x += -c R^2 grad C, thesis 2.109: 0.5) or stable");
        if (s.shifting_coefficient > 1)
          r.fail(c, "scheme.shifting_coefficient", "expected 0 < c <= 1 (the thesis' 0.5), or stable");
      }
    }
    // scheme.ale: the transport-velocity law's characteristic velocity U_char = Ma c0 (2.113)
    if (const YAML::Node a = sc["ale"]) {
      if (!s.ale) r.fail(a, "scheme.ale", "is read with scheme.transport: ale only");
      r.only_keys(a, "scheme.ale", {"mach", "cut_supports"});
      if (a["cut_supports"])
        s.ale_tangential_cut = r.word(a["cut_supports"], "scheme.ale.cut_supports", {"tangential", "free"}) == "tangential";
      if (a["mach"]) {
        s.ale_mach = r.non_negative(a["mach"], "scheme.ale.mach", " (U_char / c0 of thesis 2.113)");
        if (s.ale_mach <= 0 || s.ale_mach > 1) r.fail(a["mach"], "scheme.ale.mach", "expected 0 < Ma <= 1 (U_char = Ma c0 of thesis 2.113)");
      }
    }
    if (sc["time_integrator"])
      s.integrator = r.word(sc["time_integrator"], "scheme.time_integrator", {"rk4", "predictor_corrector"}) == "rk4"
                         ? TimeIntegrator::RK4 : TimeIntegrator::PredictorCorrector;
    if (sc["density_gradient"])
      s.density_gradient_once_per_step = r.word(sc["density_gradient"], "scheme.density_gradient", {"stage", "step"}) == "step";
    read_flux(r, sc, s);
    if (const YAML::Node c = sc["cfl"]) {
      r.only_keys(c, "scheme.cfl", {"acoustic", "viscous", "force"});
      if (c["acoustic"]) s.cfl_acoustic = r.positive(c["acoustic"], "scheme.cfl.acoustic", "");
      if (c["viscous"]) s.cfl_viscous = r.positive(c["viscous"], "scheme.cfl.viscous", "");
      if (c["force"]) s.cfl_force = r.positive(c["force"], "scheme.cfl.force", "");
    }
  }
}

// scheme.viscous_term and fluid.viscosity agree; the density gradient once per step is not
// taken with the consistent Laplacian (after the turbulence section, which rules it out)
void check_viscosity(const Reader& r, YAML::Node& root, const Scene& s) {
  const YAML::Node fl = root["fluid"];
  // the consistent Laplacian's weights come out of the gradient pass and follow the particles next to no-slip walls
  if (s.density_gradient_once_per_step && uses_consistent_laplacian(s))
    r.fail(root["scheme"]["density_gradient"], "scheme.density_gradient",
           "step is not supported with the consistent Laplacian (scheme.viscous_term morris with no-slip walls), whose weights the gradient pass solves at every stage; use stage, or scheme.consistent_laplacian: false");
  if (s.viscous_term != ViscousTerm::None && !(s.nu > 0))
    r.fail(fl, "fluid.viscosity", "scheme.viscous_term is set, so fluid.viscosity must be > 0");
  if (s.viscous_term == ViscousTerm::None && s.nu > 0)
    r.fail(fl["viscosity"], "fluid.viscosity", "is > 0 but scheme.viscous_term is none; choose morris or monaghan_gingold");
}

void resolve_pair_list(Scene& s, bool host_backend) {
  if (!s.half_pair_list) return;
  const FluxKey k = flux_key(s);  // the terms with a half-list form (pair_both: kernels/terms/*.hpp)
  const bool terms = (k.base == FluxBase::Centred || k.base == FluxBase::CentredDeltaSph) &&
                     (k.viscosity == PairViscosity::None || k.viscosity == PairViscosity::Morris);
  // on a GPU the full list stays (one thread per particle, no atomics), as LAMMPS' KOKKOS package
  // does by default there; the half list's scatter is its per-thread copies on the host
  s.half_pair_list = terms && s.refinement_zones.empty() && s.open_boundaries.empty() && host_backend;
}

void check_flux_scheme(const Reader& r, YAML::Node& root, const Scene& s) {
  const FluxKey k = flux_key(s);
  if (flux_scheme_index(k) >= 0) return;
  r.fail(root["scheme"], "scheme",
         "selects a flux scheme that is not built (" + describe(k) + "); the built ones are:\n" + list_flux_schemes() +
             "(a row of src/scene/FluxSchemes.hpp builds another)");
}

// sound speed: a number, or auto = reference_velocity / mach
void read_sound_speed(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  const YAML::Node fl = root["fluid"];
  double u_ref = -1;
  if (const YAML::Node u = fl["reference_velocity"]) {
    if (!(u.IsScalar() && u.Scalar() == "auto")) u_ref = r.positive(u, "fluid.reference_velocity", " (m/s) or auto");
  }
  if (u_ref < 0) {
    // auto: the largest of the initial speeds and the free-fall speed sqrt(2 |g| H) over the fluid height
    double g = 0, h = 0, u0 = 0;
    for (int k = 0; k < D; ++k) g += (s.gravity[k] + s.body_force[k]) * (s.gravity[k] + s.body_force[k]);
    g = std::sqrt(g);
    for (const FluidBlock& b : s.blocks) {
      // height of the block along gravity
      double hb = 0;
      for (int k = 0; k < D && g > 0; ++k) hb += std::abs(s.gravity[k] + s.body_force[k]) / g * (b.box.max[k] - b.box.min[k]);
      h = std::max(h, hb);
      double v2 = 0;
      for (int k = 0; k < D; ++k) v2 += b.velocity[k] * b.velocity[k];
      u0 = std::max({u0, std::sqrt(v2), b.tg_amplitude});
    }
    u_ref = std::max(u0, std::sqrt(2.0 * g * h));
  }
  s.reference_velocity = u_ref;
  const YAML::Node cs = fl["sound_speed"];
  if (cs && !(cs.IsScalar() && cs.Scalar() == "auto")) {
    s.c0 = r.positive(cs, "fluid.sound_speed", " (m/s) or auto");
  } else {
    if (!(u_ref > 0))
      r.fail(fl, "fluid.sound_speed", "is auto but the case has no velocity scale (no gravity, no initial velocity); give fluid.reference_velocity or a number");
    s.c0 = u_ref / s.mach;
  }
}

void read_time(const Reader& r, YAML::Node& root, Scene& s) {
  const YAML::Node t = r.required(root, "", "time");
  r.only_keys(t, "time", {"duration", "output_interval", "output_at", "snapshot_every", "max_steps", "damping"});
  s.duration = r.positive(r.required(t, "time", "duration"), "time.duration", " (s)");
  s.output_interval = r.positive(r.required(t, "time", "output_interval"), "time.output_interval", " (s)");
  if (t["damping"]) s.damping_time = r.non_negative(t["damping"], "time.damping", " (s)");
  if (t["max_steps"]) s.max_steps = r.integer(t["max_steps"], "time.max_steps", 1, 1LL << 50);
  if (t["output_at"]) s.output_at_next_step = r.word(t["output_at"], "time.output_at", {"exact", "next_step"}) == "next_step";
  if (t["snapshot_every"]) s.snapshot_every = static_cast<int>(r.integer(t["snapshot_every"], "time.snapshot_every", 1, 1000000));
}

// distributed runs (docs/parallel.md)
void read_parallel(const Reader& r, YAML::Node& root, Scene& s) {
  if (const YAML::Node par = root["parallel"]) {
    r.only_keys(par, "parallel", {"rebalance_threshold", "weight"});
    if (par["weight"]) s.balance_by_pairs = r.word(par["weight"], "parallel.weight", {"pairs", "particles"}) == "pairs";
    if (par["rebalance_threshold"]) {
      s.rebalance_threshold = r.positive(par["rebalance_threshold"], "parallel.rebalance_threshold", "");
      if (s.rebalance_threshold > 1)
        r.fail(par["rebalance_threshold"], "parallel.rebalance_threshold", "expected a value in (0, 1] (tau = min work / max work)");
    }
  }
}

// checkpoints (docs/parallel.md)
void read_checkpoint(const Reader& r, YAML::Node& root, Scene& s) {
  if (const YAML::Node cp = root["checkpoint"]) {
    r.only_keys(cp, "checkpoint", {"every_steps", "every_wall_seconds"});
    if (cp["every_steps"]) s.checkpoint_every_steps = r.integer(cp["every_steps"], "checkpoint.every_steps", 0, 1LL << 50);
    if (cp["every_wall_seconds"])
      s.checkpoint_every_wall_seconds = r.non_negative(cp["every_wall_seconds"], "checkpoint.every_wall_seconds", " (s)");
  }
}

// memory: refuse a case that cannot fit on this machine before anything is allocated
// (scene/MemoryEstimate.hpp: the particles, the refinement zones' bound, the walls)
void check_memory(const Reader& r, YAML::Node& root, const Scene& s) {
  const YAML::Node disc = root["discretisation"];
  const MemoryEstimate e = estimate_memory(s);
  const double per_rank = (e.particles + e.refined_particles) / e.ranks;
  if (e.bytes_here > 0.8 * e.machine_bytes || per_rank > 2147483647.0) {
    std::ostringstream m;
    m.precision(3);
    m << "the case needs about " << e.bytes_here / 1073741824.0 << " GiB on this machine, more than 80% of its "
      << e.machine_bytes / 1073741824.0 << " GiB, or more than 2^31 - 1 particles per rank (" << e.breakdown()
      << "); expected a larger dx" << (e.refined_particles > 0 ? ", smaller refinement zones" : "")
      << (e.ranks_here > 1 ? " or fewer ranks on this machine" : "");
    r.fail(disc["dx"], "discretisation.dx", m.str());
  }
}

}  // namespace ondine::case_file
