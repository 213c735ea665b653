#include "scene/CaseFile.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <unistd.h>

namespace ondine {

namespace {

// Schema-driven reading of one YAML document, with messages that point at the
// offending line and key. Nodes created by --set carry no mark; messages name
// the override instead.
class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden)
      : file_(std::move(file)), overridden_(std::move(overridden)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& what) const {
    std::ostringstream m;
    if (overridden_.count(key)) {
      m << "--set " << key << ": " << what;
    } else {
      m << file_;
      const YAML::Mark mk = at.IsDefined() ? at.Mark() : YAML::Mark::null_mark();
      if (mk.line >= 0) m << ":" << mk.line + 1 << ":" << mk.column + 1;
      m << ": key '" << key << "': " << what;
    }
    throw CaseError(m.str());
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  static std::string shown(const YAML::Node& n) {
    if (n.IsScalar()) return "'" + n.Scalar() + "'";
    if (n.IsSequence()) return "a list";
    if (n.IsMap()) return "a mapping";
    return "nothing";
  }

  void only_keys(const YAML::Node& map, const std::string& path, std::initializer_list<const char*> keys) const {
    if (!map.IsMap()) fail(map, path.empty() ? "(top level)" : path, "expected a mapping, got " + shown(map));
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      bool ok = false;
      for (const char* a : keys) ok = ok || k == a;
      if (!ok) {
        std::string list;
        for (const char* a : keys) list += (list.empty() ? "" : ", ") + std::string(a);
        fail(it->first, join(path, k), "unknown key; expected one of: " + list);
      }
    }
  }

  YAML::Node required(const YAML::Node& map, const std::string& path, const char* key) const {
    const YAML::Node n = map[key];
    if (!n.IsDefined() || n.IsNull()) fail(map, join(path, key), "required key is missing");
    return n;
  }

  double number(const YAML::Node& n, const std::string& key, const std::string& expect = "a number") const {
    if (!n.IsScalar()) fail(n, key, "expected " + expect + ", got " + shown(n));
    double v;
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, key, "expected " + expect + ", got " + shown(n));
    }
    if (!std::isfinite(v)) fail(n, key, "expected " + expect + ", got " + shown(n));
    return v;
  }

  double positive(const YAML::Node& n, const std::string& key, const std::string& unit) const {
    const double v = number(n, key, "a positive number" + unit);
    if (!(v > 0)) fail(n, key, "expected a positive number" + unit + ", got " + shown(n));
    return v;
  }
  double non_negative(const YAML::Node& n, const std::string& key, const std::string& unit) const {
    const double v = number(n, key, "a number >= 0" + unit);
    if (v < 0) fail(n, key, "expected a number >= 0" + unit + ", got " + shown(n));
    return v;
  }

  long long integer(const YAML::Node& n, const std::string& key, long long lo, long long hi) const {
    const std::string expect = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!n.IsScalar()) fail(n, key, "expected " + expect + ", got " + shown(n));
    long long v;
    try {
      v = n.as<long long>();
    } catch (const YAML::Exception&) {
      fail(n, key, "expected " + expect + ", got " + shown(n));
    }
    if (v < lo || v > hi) fail(n, key, "expected " + expect + ", got " + shown(n));
    return v;
  }

  bool boolean(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, key, "expected true or false, got " + shown(n));
    try {
      return n.as<bool>();
    } catch (const YAML::Exception&) {
      fail(n, key, "expected true or false, got " + shown(n));
    }
  }

  std::string word(const YAML::Node& n, const std::string& key, std::initializer_list<const char*> choices) const {
    std::string list;
    for (const char* a : choices) list += (list.empty() ? "" : " | ") + std::string(a);
    if (!n.IsScalar()) fail(n, key, "expected one of " + list + ", got " + shown(n));
    const std::string s = n.Scalar();
    for (const char* a : choices)
      if (s == a) return s;
    fail(n, key, "expected one of " + list + ", got " + shown(n));
  }

  Vec3 vector(const YAML::Node& n, const std::string& key, int dim, const std::string& unit) const {
    const std::string expect = "a list of " + std::to_string(dim) + " numbers" + unit;
    if (!n.IsSequence() || static_cast<int>(n.size()) != dim) fail(n, key, "expected " + expect + ", got " + shown(n) + (n.IsSequence() ? " of " + std::to_string(n.size()) : ""));
    Vec3 v{0, 0, 0};
    for (int k = 0; k < dim; ++k) v[k] = number(n[k], key + "[" + std::to_string(k) + "]", "a number" + unit);
    return v;
  }

  std::array<bool, 3> flags(const YAML::Node& n, const std::string& key, int dim) const {
    if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
      fail(n, key, "expected a list of " + std::to_string(dim) + " booleans, got " + shown(n));
    std::array<bool, 3> v{false, false, false};
    for (int k = 0; k < dim; ++k) v[k] = boolean(n[k], key + "[" + std::to_string(k) + "]");
    return v;
  }

  std::string text(const YAML::Node& n, const std::string& key, const std::string& expect) const {
    if (!n.IsScalar() || n.Scalar().empty()) fail(n, key, "expected " + expect + ", got " + shown(n));
    return n.Scalar();
  }


 private:
  std::string file_;
  std::set<std::string> overridden_;
};

