#include <vector>

#include <algorithm>
#include <cmath>

#include "reference/SensorSeries.hpp"
#include "reference/WedgeImpact.hpp"
#include "scene/CaseSections.hpp"

namespace ondine::case_file {

namespace {

// spheric_test2: the measured series (read now, so that a bad file stops the run before it
// starts) and the sensors it is compared with: probes P1 and P3, gauges H2 and H4
void read_spheric_reference(const Reader& r, const YAML::Node& rf, Scene& s) {
  const std::string rel = r.text(r.required(rf, "reference", "file"), "reference.file", "the CSV of the measured series");
  s.reference.file = beside_case_file(s.source_file, rel);
  try {
    reference::read_sensor_csv(s.reference.file, {"P1", "P3", "H2", "H4"});
  } catch (const std::exception& e) {
    r.fail(rf["file"], "reference.file", e.what());
  }
  for (const char* p : {"P1", "P3"})
    if (std::none_of(s.probes.begin(), s.probes.end(), [&](const Probe& q) { return q.name == p; }) &&
        std::none_of(s.wall_sensors.begin(), s.wall_sensors.end(), [&](const WallSensor& q) { return q.name == p; }))
      r.fail(rf["type"], "reference.type",
             std::string("spheric_test2 compares the pressure sensor named ") + p + ": add it to wall_sensors or probes");
  for (const char* h : {"H2", "H4"})
    if (std::none_of(s.wave_gauges.begin(), s.wave_gauges.end(), [&](const WaveGauge& g) { return g.name == h; }))
      r.fail(rf["type"], "reference.type", std::string("spheric_test2 compares the wave gauge named ") + h + ": add it to wave_gauges");
}

// wedge_impact: the similarity profile (read now, so that a bad file stops the run before it
// starts), U, the contact's time and point, the wall pushed, and the wall sensors along it
void read_wedge_reference(const Reader& r, const YAML::Node& rf, Scene& s) {
  if (s.dimension != 2) r.fail(rf["type"], "reference.type", "wedge_impact is a 2D reference");
  const std::string rel = r.text(r.required(rf, "reference", "file"), "reference.file", "the CSV of the similarity profile (eta, pressure)");
  s.reference.file = beside_case_file(s.source_file, rel);
  try {
    reference::read_wedge_profile(s.reference.file);
  } catch (const std::exception& e) {
    r.fail(rf["file"], "reference.file", e.what());
  }
  s.reference.velocity = r.positive(r.required(rf, "reference", "velocity"), "reference.velocity", " (m/s, the wedge's speed)");
  s.reference.wall = r.text(r.required(rf, "reference", "wall"), "reference.wall", "the name of the wall the wedge hits");
  if (std::none_of(s.walls.begin(), s.walls.end(), [&](const Wall& w) { return w.name == s.reference.wall; }))
    r.fail(rf["wall"], "reference.wall", "no wall is named '" + s.reference.wall + "'");
  s.reference.from = r.non_negative(r.required(rf, "reference", "from"), "reference.from", " (s, the time of the contact)");
  if (!rf["origin"]) r.fail(rf, "reference.origin", "missing: wedge_impact needs the contact point on the wall (m)");
  if (s.reference.from + s.reference.length / s.reference.velocity > s.duration * (1 + 1e-12))
    r.fail(rf["length"], "reference.length", "expected s = length to be reached: from + length / velocity <= time.duration");
  if (s.wall_sensors.empty())
    r.fail(rf["type"], "reference.type", "wedge_impact compares the wall sensors along the wall: add wall_sensors");
  for (const WallSensor& w : s.wall_sensors)
    if (std::abs(w.normal[0] - s.wall_sensors.front().normal[0]) > 1e-12 || std::abs(w.normal[1] - s.wall_sensors.front().normal[1]) > 1e-12)
      r.fail(rf["type"], "reference.type", "wedge_impact expects every wall sensor on the one plane wall (the same normal): " + w.name + " is not");
}

// the name of a probe or gauge: it heads CSV columns, so no separators, and unique
std::string csv_column_name(const Reader& r, const YAML::Node& item, const std::string& key, const std::string& what,
                            const std::vector<std::string>& taken) {
  const std::string name = r.text(r.required(item, key, "name"), key + ".name", "a " + what + " name");
  if (name.find_first_of(", \"") != std::string::npos)
    r.fail(item["name"], key + ".name", "expected a name without commas, spaces or quotes (it heads CSV columns)");
  for (const std::string& t : taken)
    if (t == name) r.fail(item["name"], key + ".name", "duplicate " + what + " name '" + name + "'");
  return name;
}

// item.position: D numbers inside the closed domain box
Vec3 point_in_domain(const Reader& r, const YAML::Node& item, const std::string& key, const std::string& unit, const std::string& what,
                     const Scene& s) {
  const Vec3 p = r.vector(r.required(item, key, "position"), key + ".position", s.dimension, unit);
  for (int k = 0; k < s.dimension; ++k)
    if (p[k] < s.domain.min[k] || p[k] > s.domain.max[k]) r.fail(item["position"], key + ".position", what + " lies outside the domain");
  return p;
}

// one wave gauge: a vertical line along the last axis
WaveGauge read_wave_gauge(const Reader& r, const YAML::Node& item, const std::string& key, const Scene& s) {
  const int D = s.dimension;
  r.only_keys(item, key, {"name", "position", "bottom", "top"});
  WaveGauge g;
  std::vector<std::string> taken;
  for (const WaveGauge& q : s.wave_gauges) taken.push_back(q.name);
  g.name = csv_column_name(r, item, key, "wave gauge", taken);
  const Vec3 p = r.vector(r.required(item, key, "position"), key + ".position", D - 1, " (m, the horizontal coordinates)");
  for (int k = 0; k < D - 1; ++k) {
    g.position[k] = p[k];
    if (p[k] < s.domain.min[k] || p[k] > s.domain.max[k])
      r.fail(item["position"], key + ".position", "the gauge lies outside the domain");
  }
  g.bottom = r.number(r.required(item, key, "bottom"), key + ".bottom", "a height (m)");
  g.top = r.number(r.required(item, key, "top"), key + ".top", "a height (m)");
  if (!(g.top > g.bottom)) r.fail(item["top"], key + ".top", "expected top > bottom");
  return g;
}

}  // namespace

void read_probes(const Reader& r, YAML::Node& root, Scene& s) {
  if (const YAML::Node pr = root["probes"]) {
    if (!pr.IsSequence()) r.fail(pr, "probes", "expected a list of {name, position}");
    for (std::size_t i = 0; i < pr.size(); ++i) {
      const std::string key = "probes[" + std::to_string(i) + "]";
      r.only_keys(pr[i], key, {"name", "position"});
      Probe p;
      std::vector<std::string> taken;
      for (const Probe& q : s.probes) taken.push_back(q.name);
      p.name = csv_column_name(r, pr[i], key, "probe", taken);
      p.position = point_in_domain(r, pr[i], key, " (m)", "the probe", s);
      s.probes.push_back(p);
    }
  }
}

// pressure sensors on the walls: a face of side `size` centred at `position`, normal to `normal`
// (out of the fluid)
void read_wall_sensors(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  const YAML::Node ws = root["wall_sensors"];
  if (!ws) return;
  if (!ws.IsSequence()) r.fail(ws, "wall_sensors", "expected a list of {name, position, normal, size}");
  if (s.walls.empty()) r.fail(ws, "wall_sensors", "wall sensors read the pressure of NFM walls: the case has no walls");
  for (const Wall& w : s.walls)
    if (w.motion != WallMotion::Fixed && w.motion != WallMotion::Sliding)
      r.fail(ws, "wall_sensors", "wall sensors stay where they are put: not built for a case whose walls move (wall '" + w.name + "')");
  for (std::size_t i = 0; i < ws.size(); ++i) {
    const std::string key = "wall_sensors[" + std::to_string(i) + "]";
    r.only_keys(ws[i], key, {"name", "position", "normal", "size"});
    WallSensor w;
    std::vector<std::string> taken;
    for (const WallSensor& q : s.wall_sensors) taken.push_back(q.name);
    w.name = csv_column_name(r, ws[i], key, "wall sensor", taken);
    w.position = point_in_domain(r, ws[i], key, " (m, the centre of the sensor's face)", "the sensor", s);
    w.normal = r.vector(r.required(ws[i], key, "normal"), key + ".normal", D, " (the wall's normal out of the fluid)");
    double len = 0;
    for (int k = 0; k < D; ++k) len += w.normal[k] * w.normal[k];
    len = std::sqrt(len);
    if (!(len > 0)) r.fail(ws[i]["normal"], key + ".normal", "expected a non-zero vector (the wall's normal out of the fluid)");
    for (int k = 0; k < D; ++k) w.normal[k] /= len;
    if (ws[i]["size"]) w.size = r.non_negative(ws[i]["size"], key + ".size", " (m, the side of the sensor's face; 0: a point)");
    s.wall_sensors.push_back(w);
  }
}

// wave gauges: vertical lines along the last axis
void read_wave_gauges(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  if (const YAML::Node wg = root["wave_gauges"]) {
    if (!wg.IsSequence()) r.fail(wg, "wave_gauges", "expected a list of {name, position, bottom, top}");
    for (std::size_t i = 0; i < wg.size(); ++i)
      s.wave_gauges.push_back(read_wave_gauge(r, wg[i], "wave_gauges[" + std::to_string(i) + "]", s));
    if (!(s.gravity[D - 1] < 0))
      r.fail(wg, "wave_gauges", "wave gauges measure along the last axis: they need gravity pointing down it (forces.gravity)");
  }
}

// reference solution
void read_reference(const Reader& r, YAML::Node& root, Scene& s) {
  const int D = s.dimension;
  if (const YAML::Node rf = root["reference"]) {
    r.only_keys(rf, "reference", {"type", "length", "origin", "velocity", "file", "wall", "from", "plane"});
    const std::string t = r.word(r.required(rf, "reference", "type"), "reference.type",
                                 {"poiseuille", "couette", "hydrostatic", "martin_moyce", "ghia_re100", "ghia_re1000", "duct",
                                  "spheric_test2", "cylinder", "open_channel", "log_law", "wedge_impact"});
    s.reference.kind = t == "wedge_impact" ? ReferenceKind::WedgeImpact
                       : t == "cylinder"     ? ReferenceKind::Cylinder
                       : t == "open_channel" ? ReferenceKind::OpenChannel
                       : t == "log_law"      ? ReferenceKind::LogLaw
                       : t == "duct"         ? ReferenceKind::Duct
                       : t == "spheric_test2" ? ReferenceKind::SphericTest2
                       : t == "poiseuille" ? ReferenceKind::Poiseuille
                       : t == "couette" ? ReferenceKind::Couette
                       : t == "hydrostatic" ? ReferenceKind::Hydrostatic
                       : t == "martin_moyce" ? ReferenceKind::MartinMoyce
                       : t == "ghia_re100" ? ReferenceKind::GhiaRe100 : ReferenceKind::GhiaRe1000;
    s.reference.length = r.positive(r.required(rf, "reference", "length"), "reference.length", " (m)");
    if (rf["origin"]) s.reference.origin = r.vector(rf["origin"], "reference.origin", D, " (m)");
    if (D != 2 && s.reference.kind != ReferenceKind::Hydrostatic && s.reference.kind != ReferenceKind::Duct &&
        s.reference.kind != ReferenceKind::SphericTest2)
      r.fail(rf["type"], "reference.type", "in 3D hydrostatic, duct or spheric_test2 (the other references are 2D)");
    if (s.reference.kind == ReferenceKind::SphericTest2) read_spheric_reference(r, rf, s);
    else if (s.reference.kind == ReferenceKind::WedgeImpact) read_wedge_reference(r, rf, s);
    else if (rf["file"]) r.fail(rf["file"], "reference.file", "only a spheric_test2 or wedge_impact reference takes a file");
    if (D != 3 && s.reference.kind == ReferenceKind::Duct) r.fail(rf["type"], "reference.type", "duct is a 3D reference");
    if (s.reference.kind == ReferenceKind::Duct && !(s.nu > 0)) r.fail(rf["type"], "reference.type", "duct needs fluid.viscosity > 0");
    if ((s.reference.kind == ReferenceKind::Poiseuille || s.reference.kind == ReferenceKind::Couette ||
         s.reference.kind == ReferenceKind::OpenChannel) && !(s.nu > 0))
      r.fail(rf["type"], "reference.type", t + " needs fluid.viscosity > 0");
    if (s.reference.kind == ReferenceKind::LogLaw) {
      if (s.turbulence.wall_function == WallLaw::None)
        r.fail(rf["type"], "reference.type", "log_law compares with the law of turbulence.wall_function, which the case does not set");
      if (!(s.body_force[0] + s.gravity[0] > 0))
        r.fail(rf["type"], "reference.type", "log_law needs a driving force along +x (forces.body_force or gravity): u_* = sqrt(F H)");
      if (rf["plane"]) s.reference.plane = r.boolean(rf["plane"], "reference.plane");
    } else if (rf["plane"]) {
      r.fail(rf["plane"], "reference.plane", "only a log_law reference takes plane (a plane channel of half-width length)");
    }
    if (s.reference.kind == ReferenceKind::WedgeImpact) {
      // read by read_wedge_reference
    } else if (s.reference.kind == ReferenceKind::Cylinder) {
      // a body in a stream: its wall, the stream's speed, the start of the averaging
      s.reference.velocity = r.positive(r.required(rf, "reference", "velocity"), "reference.velocity", " (m/s, the stream's speed)");
      s.reference.wall = r.text(r.required(rf, "reference", "wall"), "reference.wall", "the name of the body's wall");
      if (std::none_of(s.walls.begin(), s.walls.end(), [&](const Wall& w) { return w.name == s.reference.wall; }))
        r.fail(rf["wall"], "reference.wall", "no wall is named '" + s.reference.wall + "'");
      if (rf["from"]) s.reference.from = r.non_negative(rf["from"], "reference.from", " (s)");
      if (s.reference.from >= s.duration) r.fail(rf["from"] ? rf["from"] : rf, "reference.from", "expected a time before time.duration");
    } else if (rf["wall"] || rf["from"]) {
      r.fail(rf["wall"] ? rf["wall"] : rf["from"], "reference", "wall and from belong to a cylinder or wedge_impact reference");
    } else if (s.reference.kind == ReferenceKind::OpenChannel) {
      // a channel between an inlet and an outlet: the inlet's mean speed; the section measured
      // (origin) and the pressure stations (origin.x - 1.5 H, origin.x + 0.5 H) inside the domain
      s.reference.velocity = r.positive(r.required(rf, "reference", "velocity"), "reference.velocity", " (m/s, the inlet's mean speed)");
      const double x0 = s.reference.origin[0], H = s.reference.length;
      if (!rf["origin"] || x0 - 1.5 * H < s.domain.min[0] || x0 + 0.5 * H > s.domain.max[0] ||
          s.reference.origin[1] < s.domain.min[1] || s.reference.origin[1] + H > s.domain.max[1])
        r.fail(rf["origin"] ? rf["origin"] : rf, "reference.origin",
               "the bottom wall at the measured section, with origin.x - 1.5 length and origin.x + 0.5 length, and the "
               "channel's height, inside the domain");
    } else if (s.reference.kind == ReferenceKind::Couette)
      s.reference.velocity = r.number(r.required(rf, "reference", "velocity"), "reference.velocity",
                                      "the speed along x of the wall at y = origin + length (m/s)");
    else if (rf["velocity"] && s.reference.kind != ReferenceKind::Cylinder)
      r.fail(rf["velocity"], "reference.velocity", "only a couette, cylinder, open_channel or wedge_impact reference takes a velocity");
  }
}

}  // namespace ondine::case_file
