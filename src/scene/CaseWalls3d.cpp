// 3D walls: one triangle mesh per entry of `walls`, from a primitive or an STL file,
// placed, checked and oriented so that every triangle's normal points into the fluid
// (WallMesh in scene/Scene.hpp; docs/case-file.md, `walls`).
#include <cmath>
#include <string>
#include <vector>

#include "geometry/MeshChecks.hpp"
#include "geometry/MeshPrimitives.hpp"
#include "geometry/MeshTransform.hpp"
#include "geometry/StlReader.hpp"
#include "scene/CaseSections.hpp"

namespace ondine::case_file {

namespace {

using geometry::GeometryError;
using geometry::TriangleMesh;

constexpr const char* kGeometries[] = {"box", "rectangle", "prism", "cylinder", "stl"};

// A mesh as built: primitives with their normals out of the shape (the rectangle: along
// u x v), an STL file with its own vertex order. `closed`: a closed surface.
struct BuiltMesh {
  TriangleMesh mesh;
  bool closed = true;
  std::string source;
  std::string file;  // stl: the path it was read from, for messages
  double unit = 1;   // stl: metres per unit of the file
};

geometry::Point point(const Vec3& v) { return {v[0], v[1], v[2]}; }

// the fluid sides a geometry takes, and what to say when fluid_side is missing
bool takes_front_back(const std::string& geometry) { return geometry == "rectangle"; }
std::string fluid_side_help(const std::string& geometry) {
  if (geometry == "rectangle") return "required for a rectangle: front (the side u x v points to) or back";
  if (geometry == "stl")
    return "required for an STL surface: inside (a tank) or outside (a body) for a closed surface, front or back (the side "
           "its triangles' normals by vertex order point to) for an open one";
  return "required for a " + geometry + ": inside (a tank) or outside (a body)";
}

BuiltMesh read_box(const Reader& r, const YAML::Node& g, const std::string& gk, const YAML::Node& w,
                   const std::string& key, const std::string& side) {
  r.only_keys(g, gk, {"min", "max", "open_top"});
  const Vec3 lo = r.vector(r.required(g, gk, "min"), gk + ".min", 3, " (m)");
  const Vec3 hi = r.vector(r.required(g, gk, "max"), gk + ".max", 3, " (m)");
  for (int k = 0; k < 3; ++k)
    if (!(hi[k] > lo[k])) r.fail(g["max"], gk + ".max", "expected max > min in every axis");
  const bool open_top = g["open_top"] ? r.boolean(g["open_top"], gk + ".open_top") : false;
  if (open_top && side != "inside")
    r.fail(w["fluid_side"], key + ".fluid_side",
           "an open-top box is a tank: expected fluid_side: inside (or open_top: false for a body in the fluid)");
  return {geometry::box_mesh(point(lo), point(hi), open_top), !open_top, open_top ? "open-top box" : "box", ""};
}

BuiltMesh read_rectangle(const Reader& r, const YAML::Node& g, const std::string& gk) {
  r.only_keys(g, gk, {"origin", "u", "v"});
  const Vec3 o = r.vector(r.required(g, gk, "origin"), gk + ".origin", 3, " (m)");
  const Vec3 u = r.vector(r.required(g, gk, "u"), gk + ".u", 3, " (m)");
  const Vec3 v = r.vector(r.required(g, gk, "v"), gk + ".v", 3, " (m)");
  try {
    return {geometry::rectangle_mesh(point(o), point(u), point(v)), false, "rectangle", ""};
  } catch (const GeometryError& e) {
    r.fail(g["v"], gk + ".v", e.what());
  }
}

BuiltMesh read_prism(const Reader& r, const YAML::Node& g, const std::string& gk) {
  r.only_keys(g, gk, {"base", "z"});
  const YAML::Node base = r.required(g, gk, "base");
  if (!base.IsSequence() || base.size() < 3)
    r.fail(base, gk + ".base", "expected a list of at least 3 [x, y] points (m), got " + Reader::shown(base) +
                                   (base.IsSequence() ? " of " + std::to_string(base.size()) : ""));
  std::vector<std::array<double, 2>> polygon;
  for (std::size_t k = 0; k < base.size(); ++k) {
    const Vec3 p = r.vector(base[k], gk + ".base[" + std::to_string(k) + "]", 2, " (m)");
    polygon.push_back({p[0], p[1]});
  }
  const Vec3 z = r.vector(r.required(g, gk, "z"), gk + ".z", 2, " (m)");
  if (!(z[1] > z[0])) r.fail(g["z"], gk + ".z", "expected [z0, z1] with z1 > z0 (the base at z0, the top at z1)");
  try {
    return {geometry::prism_mesh(polygon, z[0], z[1]), true, "prism", ""};
  } catch (const GeometryError& e) {
    r.fail(base, gk + ".base", e.what());
  }
}

BuiltMesh read_cylinder(const Reader& r, const YAML::Node& g, const std::string& gk) {
  r.only_keys(g, gk, {"centre", "axis", "radius", "length", "segments", "caps"});
  const Vec3 c = r.vector(r.required(g, gk, "centre"), gk + ".centre", 3, " (m)");
  const Vec3 a = r.vector(r.required(g, gk, "axis"), gk + ".axis", 3, "");
  if (!(std::hypot(a[0], a[1], a[2]) > 0)) r.fail(g["axis"], gk + ".axis", "expected a non-zero direction, got [0, 0, 0]");
  const double radius = r.positive(r.required(g, gk, "radius"), gk + ".radius", " (m)");
  const double length = r.positive(r.required(g, gk, "length"), gk + ".length", " (m)");
  const int segments = g["segments"] ? static_cast<int>(r.integer(g["segments"], gk + ".segments", 3, 100000)) : 32;
  const bool caps = g["caps"] ? r.boolean(g["caps"], gk + ".caps") : true;
  return {geometry::cylinder_mesh(point(c), point(a), radius, length, segments, caps), caps, caps ? "cylinder" : "tube", ""};
}

// an STL file, relative to the case file's folder unless absolute, in its `units`
BuiltMesh read_stl_wall(const Reader& r, const YAML::Node& w, const std::string& key, const std::string& path) {
  const std::string rel = r.text(w["stl"], key + ".stl", "the path of an STL file");
  const std::string file = beside_case_file(path, rel);
  BuiltMesh b;
  if (w["units"]) {
    const std::string u = r.word(w["units"], key + ".units", {"m", "cm", "mm"});
    b.unit = u == "cm" ? 0.01 : u == "mm" ? 0.001 : 1;
  }
  try {
    b.mesh = geometry::read_stl(file);
  } catch (const GeometryError& e) {
    r.fail(w["stl"], key + ".stl", e.what());
  }
  b.closed = geometry::count_open_edges(b.mesh) == 0;
  b.source = "stl '" + rel + "'";
  b.file = file;
  return b;
}

// scale, rotate, translate: a positive number or three, and two vectors of 3
geometry::MeshTransform read_transform(const Reader& r, const YAML::Node& w, const std::string& key) {
  geometry::MeshTransform t;
  if (const YAML::Node n = w["scale"]) {
    if (n.IsSequence()) {
      const Vec3 s = r.vector(n, key + ".scale", 3, "");
      for (int k = 0; k < 3; ++k)
        if (!(s[k] > 0))
          r.fail(n[k], key + ".scale[" + std::to_string(k) + "]",
                 "expected a positive number (a mirror would turn the wall inside out), got " + Reader::shown(n[k]));
      t.scale = point(s);
    } else {
      const double s = r.positive(n, key + ".scale", " (or a list of 3 positive numbers)");
      t.scale = {s, s, s};
    }
  }
  if (w["rotate"]) t.rotate_degrees = point(r.vector(w["rotate"], key + ".rotate", 3, " (degrees about x, then y, then z)"));
  if (w["translate"]) t.translate = point(r.vector(w["translate"], key + ".translate", 3, " (m)"));
  return t;
}

}  // namespace

void refuse_wall_keys_of_other_dimension(const Reader& r, const YAML::Node& w, const std::string& key, int D) {
  if (!w.IsMap()) return;
  if (D == 2) {
    for (const char* k : {"box", "rectangle", "prism", "cylinder", "stl", "units", "scale", "rotate", "translate"})
      if (w[k])
        r.fail(w[k], key + "." + k,
               "a key of 3D walls; a 2D wall is a polyline: expected points (a list of [x, y]) or file (a CSV of x, y "
               "lines), with closed and fluid_side");
  } else {
    for (const char* k : {"points", "file"})
      if (w[k])
        r.fail(w[k], key + "." + k,
               "a key of 2D walls; a 3D wall is a triangle mesh: expected one of box, rectangle, prism, cylinder, stl");
    if (w["closed"])
      r.fail(w["closed"], key + ".closed",
             "a key of 2D walls; in 3D the geometry tells whether a wall is closed (a box, a prism, a cylinder with caps, "
             "an STL surface without holes): remove it");
  }
}

void read_wall_mesh(const Reader& r, const YAML::Node& w, const std::string& key, const std::string& path, const Scene& s,
                    Wall& wall) {
  std::string geometry;
  for (const char* g : kGeometries)
    if (w[g]) {
      if (!geometry.empty()) r.fail(w[g], key + "." + g, "give one geometry per wall, not both " + geometry + " and " + g);
      geometry = g;
    }
  if (geometry.empty())
    r.fail(w, key, "required: one geometry key: box, rectangle, prism, cylinder or stl (a 3D wall is a triangle mesh)");
  const std::string gk = key + "." + geometry;
  const YAML::Node g = w[geometry];
  if (w["units"] && geometry != "stl")
    r.fail(w["units"], key + ".units", "units belong to an stl file; the " + geometry + " is given in m");

  if (!w["fluid_side"]) r.fail(w, key + ".fluid_side", fluid_side_help(geometry));
  const std::string side = geometry == "stl" ? r.word(w["fluid_side"], key + ".fluid_side", {"inside", "outside", "front", "back"})
                           : takes_front_back(geometry) ? r.word(w["fluid_side"], key + ".fluid_side", {"front", "back"})
                                                  : r.word(w["fluid_side"], key + ".fluid_side", {"inside", "outside"});
  const bool need_closed = side == "inside" || side == "outside";
  geometry::MeshTransform placement = read_transform(r, w, key);

  BuiltMesh b;
  try {
    if (geometry == "box") b = read_box(r, g, gk, w, key, side);
    else if (geometry == "rectangle") b = read_rectangle(r, g, gk);
    else if (geometry == "prism") b = read_prism(r, g, gk);
    else if (geometry == "cylinder") b = read_cylinder(r, g, gk);
    else b = read_stl_wall(r, w, key, path);
  } catch (const GeometryError& e) {
    r.fail(g, gk, e.what());
  }

  // the checks on the mesh as read (an STL file's own triangle numbers and coordinates,
  // in its units); open primitives (open-top box, tube) take inside/outside unclosed
  const std::string in_file = b.file.empty() ? "" : "'" + b.file + "': ";
  const std::string problem = geometry::mesh_problem(
      b.mesh, geometry == "stl" ? need_closed : b.closed,
      "; fluid_side inside or outside needs a closed surface, front or back takes an open one");
  if (!problem.empty()) r.fail(g, gk, in_file + problem);
  if (geometry == "stl")
    if (const std::string crossing = geometry::crossing_problem(b.mesh); !crossing.empty()) r.fail(g, gk, in_file + crossing);
  if (geometry == "stl" && !need_closed && b.closed)
    r.fail(w["fluid_side"], key + ".fluid_side",
           in_file + "the surface is closed: expected fluid_side inside (the fluid in it) or outside (a body in the fluid); "
                     "front and back are for an open surface");

  for (double& f : placement.scale) f *= b.unit;  // units first, then scale, rotate, translate
  geometry::place(placement, b.mesh);
  for (const geometry::Point& p : b.mesh.vertices)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      r.fail(g, gk, "a vertex lies at a non-finite position " + geometry::format_point(p) +
                        " after units, scale, rotate and translate; expected finite coordinates");

  // into the fluid: a closed surface by the sign of its volume (negative when its
  // normals point in), an open one by construction (primitives: out of the shape or
  // along u x v; an STL: its own order, the front)
  bool reverse;
  if (b.closed) {
    const double v = geometry::signed_volume(b.mesh);
    reverse = side == "inside" ? v > 0 : v < 0;
  } else {
    reverse = side == "inside" || side == "back";
  }
  if (reverse) geometry::flip(b.mesh);

  // along a periodic axis the wall's images one period away are added, so the wall
  // itself must lie within one period (as in 2D)
  for (int k = 0; k < 3; ++k) {
    if (!s.periodic[k]) continue;
    const double tol = 1e-9 * (s.domain.max[k] - s.domain.min[k]);
    for (const geometry::Point& p : b.mesh.vertices)
      if (p[k] < s.domain.min[k] - tol || p[k] > s.domain.max[k] + tol)
        r.fail(g, gk,
               std::string("a wall must lie within the domain along the periodic axis ") + "xyz"[k] +
                   " (its periodic images are added; a wall across the axis spans exactly one period)");
  }

  wall.mesh.vertices = std::move(b.mesh.vertices);
  wall.mesh.triangles = std::move(b.mesh.triangles);
  wall.mesh.source = b.source;
  wall.closed = b.closed;
  wall.fluid_inside = side == "inside" || side == "front";
}

}  // namespace ondine::case_file
