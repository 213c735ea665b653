#pragma once
// What a checkpoint records of the refinement zones, and the check that a restart uses
// the zones it was written with.
#include <string>

#include "io/Checkpoint.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// The refinement zones of a case as a checkpoint records them (attribute
// `refinement_zones`): the transition width, then one line per zone, each number with
// the fewest significant digits that read back as the same double. A restart requires
// the case's to be the same text.
std::string refinement_zone_text(const Scene& s);

// A checkpoint's APR state against the case: both or neither have refinement zones,
// and the same ones. Throws CheckpointError naming the file and the difference.
void check_refinement_restart(const Scene& scene, const CheckpointHeader& h, const std::string& path);
// After the checkpoint's own checks: the case is the one that wrote it (name, fluid.rho0, domain),
// and out_dir holds the snapshots that run wrote before the checkpoint (the series continues
// there). Throws CheckpointError naming the file and the key or the missing snapshot.
void check_restart_case(const Scene& scene, const CheckpointHeader& h, const std::string& path, const std::string& out_dir);

}  // namespace ondine