std::set<std::string> apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides) {
  std::set<std::string> keys;
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CaseError("--set " + o + ": expected key=value (e.g. --set discretisation.dx=0.01)");
    const std::string key = o.substr(0, eq);
    YAML::Node value;
    try {
      value = YAML::Load(o.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw CaseError("--set " + o + ": the value is not valid YAML (" + e.msg + ")");
    }
    // Walk the dotted path, creating mappings as needed; list items are addressed as key.N.
    std::vector<std::string> parts;
    std::stringstream ss(key);
    for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
    std::vector<YAML::Node> chain{root};
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      YAML::Node cur = chain.back();
      const bool index = !parts[i].empty() && parts[i].find_first_not_of("0123456789") == std::string::npos;
      if (cur.IsSequence() && index) {
        const std::size_t k = std::stoul(parts[i]);
        if (k >= cur.size()) throw CaseError("--set " + key + ": list index " + parts[i] + " is out of range");
        chain.push_back(cur[k]);
      } else {
        if (cur.IsScalar() || cur.IsSequence())
          throw CaseError("--set " + key + ": '" + (i == 0 ? std::string("(top level)") : parts[i - 1]) +
                          "' is not a mapping");
        chain.push_back(cur[parts[i]]);
      }
    }
    YAML::Node parent = chain.back();
    const std::string& last = parts.back();
    if (parent.IsScalar())
      throw CaseError("--set " + key + ": '" + (parts.size() > 1 ? parts[parts.size() - 2] : std::string("(top level)")) +
                      "' is not a mapping");
    if (parent.IsSequence() && last.find_first_not_of("0123456789") == std::string::npos) {
      const std::size_t k = std::stoul(last);
      if (k >= parent.size()) throw CaseError("--set " + key + ": list index " + last + " is out of range");
      parent[k] = value;
    } else {
      parent[last] = value;
    }
    keys.insert(key);
  }
  return keys;
}

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

KernelType kernel_of(const std::string& s) {
  if (s == "quartic_spline") return KernelType::QuarticSpline;
  if (s == "cubic_spline") return KernelType::CubicSpline;
  return KernelType::WendlandC2;
}

// Bytes per particle of the largest scheme (fields + RK4 stage copies + neighbour
// cells), a deliberately generous bound for the memory check.
constexpr double bytes_per_particle(int dim) { return 8.0 * (6.0 * dim + 12.0) + 64.0; }

}  // namespace

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

// yaml-cpp keeps both entries of a key written twice in a mapping and reads the
// first: a second `dx:` further down would be silently ignored. Refused instead.
static void reject_duplicate_keys(const YAML::Node& n, const std::string& path, const std::string& where) {
  if (n.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : n) {
      const std::string key = kv.first.Scalar();
      const std::string full = where.empty() ? key : where + "." + key;
      if (!seen.insert(key).second) {
        const YAML::Mark mk = kv.first.Mark();
        throw CaseError(path + ":" + std::to_string(mk.line + 1) + ":" + std::to_string(mk.column + 1) + ": key '" + full +
                        "': written twice in the same mapping; keep one");
      }
      reject_duplicate_keys(kv.second, path, full);
    }
  } else if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) reject_duplicate_keys(n[i], path, where + "[" + std::to_string(i) + "]");
  }
}

