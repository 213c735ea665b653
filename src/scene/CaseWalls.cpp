#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/SegmentMeet.hpp"
#include "scene/CaseSections.hpp"

namespace ondine::case_file {

namespace {

// A CSV of "x, y" lines (also ';', tabs or spaces; '#' comments, blank lines skipped)
void read_wall_file(const Reader& r, const YAML::Node& f, const std::string& key, const std::string& path, Wall& wall) {
  const std::string rel = r.text(f, key + ".file", "a CSV file of x, y lines");
  const std::string file = beside_case_file(path, rel);
  if (std::filesystem::is_directory(file)) r.fail(f, key + ".file", "'" + file + "' is a folder; expected a CSV file of x, y lines");
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
}

// circle: {centre, radius, segments}: a closed polygon inscribed in the circle, its vertices
// counter-clockwise from angle 0
void read_wall_circle(const Reader& r, const YAML::Node& c, const std::string& key, Wall& wall) {
  r.only_keys(c, key + ".circle", {"centre", "radius", "segments"});
  const Vec3 o = r.vector(r.required(c, key + ".circle", "centre"), key + ".circle.centre", 2, " (m)");
  const double rad = r.positive(r.required(c, key + ".circle", "radius"), key + ".circle.radius", " (m)");
  const int n = static_cast<int>(r.integer(r.required(c, key + ".circle", "segments"), key + ".circle.segments", 8, 1000000));
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * k / n;
    wall.points.push_back({o[0] + rad * std::cos(a), o[1] + rad * std::sin(a)});
  }
  wall.closed = true;
}

// the polyline: points, a file of points, or a circle
void read_wall_points(const Reader& r, const YAML::Node& w, const std::string& key, const std::string& path, Wall& wall) {
  if (w["points"] && w["file"]) r.fail(w["file"], key + ".file", "give either points or file, not both");
  if (w["circle"] && (w["points"] || w["file"])) r.fail(w["circle"], key + ".circle", "give either circle, points or file, not two of them");
  if (w["circle"] && w["closed"]) r.fail(w["closed"], key + ".closed", "a circle is closed; leave out closed");
  if (const YAML::Node c = w["circle"]) {
    read_wall_circle(r, c, key, wall);
  } else if (const YAML::Node pts = w["points"]) {
    if (!pts.IsSequence()) r.fail(pts, key + ".points", "expected a list of [x, y] points");
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const Vec3 v = r.vector(pts[k], key + ".points[" + std::to_string(k) + "]", 2, " (m)");
      wall.points.push_back({v[0], v[1]});
    }
  } else if (const YAML::Node f = w["file"]) {
    read_wall_file(r, f, key, path, wall);
  } else {
    r.fail(w, key + ".points", "required: points (a list of [x, y]), file (a CSV of x, y lines) or circle ({centre, radius, segments})");
  }
}

