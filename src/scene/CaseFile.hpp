#pragma once
#include <string>
#include <vector>

#include "scene/CaseError.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// Reads and validates a YAML case file (docs/case-file.md). `overrides` are
// "dotted.key=value" strings from --set, applied before validation.
// Throws CaseError with "FILE:LINE:COL: key 'a.b': expected ..., got ...".
Scene load_case(const std::string& path, const std::vector<std::string>& overrides = {});

// Same, from YAML text (`path` is only used in messages).
Scene parse_case(const std::string& yaml_text, const std::string& path,
                 const std::vector<std::string>& overrides = {});

// Number of particles the fluid blocks will hold (validated scene).
std::size_t count_particles(const Scene& scene);

}  // namespace ondine
