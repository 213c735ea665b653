#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "scene/CaseSections.hpp"

namespace ondine::case_file {

namespace {

// a zone moves with a velocity, follows a criterion inside a search box, or stays
void read_zone_motion(const Reader& r, const YAML::Node& z, const std::string& key, int D, int parent, RefinementZone& rz) {
  const int motions = (z["velocity"] ? 1 : 0) + (z["follow"] ? 1 : 0);
  if (motions > 1) r.fail(z, key, "a zone either moves with a velocity or follows a criterion, not both");
  if (parent >= 0 && motions > 0)
    r.fail(z["velocity"] ? z["velocity"] : z["follow"], key, "a nested zone moves with the zone that contains it; give the motion to the outermost zone");
  if (z["velocity"]) {
    rz.motion = ZoneMotion::Translation;
    rz.velocity = r.vector(z["velocity"], key + ".velocity", D, " (m/s)");
  }
  if (z["follow"]) {
    rz.motion = ZoneMotion::Criterion;
    rz.criterion = r.word(z["follow"], key + ".follow", {"pressure", "speed"}) == "pressure" ? ZoneCriterion::Pressure
                                                                                             : ZoneCriterion::Speed;
    rz.search.min = r.vector(r.required(z, key, "search_min"), key + ".search_min", D, " (m)");
    rz.search.max = r.vector(r.required(z, key, "search_max"), key + ".search_max", D, " (m)");
    for (int k = 0; k < D; ++k)
      if (!(rz.search.max[k] > rz.search.min[k])) r.fail(z["search_max"], key + ".search_max", "expected search_max > search_min in every axis");
    if (z["every"]) rz.every = static_cast<int>(r.integer(z["every"], key + ".every", 1, 1000000));
  } else if (z["search_min"] || z["search_max"] || z["every"]) {
    r.fail(z, key, "search_min, search_max and every belong to a zone with 'follow'");
  }
}

// nesting: the zone and its daughter-guard layer inside the enclosing zone
// (an enclosing zone that reaches a domain face does not constrain that side);
// zones of one level must not overlap (a box inside another is a deeper level)
void check_zone_placement(const Reader& r, const YAML::Node& z, const std::string& key, const Scene& s,
                          const RefinementZone& rz) {
  const int D = s.dimension;
  if (rz.parent >= 0) {
    const Box& pb = s.refinement_zones[rz.parent].box;
    // width of the daughter-guard layer of level l (in m): transition R_{l-1}
    const double w = s.refinement_transition * s.R() / std::ldexp(1.0, rz.level - 1);
    for (int k = 0; k < D; ++k) {
      const bool lo_ok = pb.min[k] <= s.domain.min[k] || rz.box.min[k] - w >= pb.min[k];
      const bool hi_ok = pb.max[k] >= s.domain.max[k] || rz.box.max[k] + w <= pb.max[k];
      if (!lo_ok || !hi_ok) {
        std::ostringstream m;
        m << "the zone and its transition layer (" << w << " m) must lie inside the zone '"
          << s.refinement_zones[rz.parent].name << "' that contains it";
        r.fail(z["min"], key + ".min", m.str());
      }
    }
  }
  for (const RefinementZone& o : s.refinement_zones) {
    if (o.level != rz.level) continue;
    bool overlap = true;
    for (int k = 0; k < D; ++k) overlap = overlap && rz.box.min[k] < o.box.max[k] && o.box.min[k] < rz.box.max[k];
    if (overlap)
      r.fail(z["min"], key + ".min", "the zone overlaps zone '" + o.name + "' of the same level without being nested in it (nest it under 'zones:' of that zone)");
  }
}

// one zone {name, min, max, ...} of level `level` inside zone `parent` (-1: none)
RefinementZone read_zone(const Reader& r, const YAML::Node& z, const std::string& key, int level, int parent, const Scene& s) {
  const int D = s.dimension;
  r.only_keys(z, key, {"name", "min", "max", "velocity", "follow", "search_min", "search_max", "every", "zones"});
  if (level > kMaxRefinementLevel)
    r.fail(z, key, "level " + std::to_string(level) + " is deeper than the " + std::to_string(kMaxRefinementLevel) +
                       " levels supported");
  if (static_cast<int>(s.refinement_zones.size()) >= kMaxRefinementZones)
    r.fail(z, key, "more than " + std::to_string(kMaxRefinementZones) + " refinement zones");
  RefinementZone rz;
  rz.level = level;
  rz.parent = parent;
  rz.name = r.text(r.required(z, key, "name"), key + ".name", "a zone name");
  for (const RefinementZone& o : s.refinement_zones)
    if (o.name == rz.name) r.fail(z["name"], key + ".name", "duplicate zone name '" + rz.name + "'");
  rz.box.min = r.vector(r.required(z, key, "min"), key + ".min", D, " (m)");
  rz.box.max = r.vector(r.required(z, key, "max"), key + ".max", D, " (m)");
  for (int k = 0; k < D; ++k) {
    if (!(rz.box.max[k] > rz.box.min[k])) r.fail(z["max"], key + ".max", "expected max > min in every axis");
    if (rz.box.max[k] <= s.domain.min[k] || rz.box.min[k] >= s.domain.max[k])
      r.fail(z["min"], key + ".min", "the zone lies outside the domain");
  }
  read_zone_motion(r, z, key, D, parent, rz);
  check_zone_placement(r, z, key, s, rz);
  return rz;
}

// a list of zones, each followed by the zones nested in it (depth first)
void read_zones(const Reader& r, const YAML::Node& list, const std::string& path, int level, int parent, Scene& s) {
  if (!list.IsSequence() || list.size() == 0) r.fail(list, path, "expected a non-empty list of zones {name, min, max}");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string key = path + "[" + std::to_string(i) + "]";
    const YAML::Node z = list[i];
    s.refinement_zones.push_back(read_zone(r, z, key, level, parent, s));
    const int me = static_cast<int>(s.refinement_zones.size()) - 1;
    if (z["zones"]) read_zones(r, z["zones"], key + ".zones", level + 1, me, s);
  }
}

// Two fluid blocks that meet at a face: the lattice of the one below the face ends dx/2 from it
// only when its extent along that axis is a whole multiple of dx (docs/case-file.md, "Lattice
// fill"); otherwise particle pairs lie dx/2 apart at the seam, and with refinement zones their
// daughters coincide (a non-finite state at the first step). Refused, naming the block.
void check_block_seams(const Reader& r, YAML::Node& root, const Scene& s) {
  const std::vector<FluidBlock>& b = s.blocks;
  for (std::size_t i = 0; i < b.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      for (int k = 0; k < s.dimension; ++k) {
        if (i == j || std::abs(b[i].box.max[k] - b[j].box.min[k]) > 1e-9 * s.dx) continue;
        bool touch = true;  // the two faces overlap
        for (int a = 0; a < s.dimension; ++a)
          if (a != k) touch = touch && b[i].box.min[a] < b[j].box.max[a] && b[j].box.min[a] < b[i].box.max[a];
        if (!touch) continue;
        for (const std::size_t q : {i, j}) {
          const double n = (b[q].box.max[k] - b[q].box.min[k]) / s.dx;
          if (std::abs(n - std::round(n)) < 1e-6) continue;
          std::ostringstream m;
          m << "meets fluid_blocks[" << (q == i ? j : i) << "] at " << "xyz"[k] << " = " << b[i].box.max[k]
            << " m, and with refinement zones its extent along " << "xyz"[k] << " must be a whole multiple of dx ("
            << s.dx << " m); it is " << n << " dx, which leaves particles dx/2 apart at the seam, whose daughters coincide";
          const std::string key = "fluid_blocks[" + std::to_string(q) + "]";
          r.fail(root["fluid_blocks"][q], key, m.str());
        }
      }
}

}  // namespace

// adaptive particle refinement (thesis 5.4, docs/apr.md): nested boxes, one level per depth
void read_refinement(const Reader& r, YAML::Node& root, Scene& s) {
  if (const YAML::Node ref = root["refinement"]) {
    r.only_keys(ref, "refinement", {"zones", "transition", "guard_shifting", "mother_shifting", "local_time_stepping", "adoption"});
    if (ref["guard_shifting"]) s.refinement_guard_shifting = r.boolean(ref["guard_shifting"], "refinement.guard_shifting");
    if (ref["mother_shifting"]) s.refinement_mother_shifting = r.boolean(ref["mother_shifting"], "refinement.mother_shifting");
    if (ref["transition"]) {
      s.refinement_transition = r.positive(ref["transition"], "refinement.transition", " (in R of the coarser level)");
      if (s.refinement_transition < 0.5 || s.refinement_transition > 4.0)
        r.fail(ref["transition"], "refinement.transition",
               "expected a value in [0.5, 4] (the daughter guards must complete the fine supports: at least R_f = R_m / 2, i.e. 0.5; the thesis uses R_m, i.e. 1)");
    }
    if (s.density_gradient_once_per_step)
      r.fail(ref, "refinement", "scheme.density_gradient: step with refinement zones is not supported (the guards' gradients are interpolated at every stage); use stage");
    if (s.flux == FluxScheme::Riemann)
      r.fail(ref, "refinement", "scheme.flux: riemann with refinement zones is not supported yet (the guards' velocity gradients of the MUSCL reconstruction are not interpolated); use delta_sph");
    if (s.renormalised_continuity)
      r.fail(ref, "refinement", "scheme.renormalised_continuity with refinement zones is not supported (the per-level flux does not run it)");
    if (ref["local_time_stepping"])
      s.refinement_local_time_stepping = r.boolean(ref["local_time_stepping"], "refinement.local_time_stepping");
    if (ref["adoption"]) s.refinement_adoption = r.boolean(ref["adoption"], "refinement.adoption");
    read_zones(r, r.required(ref, "refinement", "zones"), "refinement.zones", 1, -1, s);
    check_block_seams(r, root, s);
  }
}

}  // namespace ondine::case_file