// enough points, no zero-length segment, within one period along a periodic axis
// Two segments of one polyline that are not neighbours must not meet (cross, touch or overlap),
// and neighbours must not fold back onto each other: the side test and the Shepard factor need a
// simple curve. Pairs whose bounding boxes are apart are skipped.
void check_no_self_intersection(const Reader& r, const YAML::Node& w, const std::string& key, const Wall& wall, std::size_t nseg) {
  using P = std::array<double, 2>;
  const std::size_t n = wall.points.size();
  auto pt = [&](std::size_t k) -> const P& { return wall.points[k % n]; };
  auto cross = geometry::cross2;
  double extent = 0;
  for (const P& q : wall.points) extent = std::max({extent, std::abs(q[0] - pt(0)[0]), std::abs(q[1] - pt(0)[1])});
  const double eps = 1e-12 * extent * extent;  // an area: the orientation test's round-off
  auto meet = [&](const P& a, const P& b, const P& c, const P& d) { return geometry::segments_meet(a, b, c, d, extent); };
  const YAML::Node at = w["points"] ? w["points"] : w;
  for (std::size_t i = 0; i < nseg; ++i) {
    const P &a = pt(i), &b = pt(i + 1);
    // the next segment folding back along this one
    if (wall.closed || i + 1 < nseg) {
      const P& c = pt(i + 2);
      const double dot = (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]);
      if (std::abs(cross(b, a, c)) <= eps && dot > 0)
        r.fail(at, key + ".points", "segments " + std::to_string(i) + " and " + std::to_string((i + 1) % nseg) +
                                        " fold back onto each other at point " + std::to_string((i + 1) % n) + "; expected a wall that does not meet itself");
    }
    const double xlo = std::min(a[0], b[0]), xhi = std::max(a[0], b[0]), ylo = std::min(a[1], b[1]), yhi = std::max(a[1], b[1]);
    for (std::size_t j = i + 2; j < nseg; ++j) {
      if (wall.closed && i == 0 && j == nseg - 1) continue;  // neighbours through the closing point
      const P &c = pt(j), &d = pt(j + 1);
      if (std::max(c[0], d[0]) < xlo - 1e-12 * extent || std::min(c[0], d[0]) > xhi + 1e-12 * extent ||
          std::max(c[1], d[1]) < ylo - 1e-12 * extent || std::min(c[1], d[1]) > yhi + 1e-12 * extent)
        continue;
      if (meet(a, b, c, d))
        r.fail(at, key + ".points", "segments " + std::to_string(i) + " and " + std::to_string(j) +
                                        " (0-based) meet; expected a wall that does not meet itself (a simple polyline)");
    }
  }
}

void check_wall_shape(const Reader& r, const YAML::Node& w, const std::string& key, const Scene& s, const Wall& wall) {
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
  check_no_self_intersection(r, w, key, wall, nseg);
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
}

void read_wall_motion(const Reader& r, const YAML::Node& m, const std::string& key, int D, Wall& wall) {
  const std::string mk = key + ".motion";
  r.only_keys(m, mk, {"type", "velocity", "amplitude", "period", "centre", "axis", "angular_velocity", "angle_amplitude"});
  const std::string type =
      r.word(r.required(m, mk, "type"), mk + ".type", {"fixed", "sliding", "translation", "oscillation", "rotation"});
  if (type == "rotation") {  // a rigid rotation about centre (and axis, 3D): constant rate or oscillating angle
    wall.motion = WallMotion::Rotation;
    wall.centre = r.vector(r.required(m, mk, "centre"), mk + ".centre", D, " (m)");
    if (D == 3) {
      const Vec3 a = r.vector(r.required(m, mk, "axis"), mk + ".axis", 3, "");
      const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      if (!(n > 0)) r.fail(m["axis"], mk + ".axis", "expected a non-zero axis vector");
      wall.axis = {a[0] / n, a[1] / n, a[2] / n};
    } else if (m["axis"]) {
      r.fail(m["axis"], mk + ".axis", "a 2D wall rotates about the z axis: give centre only");
    }
    if (m["angular_velocity"] && m["angle_amplitude"])
      r.fail(m["angle_amplitude"], mk + ".angle_amplitude", "give either angular_velocity or angle_amplitude with period, not both");
    if (m["angular_velocity"]) {
      wall.angular_velocity = r.number(m["angular_velocity"], mk + ".angular_velocity", "a rate (rad/s)");
    } else if (m["angle_amplitude"]) {
      wall.angle_amplitude = r.positive(m["angle_amplitude"], mk + ".angle_amplitude", " (degrees)") * M_PI / 180.0;
      wall.period = r.positive(r.required(m, mk, "period"), mk + ".period", " (s)");
    } else {
      r.fail(m, mk + ".angular_velocity", "required for a rotation: angular_velocity (rad/s), or angle_amplitude (degrees) with period (s)");
    }
    return;
  }
  if (type == "sliding" || type == "translation") {
    wall.motion = type == "sliding" ? WallMotion::Sliding : WallMotion::Translation;
    wall.velocity = r.vector(r.required(m, mk, "velocity"), mk + ".velocity", D, " (m/s)");
  } else if (type == "oscillation") {
    wall.motion = WallMotion::Oscillation;
    wall.amplitude = r.vector(r.required(m, mk, "amplitude"), mk + ".amplitude", D, " (m)");
    wall.period = r.positive(r.required(m, mk, "period"), mk + ".period", " (s)");
  }
}

