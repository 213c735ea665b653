#include "scene/CaseFile.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kernels/Fields.hpp"
#include "scene/CaseReader.hpp"
#include "scene/CaseSections.hpp"

namespace ondine {

std::size_t count_particles(const Scene& s) {
  std::size_t n = 0;
  for (const FluidBlock& b : s.blocks) {
    std::size_t c = 1;
    for (int k = 0; k < s.dimension; ++k)
      c *= static_cast<std::size_t>(std::llround((b.box.max[k] - b.box.min[k]) / s.dx));
    n += c;
  }
  return n;
}

// The sections are read in this order, which decides the error a file with several
// faults gets first; a section may check against those read before it.
Scene parse_case(const std::string& text, const std::string& path, const std::vector<std::string>& overrides) {
  using namespace case_file;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw CaseError(path + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                    ": not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw CaseError(path + ": expected a YAML mapping at the top level (see docs/case-file.md)");
  reject_duplicate_keys(root, path, "");
  const Reader r(path, apply_overrides(root, overrides));

  r.only_keys(root, "", {"name", "dimension", "domain", "fluid", "discretisation", "fluid_blocks", "walls", "forces",
                         "scheme", "time", "probes", "wall_sensors", "wave_gauges", "reference", "parallel", "checkpoint",
                         "refinement", "open_boundaries", "turbulence"});
  Scene s;
  s.source_file = path;
  read_name_and_dimension(r, root, path, s);
  read_domain(r, root, s);
  read_discretisation(r, root, s);
  read_fluid(r, root, s);
  read_fluid_blocks(r, root, s);
  read_walls(r, root, path, s);
  read_forces(r, root, s);
  read_scheme(r, root, s);
  read_turbulence(r, root, s);
  check_viscosity(r, root, s);
  check_flux_scheme(r, root, s);
  read_sound_speed(r, root, s);
  read_time(r, root, s);
  read_parallel(r, root, s);
  read_checkpoint(r, root, s);
  read_probes(r, root, s);
  read_wall_sensors(r, root, s);
  read_wave_gauges(r, root, s);
  read_reference(r, root, s);
  read_refinement(r, root, s);
  read_open_boundaries(r, root, s);
  resolve_pair_list(s, host_backend);
  check_memory(r, root, s);
  return s;
}

Scene load_case(const std::string& path, const std::vector<std::string>& overrides) {
  if (std::filesystem::is_directory(path)) throw CaseError(path + ": is a folder; expected a YAML case file");
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open the case file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_case(ss.str(), path, overrides);
}

std::string to_string(KernelType k) {
  switch (k) {
    case KernelType::WendlandC2: return "wendland_c2";
    case KernelType::QuarticSpline: return "quartic_spline";
    case KernelType::CubicSpline: return "cubic_spline";
  }
  return "?";
}
std::string to_string(EosLaw e) { return e == EosLaw::Tait ? "tait" : "linear"; }
std::string to_string(FluxScheme f) { return f == FluxScheme::Riemann ? "riemann" : "delta_sph"; }
std::string to_string(ViscousTerm v) {
  return v == ViscousTerm::Morris ? "morris" : v == ViscousTerm::MonaghanGingold ? "monaghan_gingold" : "none";
}
std::string to_string(TimeIntegrator t) { return t == TimeIntegrator::RK4 ? "rk4" : "predictor_corrector"; }

}  // namespace ondine
