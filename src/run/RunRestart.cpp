#include "run/RunRestart.hpp"

#include "io/SnapshotWriter.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace ondine {

namespace {

// the fewest significant digits that read back as the same double
std::string shortest(double v) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace

std::string refinement_zone_text(const Scene& s) {
  std::ostringstream o;
  auto vec = [&](const Vec3& v) {
    o << "[";
    for (int k = 0; k < s.dimension; ++k) o << (k ? ", " : "") << shortest(v[k]);
    o << "]";
  };
  o << "transition " << shortest(s.refinement_transition) << "\n";
  for (const RefinementZone& z : s.refinement_zones) {
    o << "zone " << z.name << ": level " << z.level << ", in "
      << (z.parent >= 0 ? s.refinement_zones[static_cast<std::size_t>(z.parent)].name : std::string("-")) << ", min ";
    vec(z.box.min);
    o << ", max ";
    vec(z.box.max);
    if (z.motion == ZoneMotion::Translation) {
      o << ", velocity ";
      vec(z.velocity);
    } else if (z.motion == ZoneMotion::Criterion) {
      o << ", follow " << (z.criterion == ZoneCriterion::Pressure ? "pressure" : "speed") << " every " << z.every << " in ";
      vec(z.search.min);
      o << " .. ";
      vec(z.search.max);
    } else {
      o << ", static";
    }
    o << "\n";
  }
  return o.str();
}

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

void check_refinement_restart(const Scene& scene, const CheckpointHeader& h, const std::string& path) {
  const CheckpointRefinement& a = h.refinement;
  const bool zones = !scene.refinement_zones.empty();
  if (zones && !a.present)
    throw CheckpointError(path + ": it has no refinement state (no attribute 'refinement_zones', no datasets birth_level, level, "
                          "guard, mother, parent_id): it was written by a run without refinement zones, and the case " +
                          scene.source_file + " has " + std::to_string(scene.refinement_zones.size()) +
                          (scene.refinement_zones.size() == 1 ? " zone" : " zones") + " (key 'refinement'); restart it with the case that wrote it, or start this case anew");
  if (!zones && a.present)
    throw CheckpointError(path + ": it was written by a run with refinement zones (it holds their APR fields and state), and the case " +
                          scene.source_file + " has none (no key 'refinement'); restart it with the case that wrote it");
  if (!zones) return;
  const std::string mine = refinement_zone_text(scene);
  if (mine == a.zones) return;
  const auto saved = lines_of(a.zones), ours = lines_of(mine);
  std::string what;
  for (std::size_t k = 0; k < std::max(saved.size(), ours.size()) && what.empty(); ++k) {
    if (k >= saved.size()) what = "the case has '" + ours[k] + "', the checkpoint no such zone";
    else if (k >= ours.size()) what = "the checkpoint has '" + saved[k] + "', the case no such zone";
    else if (saved[k] != ours[k]) what = "the checkpoint has '" + saved[k] + "', the case has '" + ours[k] + "'";
  }
  auto zones_count = [](std::size_t lines) { return std::to_string(lines - 1) + (lines == 2 ? " zone" : " zones"); };
  throw CheckpointError(path + ": it was written with other refinement zones than those of the case " + scene.source_file +
                        " (key 'refinement'): " + what + " (" + zones_count(saved.size()) + " in the checkpoint, " +
                        zones_count(ours.size()) + " in the case); a run with zones restarts with the zones it was written with");
}

void check_restart_case(const Scene& scene, const CheckpointHeader& h, const std::string& path, const std::string& out_dir) {
  const int D = scene.dimension;
  if (!h.case_name.empty() && h.case_name != scene.name)
    throw CheckpointError(path + ": written by the case named '" + h.case_name + "'; the case " + scene.source_file + " is named '" +
                          scene.name + "' (key 'name'); restart it with the case that wrote it (name: " + h.case_name + ")");
  if (h.rho0 > 0 && std::abs(h.rho0 - scene.rho0) > 1e-12 * scene.rho0)
    throw CheckpointError(path + ": written with fluid.rho0 = " + std::to_string(h.rho0) + " kg/m^3; the case " + scene.source_file +
                          " has " + std::to_string(scene.rho0) + " (key 'fluid.rho0'); restart it with the case that wrote it");
  if (h.domain.size() == 6) {
    double scale = 0;
    for (int k = 0; k < D; ++k) scale = std::max(scale, scene.domain.max[k] - scene.domain.min[k]);
    for (int k = 0; k < D; ++k)
      if (std::abs(h.domain[k] - scene.domain.min[k]) > 1e-12 * scale || std::abs(h.domain[3 + k] - scene.domain.max[k]) > 1e-12 * scale)
        throw CheckpointError(path + ": written with another domain box (axis " + std::to_string(k) + ": " + std::to_string(h.domain[k]) +
                              " to " + std::to_string(h.domain[3 + k]) + " m) than the case " + scene.source_file + " (" +
                              std::to_string(scene.domain.min[k]) + " to " + std::to_string(scene.domain.max[k]) +
                              " m, key 'domain'); restart it with the case that wrote it");
  }
  // the run's snapshot series goes on in its folder: the snapshots written before the checkpoint must be there
  // (checked here, before the folder is written to; SnapshotWriter::resume then reads them)
  const SnapshotWriter series(out_dir, scene.name);
  for (std::int64_t k = 0; k < h.snapshots; ++k) {
    const std::string snap = out_dir + "/" + series.file_name(static_cast<std::size_t>(k));
    if (!std::filesystem::exists(snap))
      throw CheckpointError(path + ": the run that wrote it had " + std::to_string(h.snapshots) + " snapshots, and " + snap +
                            " is missing: a restart continues that run's series in its own folder; give --out the folder that holds them");
  }
}


}  // namespace ondine