// a 2D wall: its points, closed or not, and the side of the fluid
void read_wall_polyline(const Reader& r, const YAML::Node& w, const std::string& key, const std::string& path, const Scene& s,
                        Wall& wall) {
  read_wall_points(r, w, key, path, wall);
  if (w["closed"]) wall.closed = r.boolean(w["closed"], key + ".closed");
  check_wall_shape(r, w, key, s, wall);
  if (w["fluid_side"]) {
    const std::string side = wall.closed ? r.word(w["fluid_side"], key + ".fluid_side", {"inside", "outside"})
                                         : r.word(w["fluid_side"], key + ".fluid_side", {"left", "right"});
    wall.fluid_inside = side == "inside" || side == "left";
  } else {
    r.fail(w, key + ".fluid_side", wall.closed ? "required for a closed wall: inside (a tank) or outside (a body)"
                                               : "required for an open wall: left or right of the direction of its points");
  }
}

// one entry of walls, checked against the walls before it: a polyline in 2D, a
// triangle mesh in 3D (CaseWalls3d.cpp)
Wall read_wall(const Reader& r, const YAML::Node& w, std::size_t i, const std::string& path, const Scene& s) {
  const std::string key = "walls[" + std::to_string(i) + "]";
  refuse_wall_keys_of_other_dimension(r, w, key, s.dimension);
  if (s.dimension == 2)
    r.only_keys(w, key, {"name", "points", "file", "circle", "closed", "fluid_side", "condition", "motion", "moment_centre"});
  else
    r.only_keys(w, key, {"name", "box", "rectangle", "prism", "cylinder", "stl", "units", "scale", "rotate", "translate",
                         "fluid_side", "condition", "motion", "moment_centre"});
  Wall wall;
  wall.name = w["name"] ? r.text(w["name"], key + ".name", "a wall name") : "wall" + std::to_string(i);
  if (wall.name.find_first_of(", \"") != std::string::npos)
    r.fail(w["name"], key + ".name", "expected a name without commas, spaces or quotes (it heads CSV columns)");
  for (const Wall& o : s.walls)
    if (o.name == wall.name) r.fail(w["name"] ? w["name"] : w, key + ".name", "duplicate wall name '" + wall.name + "'");
  if (s.dimension == 3)
    read_wall_mesh(r, w, key, path, s, wall);
  else
    read_wall_polyline(r, w, key, path, s, wall);
  if (w["condition"])
    wall.condition = r.word(w["condition"], key + ".condition", {"no_slip", "slip"}) == "slip" ? WallCondition::Slip : WallCondition::NoSlip;
  if (const YAML::Node m = w["motion"]) read_wall_motion(r, m, key, s.dimension, wall);
  if (const YAML::Node c = w["moment_centre"]) wall.moment_centre = r.vector(c, key + ".moment_centre", s.dimension, " (m)");
  return wall;
}

}  // namespace

// walls (NFM: 2D polylines, 3D triangle meshes)
void read_walls(const Reader& r, YAML::Node& root, const std::string& path, Scene& s) {
  if (const YAML::Node ws = root["walls"]) {
    if (!ws.IsSequence()) r.fail(ws, "walls", "expected a list of walls");
    for (std::size_t i = 0; i < ws.size(); ++i) s.walls.push_back(read_wall(r, ws[i], i, path, s));
  }
  const YAML::Node disc = root["discretisation"];
  if (!s.walls.empty() && s.kernel != KernelType::WendlandC2)
    r.fail(disc["kernel"], "discretisation.kernel", "NFM walls need wendland_c2: the analytical Shepard factor (thesis 4.55) is Wendland's");
}

}  // namespace ondine::case_file