Scene parse_case(const std::string& text, const std::string& path, const std::vector<std::string>& overrides) {
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
                         "scheme", "time", "probes", "wave_gauges", "reference", "parallel", "checkpoint",
                         "refinement"});
  Scene s;
  s.source_file = path;
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
  const int D = s.dimension;

  // domain
  const YAML::Node dom = r.required(root, "", "domain");
  r.only_keys(dom, "domain", {"min", "max", "periodic"});
  s.domain.min = r.vector(r.required(dom, "domain", "min"), "domain.min", D, " (m)");
  s.domain.max = r.vector(r.required(dom, "domain", "max"), "domain.max", D, " (m)");
  for (int k = 0; k < D; ++k)
    if (!(s.domain.max[k] > s.domain.min[k]))
      r.fail(dom["max"], "domain.max", "expected domain.max > domain.min in every axis");
  if (dom["periodic"]) s.periodic = r.flags(dom["periodic"], "domain.periodic", D);

  // discretisation
  const YAML::Node disc = r.required(root, "", "discretisation");
  r.only_keys(disc, "discretisation", {"dx", "kernel", "R_over_dx", "reorder_interval", "neighbour_skin",
                                       "wall_quadrature_spacing"});
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

  // fluid
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

  // fluid blocks
  const YAML::Node blocks = r.required(root, "", "fluid_blocks");
  if (!blocks.IsSequence() || blocks.size() == 0)
    r.fail(blocks, "fluid_blocks", "expected a non-empty list of blocks (min, max, ...)");
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string key = "fluid_blocks[" + std::to_string(i) + "]";
    const YAML::Node b = blocks[i];
    r.only_keys(b, key, {"min", "max", "velocity", "pressure", "wall_clearance"});
    FluidBlock fb;
    fb.box.min = r.vector(r.required(b, key, "min"), key + ".min", D, " (m)");
    fb.box.max = r.vector(r.required(b, key, "max"), key + ".max", D, " (m)");
    for (int k = 0; k < D; ++k) {
      if (fb.box.min[k] < s.domain.min[k] - 1e-12 || fb.box.max[k] > s.domain.max[k] + 1e-12) {
        r.fail(fb.box.min[k] < s.domain.min[k] - 1e-12 ? b["min"] : b["max"],
               key + (fb.box.min[k] < s.domain.min[k] - 1e-12 ? ".min" : ".max"),
               "the block lies outside the domain (domain.min/max)");
      }
      if (std::llround((fb.box.max[k] - fb.box.min[k]) / s.dx) < 1)
        r.fail(b["max"], key + ".max", "empty fluid region: the block is thinner than half a particle spacing (dx = " + fmt(s.dx) + " m) in axis " + std::to_string(k));
    }
    if (const YAML::Node v = b["velocity"]) {
      if (v.IsMap()) {
        r.only_keys(v, key + ".velocity", {"taylor_green"});
        const YAML::Node tg = r.required(v, key + ".velocity", "taylor_green");
        r.only_keys(tg, key + ".velocity.taylor_green", {"amplitude", "wavelength"});
        if (D != 2) r.fail(v, key + ".velocity", "the Taylor-Green initial field is 2D only");
        fb.velocity_kind = InitialVelocity::TaylorGreen;
        fb.tg_amplitude = r.positive(r.required(tg, key + ".velocity.taylor_green", "amplitude"), key + ".velocity.taylor_green.amplitude", " (m/s)");
        fb.tg_wavelength = r.positive(r.required(tg, key + ".velocity.taylor_green", "wavelength"), key + ".velocity.taylor_green.wavelength", " (m)");
      } else {
        fb.velocity = r.vector(v, key + ".velocity", D, " (m/s)");
      }
    }
    if (const YAML::Node p = b["pressure"]) {
      const std::string w = r.word(p, key + ".pressure", {"zero", "hydrostatic", "taylor_green"});
      fb.pressure_kind = w == "hydrostatic" ? InitialPressure::Hydrostatic
                         : w == "taylor_green" ? InitialPressure::TaylorGreen : InitialPressure::Zero;
      if (fb.pressure_kind == InitialPressure::TaylorGreen && fb.velocity_kind != InitialVelocity::TaylorGreen)
        r.fail(p, key + ".pressure", "taylor_green pressure needs a taylor_green velocity");
    }
    if (const YAML::Node c = b["wall_clearance"]) {
      fb.wall_clearance = r.positive(c, key + ".wall_clearance", " (in units of dx)");
      if (fb.wall_clearance > 0.5)
        r.fail(c, key + ".wall_clearance",
               "expected a clearance in (0, 0.5] (in units of dx): the default 0.5 already keeps every lattice point at dx/2 or more");
    }
    for (std::size_t o = 0; o < s.blocks.size(); ++o) {
      bool overlap = true;
      for (int k = 0; k < D; ++k)
        overlap = overlap && fb.box.min[k] < s.blocks[o].box.max[k] - 0.5 * s.dx && s.blocks[o].box.min[k] < fb.box.max[k] - 0.5 * s.dx;
      if (overlap) r.fail(b, key, "overlaps fluid_blocks[" + std::to_string(o) + "]; blocks must not share volume");
    }
    s.blocks.push_back(fb);
  }

  // walls (NFM, 2D polylines)
  if (const YAML::Node ws = root["walls"]) {
    if (!ws.IsSequence()) r.fail(ws, "walls", "expected a list of walls");
    if (D != 2 && ws.size() > 0) r.fail(ws, "walls", "NFM walls are implemented in 2D only so far");
    for (std::size_t i = 0; i < ws.size(); ++i) {
      const std::string key = "walls[" + std::to_string(i) + "]";
      const YAML::Node w = ws[i];
      r.only_keys(w, key, {"name", "points", "file", "closed", "fluid_side", "condition", "motion"});
      Wall wall;
      wall.name = w["name"] ? r.text(w["name"], key + ".name", "a wall name") : "wall" + std::to_string(i);
      if (wall.name.find_first_of(", \"") != std::string::npos)
        r.fail(w["name"], key + ".name", "expected a name without commas, spaces or quotes (it heads CSV columns)");
      for (const Wall& o : s.walls)
        if (o.name == wall.name) r.fail(w["name"] ? w["name"] : w, key + ".name", "duplicate wall name '" + wall.name + "'");
      if (w["points"] && w["file"]) r.fail(w["file"], key + ".file", "give either points or file, not both");
      if (const YAML::Node pts = w["points"]) {
        if (!pts.IsSequence()) r.fail(pts, key + ".points", "expected a list of [x, y] points");
        for (std::size_t k = 0; k < pts.size(); ++k) {
          const Vec3 v = r.vector(pts[k], key + ".points[" + std::to_string(k) + "]", 2, " (m)");
          wall.points.push_back({v[0], v[1]});
        }
      } else if (const YAML::Node f = w["file"]) {
        const std::string rel = r.text(f, key + ".file", "a CSV file of x, y lines");
        const auto slash = path.find_last_of('/');
        const std::string file = (!rel.empty() && rel[0] == '/') || slash == std::string::npos ? rel : path.substr(0, slash + 1) + rel;
        std::ifstream in(file);
        if (!in) r.fail(f, key + ".file", "cannot open '" + file + "'");
        std::string line;
        for (int ln = 1; std::getline(in, line); ++ln) {
          const auto hash = line.find('#');
          if (hash != std::string::npos) line.erase(hash);
          for (char& c : line) if (c == ',' || c == ';' || c == '\t') c = ' ';
          std::istringstream ls(line);
          double x, y;
          std::string rest;
          if (!(ls >> x)) {
            if (line.find_first_not_of(' ') == std::string::npos) continue;  // blank line
            throw CaseError(file + ":" + std::to_string(ln) + ": expected two numbers 'x, y' (m), got '" + line + "'");
          }
          if (!(ls >> y) || (ls >> rest) || !std::isfinite(x) || !std::isfinite(y))
            throw CaseError(file + ":" + std::to_string(ln) + ": expected two numbers 'x, y' (m), got '" + line + "'");
          wall.points.push_back({x, y});
        }
      } else {
        r.fail(w, key + ".points", "required: points (a list of [x, y]) or file (a CSV of x, y lines)");
      }
      if (w["closed"]) wall.closed = r.boolean(w["closed"], key + ".closed");
      const std::size_t need = wall.closed ? 3 : 2;
      if (wall.points.size() < need)
        r.fail(w, key + ".points", "expected at least " + std::to_string(need) + " points for a" + (wall.closed ? " closed" : "n open") + " wall");
      const std::size_t nseg = wall.closed ? wall.points.size() : wall.points.size() - 1;
      for (std::size_t k = 0; k < nseg; ++k) {
        const auto& a = wall.points[k];
        const auto& b = wall.points[(k + 1) % wall.points.size()];
        if (std::hypot(b[0] - a[0], b[1] - a[1]) < 1e-9 * s.dx)
          r.fail(w["points"] ? w["points"] : w, key + ".points", "segment " + std::to_string(k) + " has zero length (repeated point)");
      }
      // along a periodic axis the wall's images one period away are added, so the wall
      // itself must lie within one period: a wall across the axis spans exactly one
      for (int k = 0; k < 2; ++k) {
        if (!s.periodic[k]) continue;
        const double tol = 1e-9 * (s.domain.max[k] - s.domain.min[k]);
        for (const auto& pt : wall.points)
          if (pt[k] < s.domain.min[k] - tol || pt[k] > s.domain.max[k] + tol)
            r.fail(w["points"] ? w["points"] : w, key + ".points",
                   std::string("a wall must lie within the domain along the periodic axis ") + "xyz"[k] +
                       " (its periodic images are added; a wall across the axis spans exactly one period)");
      }
      if (w["fluid_side"]) {
        const std::string side = wall.closed ? r.word(w["fluid_side"], key + ".fluid_side", {"inside", "outside"})
                                             : r.word(w["fluid_side"], key + ".fluid_side", {"left", "right"});
        wall.fluid_inside = side == "inside" || side == "left";
      } else {
        r.fail(w, key + ".fluid_side", wall.closed ? "required for a closed wall: inside (a tank) or outside (a body)"
                                                   : "required for an open wall: left or right of the direction of its points");
      }
      if (w["condition"])
        wall.condition = r.word(w["condition"], key + ".condition", {"no_slip", "slip"}) == "slip" ? WallCondition::Slip : WallCondition::NoSlip;
      if (const YAML::Node m = w["motion"]) {
        const std::string mk = key + ".motion";
        r.only_keys(m, mk, {"type", "velocity", "amplitude", "period"});
        const std::string type = r.word(r.required(m, mk, "type"), mk + ".type", {"fixed", "sliding", "translation", "oscillation"});
        if (type == "sliding" || type == "translation") {
          wall.motion = type == "sliding" ? WallMotion::Sliding : WallMotion::Translation;
          wall.velocity = r.vector(r.required(m, mk, "velocity"), mk + ".velocity", D, " (m/s)");
        } else if (type == "oscillation") {
          wall.motion = WallMotion::Oscillation;
          wall.amplitude = r.vector(r.required(m, mk, "amplitude"), mk + ".amplitude", D, " (m)");
          wall.period = r.positive(r.required(m, mk, "period"), mk + ".period", " (s)");
        }
      }
      s.walls.push_back(wall);
    }
  }

  if (!s.walls.empty() && s.kernel != KernelType::WendlandC2)
    r.fail(disc["kernel"], "discretisation.kernel", "NFM walls need wendland_c2: the analytical Shepard factor (thesis 4.55) is Wendland's");

  // forces
  if (const YAML::Node f = root["forces"]) {
    r.only_keys(f, "forces", {"gravity", "body_force"});
    if (f["gravity"]) s.gravity = r.vector(f["gravity"], "forces.gravity", D, " (m/s^2)");
    if (f["body_force"]) s.body_force = r.vector(f["body_force"], "forces.body_force", D, " (m/s^2)");
  }

  // scheme
  if (const YAML::Node sc = root["scheme"]) {
    r.only_keys(sc, "scheme", {"viscous_term", "delta_sph", "artificial_viscosity", "background_pressure",
                               "time_integrator", "cfl", "shifting", "consistent_laplacian",
                               "wall_velocity_reconstruction", "renormalised_continuity"});
    if (sc["renormalised_continuity"])
      s.renormalised_continuity = r.boolean(sc["renormalised_continuity"], "scheme.renormalised_continuity");
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
    if (sc["artificial_viscosity"]) s.artificial_viscosity = r.non_negative(sc["artificial_viscosity"], "scheme.artificial_viscosity", " (alpha)");
    if (sc["consistent_laplacian"]) s.consistent_laplacian = r.boolean(sc["consistent_laplacian"], "scheme.consistent_laplacian");
    if (sc["background_pressure"]) s.background_pressure = r.boolean(sc["background_pressure"], "scheme.background_pressure");
    if (sc["shifting"]) {
      s.shifting = r.boolean(sc["shifting"], "scheme.shifting");
      bool all_periodic = true;
      for (int k = 0; k < D; ++k) all_periodic = all_periodic && s.periodic[k];
      if (s.shifting && (!all_periodic || root["walls"]))
        r.fail(sc["shifting"], "scheme.shifting", "particle shifting is for flows without a free surface or wall; it needs every axis periodic and no walls (the free-surface treatment of shifting is not built yet)");
    }
    if (sc["time_integrator"])
      s.integrator = r.word(sc["time_integrator"], "scheme.time_integrator", {"rk4", "predictor_corrector"}) == "rk4"
                         ? TimeIntegrator::RK4 : TimeIntegrator::PredictorCorrector;
    if (const YAML::Node c = sc["cfl"]) {
      r.only_keys(c, "scheme.cfl", {"acoustic", "viscous", "force"});
      if (c["acoustic"]) s.cfl_acoustic = r.positive(c["acoustic"], "scheme.cfl.acoustic", "");
      if (c["viscous"]) s.cfl_viscous = r.positive(c["viscous"], "scheme.cfl.viscous", "");
      if (c["force"]) s.cfl_force = r.positive(c["force"], "scheme.cfl.force", "");
    }
  }
  if (s.viscous_term != ViscousTerm::None && !(s.nu > 0))
    r.fail(fl, "fluid.viscosity", "scheme.viscous_term is set, so fluid.viscosity must be > 0");
  if (s.viscous_term == ViscousTerm::None && s.nu > 0)
    r.fail(fl["viscosity"], "fluid.viscosity", "is > 0 but scheme.viscous_term is none; choose morris or monaghan_gingold");

  // sound speed: a number, or auto = reference_velocity / mach
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

  // time
  const YAML::Node t = r.required(root, "", "time");
  r.only_keys(t, "time", {"duration", "output_interval", "max_steps", "damping"});
  s.duration = r.positive(r.required(t, "time", "duration"), "time.duration", " (s)");
  s.output_interval = r.positive(r.required(t, "time", "output_interval"), "time.output_interval", " (s)");
  if (t["damping"]) s.damping_time = r.non_negative(t["damping"], "time.damping", " (s)");
  if (t["max_steps"]) s.max_steps = r.integer(t["max_steps"], "time.max_steps", 1, 1LL << 50);

  // distributed runs and checkpoints (docs/parallel.md)
  if (const YAML::Node par = root["parallel"]) {
    r.only_keys(par, "parallel", {"rebalance_threshold", "weight"});
    if (par["weight"]) s.balance_by_pairs = r.word(par["weight"], "parallel.weight", {"pairs", "particles"}) == "pairs";
    if (par["rebalance_threshold"]) {
      s.rebalance_threshold = r.positive(par["rebalance_threshold"], "parallel.rebalance_threshold", "");
      if (s.rebalance_threshold > 1)
        r.fail(par["rebalance_threshold"], "parallel.rebalance_threshold", "expected a value in (0, 1] (tau = min work / max work)");
    }
  }
  if (const YAML::Node cp = root["checkpoint"]) {
    r.only_keys(cp, "checkpoint", {"every_steps", "every_wall_seconds"});
    if (cp["every_steps"]) s.checkpoint_every_steps = r.integer(cp["every_steps"], "checkpoint.every_steps", 0, 1LL << 50);
    if (cp["every_wall_seconds"])
      s.checkpoint_every_wall_seconds = r.non_negative(cp["every_wall_seconds"], "checkpoint.every_wall_seconds", " (s)");
  }

  // the name of a probe or gauge: it heads CSV columns, so no separators, and unique
  auto csv_column_name = [&r](const YAML::Node& item, const std::string& key, const std::string& what,
                              const std::vector<std::string>& taken) {
    const std::string name = r.text(r.required(item, key, "name"), key + ".name", "a " + what + " name");
    if (name.find_first_of(", \"") != std::string::npos)
      r.fail(item["name"], key + ".name", "expected a name without commas, spaces or quotes (it heads CSV columns)");
    for (const std::string& t : taken)
      if (t == name) r.fail(item["name"], key + ".name", "duplicate " + what + " name '" + name + "'");
    return name;
  };

  // probes
  if (const YAML::Node pr = root["probes"]) {
    if (!pr.IsSequence()) r.fail(pr, "probes", "expected a list of {name, position}");
    for (std::size_t i = 0; i < pr.size(); ++i) {
      const std::string key = "probes[" + std::to_string(i) + "]";
      r.only_keys(pr[i], key, {"name", "position"});
      Probe p;
      std::vector<std::string> taken;
      for (const Probe& q : s.probes) taken.push_back(q.name);
      p.name = csv_column_name(pr[i], key, "probe", taken);
      p.position = r.vector(r.required(pr[i], key, "position"), key + ".position", D, " (m)");
      for (int k = 0; k < D; ++k)
        if (p.position[k] < s.domain.min[k] || p.position[k] > s.domain.max[k])
          r.fail(pr[i]["position"], key + ".position", "the probe lies outside the domain");
      s.probes.push_back(p);
    }
  }

  // wave gauges: vertical lines along the last axis
  if (const YAML::Node wg = root["wave_gauges"]) {
    if (!wg.IsSequence()) r.fail(wg, "wave_gauges", "expected a list of {name, position, bottom, top}");
    for (std::size_t i = 0; i < wg.size(); ++i) {
      const std::string key = "wave_gauges[" + std::to_string(i) + "]";
      r.only_keys(wg[i], key, {"name", "position", "bottom", "top"});
      WaveGauge g;
      std::vector<std::string> taken;
      for (const WaveGauge& q : s.wave_gauges) taken.push_back(q.name);
      g.name = csv_column_name(wg[i], key, "wave gauge", taken);
      const Vec3 p = r.vector(r.required(wg[i], key, "position"), key + ".position", D - 1, " (m, the horizontal coordinates)");
      for (int k = 0; k < D - 1; ++k) {
        g.position[k] = p[k];
        if (p[k] < s.domain.min[k] || p[k] > s.domain.max[k])
          r.fail(wg[i]["position"], key + ".position", "the gauge lies outside the domain");
      }
      g.bottom = r.number(r.required(wg[i], key, "bottom"), key + ".bottom", "a height (m)");
      g.top = r.number(r.required(wg[i], key, "top"), key + ".top", "a height (m)");
      if (!(g.top > g.bottom)) r.fail(wg[i]["top"], key + ".top", "expected top > bottom");
      s.wave_gauges.push_back(g);
    }
    if (!(s.gravity[D - 1] < 0))
      r.fail(wg, "wave_gauges", "wave gauges measure along the last axis: they need gravity pointing down it (forces.gravity)");
  }

  // reference solution
  if (const YAML::Node rf = root["reference"]) {
    r.only_keys(rf, "reference", {"type", "length", "origin", "velocity"});
    const std::string t = r.word(r.required(rf, "reference", "type"), "reference.type",
                                 {"poiseuille", "couette", "hydrostatic", "martin_moyce", "ghia_re100", "ghia_re1000"});
    s.reference.kind = t == "poiseuille" ? ReferenceKind::Poiseuille
                       : t == "couette" ? ReferenceKind::Couette
                       : t == "hydrostatic" ? ReferenceKind::Hydrostatic
                       : t == "martin_moyce" ? ReferenceKind::MartinMoyce
                       : t == "ghia_re100" ? ReferenceKind::GhiaRe100 : ReferenceKind::GhiaRe1000;
    s.reference.length = r.positive(r.required(rf, "reference", "length"), "reference.length", " (m)");
    if (rf["origin"]) s.reference.origin = r.vector(rf["origin"], "reference.origin", D, " (m)");
    if (D != 2) r.fail(rf, "reference", "these references are 2D");
    if ((s.reference.kind == ReferenceKind::Poiseuille || s.reference.kind == ReferenceKind::Couette) && !(s.nu > 0))
      r.fail(rf["type"], "reference.type", t + " needs fluid.viscosity > 0");
    if (s.reference.kind == ReferenceKind::Couette)
      s.reference.velocity = r.number(r.required(rf, "reference", "velocity"), "reference.velocity",
                                      "the speed along x of the wall at y = origin + length (m/s)");
    else if (rf["velocity"])
      r.fail(rf["velocity"], "reference.velocity", "only a couette reference takes a wall velocity");
  }

  // adaptive particle refinement (thesis 5.4, docs/apr.md): nested boxes, one level per depth
  if (const YAML::Node ref = root["refinement"]) {
    r.only_keys(ref, "refinement", {"zones", "transition", "guard_shifting", "mother_shifting"});
    if (ref["guard_shifting"]) s.refinement_guard_shifting = r.boolean(ref["guard_shifting"], "refinement.guard_shifting");
    if (ref["mother_shifting"]) s.refinement_mother_shifting = r.boolean(ref["mother_shifting"], "refinement.mother_shifting");
    if (ref["transition"]) {
      s.refinement_transition = r.positive(ref["transition"], "refinement.transition", " (in R of the coarser level)");
      if (s.refinement_transition < 0.5 || s.refinement_transition > 4.0)
        r.fail(ref["transition"], "refinement.transition",
               "expected a value in [0.5, 4] (the daughter guards must complete the fine supports: at least R_f = R_m / 2, i.e. 0.5; the thesis uses R_m, i.e. 1)");
    }
    if (s.shifting) r.fail(ref, "refinement", "particle shifting with refinement zones is not supported");
    if (s.renormalised_continuity)
      r.fail(ref, "refinement", "scheme.renormalised_continuity with refinement zones is not supported (the per-level flux does not run it)");
    // width of the daughter-guard layer of level l (in m): transition R_{l-1}
    auto layer = [&s](int level) { return s.refinement_transition * s.R() / std::ldexp(1.0, level - 1); };
    std::function<void(const YAML::Node&, const std::string&, int, int)> zones;
    zones = [&](const YAML::Node& list, const std::string& path, int level, int parent) {
      if (!list.IsSequence() || list.size() == 0) r.fail(list, path, "expected a non-empty list of zones {name, min, max}");
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string key = path + "[" + std::to_string(i) + "]";
        const YAML::Node z = list[i];
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
        // nesting: the zone and its daughter-guard layer inside the enclosing zone
        // (an enclosing zone that reaches a domain face does not constrain that side)
        if (parent >= 0) {
          const Box& pb = s.refinement_zones[parent].box;
          const double w = layer(level);
          for (int k = 0; k < D; ++k) {
            const bool lo_ok = pb.min[k] <= s.domain.min[k] || rz.box.min[k] - w >= pb.min[k];
            const bool hi_ok = pb.max[k] >= s.domain.max[k] || rz.box.max[k] + w <= pb.max[k];
            if (!lo_ok || !hi_ok) {
              std::ostringstream m;
              m << "the zone and its transition layer (" << w << " m) must lie inside the zone '"
                << s.refinement_zones[parent].name << "' that contains it";
              r.fail(z["min"], key + ".min", m.str());
            }
          }
        }
        // zones of one level must not overlap (a box inside another is a deeper level)
        for (const RefinementZone& o : s.refinement_zones) {
          if (o.level != level) continue;
          bool overlap = true;
          for (int k = 0; k < D; ++k) overlap = overlap && rz.box.min[k] < o.box.max[k] && o.box.min[k] < rz.box.max[k];
          if (overlap)
            r.fail(z["min"], key + ".min", "the zone overlaps zone '" + o.name + "' of the same level without being nested in it (nest it under 'zones:' of that zone)");
        }
        s.refinement_zones.push_back(rz);
        const int me = static_cast<int>(s.refinement_zones.size()) - 1;
        if (z["zones"]) zones(z["zones"], key + ".zones", level + 1, me);
      }
    };
    zones(r.required(ref, "refinement", "zones"), "refinement.zones", 1, -1);
  }

  // memory: refuse a particle count that cannot fit before anything is allocated
  double n = 0;
  for (const FluidBlock& b : s.blocks) {
    double c = 1;
    for (int k = 0; k < D; ++k) c *= std::round((b.box.max[k] - b.box.min[k]) / s.dx);
    n += c;
  }
  const double mem = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (n * bytes_per_particle(D) > 0.8 * mem || n > 2147483647.0) {
    std::ostringstream m;
    m.precision(3);
    m << "the fluid blocks need " << n << " particles (about " << n * bytes_per_particle(D) / 1073741824.0
      << " GiB), more than 80% of this machine's " << mem / 1073741824.0
      << " GiB or than 2^31 - 1 particles per rank; expected a larger dx";
    r.fail(disc["dx"], "discretisation.dx", m.str());
  }
  return s;
}

Scene load_case(const std::string& path, const std::vector<std::string>& overrides) {
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
std::string to_string(ViscousTerm v) {
  return v == ViscousTerm::Morris ? "morris" : v == ViscousTerm::MonaghanGingold ? "monaghan_gingold" : "none";
}
std::string to_string(TimeIntegrator t) { return t == TimeIntegrator::RK4 ? "rk4" : "predictor_corrector"; }

}  // namespace ondine
