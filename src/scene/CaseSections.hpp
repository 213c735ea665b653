#pragma once
// Internal to the case-file parser (src/scene/Case*.cpp); nothing outside src/scene
// includes it. One reader per section of the case file (docs/case-file.md), each
// filling its part of the scene and refusing what cannot run. parse_case
// (CaseFile.cpp) calls them in a fixed order, which decides the error a file with
// several faults gets first; later sections may check against earlier ones.
#include <yaml-cpp/yaml.h>

#include <string>

#include "scene/CaseReader.hpp"
#include "scene/Scene.hpp"

namespace ondine::case_file {

// A file named in a case file: a relative path is taken from the case file's folder, an
// absolute one as is.
inline std::string beside_case_file(const std::string& case_path, const std::string& rel) {
  const auto slash = case_path.find_last_of('/');
  return (!rel.empty() && rel[0] == '/') || slash == std::string::npos ? rel : case_path.substr(0, slash + 1) + rel;
}

// CaseSections.cpp: the settings
void read_name_and_dimension(const Reader& r, YAML::Node& root, const std::string& path, Scene& s);
void read_domain(const Reader& r, YAML::Node& root, Scene& s);
void read_discretisation(const Reader& r, YAML::Node& root, Scene& s);
void read_fluid(const Reader& r, YAML::Node& root, Scene& s);
void read_forces(const Reader& r, YAML::Node& root, Scene& s);
void read_scheme(const Reader& r, YAML::Node& root, Scene& s);
void check_viscosity(const Reader& r, YAML::Node& root, const Scene& s);
// the scheme keys select one of the named flux schemes (scene/FluxSchemes.hpp)
void check_flux_scheme(const Reader& r, YAML::Node& root, const Scene& s);
// scheme.pair_list: half is kept where the half-list pass is built (the centred fluxes with Morris
// viscosity or none, uniform runs without open boundaries) on a host backend (kernels/Fields.hpp);
// elsewhere, and on a GPU, the full list is used
void resolve_pair_list(Scene& s, bool host_backend);
void read_sound_speed(const Reader& r, YAML::Node& root, Scene& s);
void read_time(const Reader& r, YAML::Node& root, Scene& s);
void read_parallel(const Reader& r, YAML::Node& root, Scene& s);
void read_checkpoint(const Reader& r, YAML::Node& root, Scene& s);
void check_memory(const Reader& r, YAML::Node& root, const Scene& s);

// CaseTurbulence.cpp: the eddy-viscosity models and the log-law wall function (after the
// scheme and the walls, before the flux scheme's check)
void read_turbulence(const Reader& r, YAML::Node& root, Scene& s);

// CaseFluidBlocks.cpp: the initial fluid
void read_fluid_blocks(const Reader& r, YAML::Node& root, Scene& s);

// CaseWalls.cpp: NFM walls (and the kernel they need); `path` is the case file's,
// which wall files are relative to
void read_walls(const Reader& r, YAML::Node& root, const std::string& path, Scene& s);
// CaseWalls3d.cpp: the keys of one dimension's walls refused in the other (before the
// unknown-key check, for a message that says what that dimension expects), and a 3D
// wall's mesh (geometry, placement, checks, orientation into the fluid)
void refuse_wall_keys_of_other_dimension(const Reader& r, const YAML::Node& w, const std::string& key, int D);
void read_wall_mesh(const Reader& r, const YAML::Node& w, const std::string& key, const std::string& path, const Scene& s,
                    Wall& wall);

// CaseObservers.cpp: what a run measures and compares with
void read_probes(const Reader& r, YAML::Node& root, Scene& s);
void read_wall_sensors(const Reader& r, YAML::Node& root, Scene& s);
void read_wave_gauges(const Reader& r, YAML::Node& root, Scene& s);
void read_reference(const Reader& r, YAML::Node& root, Scene& s);

// CaseRefinement.cpp: adaptive particle refinement zones
void read_refinement(const Reader& r, YAML::Node& root, Scene& s);

// CaseOpenBoundaries.cpp: inlets and outlets (after the scheme, the sound speed and the zones)
void read_open_boundaries(const Reader& r, YAML::Node& root, Scene& s);

}  // namespace ondine::case_file
