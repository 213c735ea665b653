// 3D walls from the case file: the primitives, the placement, the STL reader, the
// orientation into the fluid, and each kind of bad mesh with the message that names it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>  // mkdtemp
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "geometry/MeshChecks.hpp"
#include "geometry/MeshPrimitives.hpp"
#include "geometry/MeshTransform.hpp"
#include "geometry/StlReader.hpp"
#include "scene/CaseFile.hpp"

using namespace ondine;
using namespace ondine::geometry;
using Catch::Matchers::Contains;

namespace {

const double pi = std::acos(-1.0);

// a 3D case around the given `walls:` entries (YAML flow mappings, one per line)
std::string case3d(const std::vector<std::string>& walls, const std::string& extra = "") {
  std::string y = R"(dimension: 3
domain: {min: [-3, -3, -3], max: [3, 3, 3]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.1}
fluid_blocks: [{min: [0, 0, 0], max: [1, 1, 0.5]}]
time: {duration: 1, output_interval: 1}
walls:
)";
  for (const std::string& w : walls) y += "  - " + w + "\n";
  return y + extra;
}

// a fresh folder for the case file and its STL files, removed at the end of the test
struct TempFolder {
  std::string path;
  TempFolder() {
    char name[] = "/tmp/ondine_wall_mesh_XXXXXX";
    REQUIRE(mkdtemp(name) != nullptr);
    path = name;
  }
  ~TempFolder() { std::filesystem::remove_all(path); }
};

Scene parse(const std::string& text, const std::string& folder = "/tmp") { return parse_case(text, folder + "/case.yaml"); }

std::string error_of(const std::string& text, const std::string& folder = "/tmp") {
  try {
    parse(text, folder);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

TriangleMesh as_mesh(const WallMesh& w) {
  TriangleMesh m;
  m.vertices = w.vertices;
  m.triangles = w.triangles;
  return m;
}

Point centroid(const TriangleMesh& m, int t) {
  const Triangle& tri = m.triangles[t];
  return (1.0 / 3) * (m.vertices[tri[0]] + m.vertices[tri[1]] + m.vertices[tri[2]]);
}

using Soup = std::vector<std::array<Point, 3>>;

Soup soup_of(const TriangleMesh& m) {
  Soup s;
  for (const Triangle& t : m.triangles) s.push_back({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
  return s;
}

void write_binary_stl(const std::string& file, const Soup& soup) {
  std::ofstream o(file, std::ios::binary);
  const std::string header(80, ' ');
  o.write(header.data(), 80);
  const std::uint32_t n = static_cast<std::uint32_t>(soup.size());
  o.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : soup) {
    const Point nrm = cross(t[1] - t[0], t[2] - t[0]);
    float f[12];
    for (int k = 0; k < 3; ++k) f[k] = static_cast<float>(nrm[k] / norm(nrm));
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) f[3 + 3 * c + k] = static_cast<float>(t[c][k]);
    o.write(reinterpret_cast<const char*>(f), sizeof f);
    const std::uint16_t attr = 0;
    o.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

void write_ascii_stl(const std::string& file, const Soup& soup) {
  std::ofstream o(file);
  o << "solid test\n";
  for (const auto& t : soup) {
    const Point nrm = cross(t[1] - t[0], t[2] - t[0]);
    o << "  facet normal " << nrm[0] << " " << nrm[1] << " " << nrm[2] << "\n    outer loop\n";
    for (const Point& p : t) o << "      vertex " << p[0] << " " << p[1] << " " << p[2] << "\n";
    o << "    endloop\n  endfacet\n";
  }
  o << "endsolid test\n";
}

// the unit cube, normals out
Soup unit_cube() { return soup_of(box_mesh({0, 0, 0}, {1, 1, 1}, false)); }

}  // namespace

TEST_CASE("Box walls: a tank or a body of 12 triangles facing the fluid", "[unit][case]") {
  const Scene s = parse(case3d({"{name: tank, box: {min: [0, 0, 0], max: [2, 1, 0.5]}, fluid_side: inside}",
                                "{name: body, box: {min: [0.2, 0.2, 0.1], max: [0.4, 0.3, 0.2]}, fluid_side: outside}",
                                "{name: open, box: {min: [0, 0, 0], max: [1, 1, 1], open_top: true}, fluid_side: inside}"}));
  REQUIRE(s.walls.size() == 3);
  const Wall& tank = s.walls[0];
  const TriangleMesh m = as_mesh(tank.mesh);
  CHECK(m.triangles.size() == 12);
  CHECK(m.vertices.size() == 8);
  CHECK(tank.closed);
  CHECK(tank.fluid_inside);
  CHECK(tank.mesh.source == "box");
  CHECK(total_area(m) == Approx(2 * (2 * 1 + 1 * 0.5 + 2 * 0.5)));
  CHECK(signed_volume(m) == Approx(-1.0));  // normals into the tank: the volume counts negative
  CHECK(mesh_problem(m, true).empty());
  const Point centre{1, 0.5, 0.25};
  for (int t = 0; t < 12; ++t) CHECK(dot(area_normal(m, t), centre - centroid(m, t)) > 0);

  const Wall& body = s.walls[1];
  const TriangleMesh b = as_mesh(body.mesh);
  CHECK(body.closed);
  CHECK_FALSE(body.fluid_inside);
  CHECK(signed_volume(b) == Approx(0.2 * 0.1 * 0.1));
  for (int t = 0; t < 12; ++t) CHECK(dot(area_normal(b, t), Point{0.3, 0.25, 0.15} - centroid(b, t)) < 0);

  const Wall& open = s.walls[2];
  const TriangleMesh o = as_mesh(open.mesh);
  CHECK(o.triangles.size() == 10);
  CHECK_FALSE(open.closed);
  CHECK(count_open_edges(o) == 4);
  CHECK(total_area(o) == Approx(5.0));
  for (int t = 0; t < 10; ++t) {
    CHECK(centroid(o, t)[2] < 1);  // no face at max z
    CHECK(dot(area_normal(o, t), Point{0.5, 0.5, 0.5} - centroid(o, t)) > 0);
  }
}

TEST_CASE("Rectangle walls: two triangles facing front (u x v) or back", "[unit][case]") {
  const Scene s = parse(case3d({"{rectangle: {origin: [0, 0, 0], u: [2, 0, 0], v: [0, 0, 1]}, fluid_side: front}",
                                "{rectangle: {origin: [0, 0, 0], u: [2, 0, 0], v: [0, 0, 1]}, fluid_side: back}"}));
  const TriangleMesh f = as_mesh(s.walls[0].mesh), b = as_mesh(s.walls[1].mesh);
  CHECK(f.triangles.size() == 2);
  CHECK_FALSE(s.walls[0].closed);
  CHECK(total_area(f) == Approx(2.0));
  CHECK(count_open_edges(f) == 4);
  const Point uxv{0, -2, 0};
  for (int t = 0; t < 2; ++t) {
    CHECK(dot(area_normal(f, t), uxv) > 0);
    CHECK(dot(area_normal(b, t), uxv) < 0);
  }
}

TEST_CASE("Prism walls: a concave polygon extruded, either orientation", "[unit][case]") {
  // an L of area 3, counter-clockwise, then clockwise, then with a point in line on an edge
  const std::string ccw = "[[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]";
  const std::string cw = "[[0, 2], [1, 2], [1, 1], [2, 1], [2, 0], [0, 0]]";
  const std::string in_line = "[[0, 0], [1, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]";
  const Scene s = parse(case3d({"{prism: {base: " + ccw + ", z: [0, 0.5]}, fluid_side: outside}",
                                "{prism: {base: " + cw + ", z: [0, 0.5]}, fluid_side: outside}",
                                "{prism: {base: " + in_line + ", z: [0, 0.5]}, fluid_side: inside}"}));
  for (int i = 0; i < 3; ++i) {
    INFO("wall " << i);
    const TriangleMesh m = as_mesh(s.walls[i].mesh);
    const int n = i < 2 ? 6 : 7;
    CHECK(m.triangles.size() == static_cast<std::size_t>(2 * n + 2 * (n - 2)));
    CHECK(s.walls[i].closed);
    CHECK(mesh_problem(m, true).empty());  // closed and consistent: the caps meet the sides edge to edge
    CHECK(total_area(m) == Approx(2 * 3 + 0.5 * (2 + 2 + 1 + 1 + 1 + 1)));
    CHECK(signed_volume(m) == Approx(i < 2 ? 1.5 : -1.5));  // out of the body, into the tank
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Point c = centroid(m, static_cast<int>(t)), nrm = area_normal(m, static_cast<int>(t));
      if (c[2] == 0.5) CHECK(nrm[2] * (i < 2 ? 1 : -1) > 0);  // the top cap
      if (c[2] == 0) CHECK(nrm[2] * (i < 2 ? 1 : -1) < 0);    // the bottom cap
    }
  }
  // ear clipping on its own: n - 2 triangles, counter-clockwise, covering the area
  const std::vector<std::array<double, 2>> comb{{0, 0}, {4, 0}, {4, 2}, {3, 2}, {3, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}};
  const auto tris = triangulate_polygon(comb);
  CHECK(tris.size() == comb.size() - 2);
  double area = 0;
  for (const Triangle& t : tris) {
    const std::vector<std::array<double, 2>> tri{comb[t[0]], comb[t[1]], comb[t[2]]};
    CHECK(polygon_twice_area(tri) > 0);
    area += polygon_twice_area(tri) / 2;
  }
  CHECK(area == Approx(polygon_twice_area(comb) / 2));
}

TEST_CASE("Cylinder walls: an inscribed N-gon prism, with or without caps", "[unit][case]") {
  const Scene s = parse(case3d({"{cylinder: {centre: [0, 0, 0], axis: [0, 0, 2], radius: 0.5, length: 1, segments: 16}, fluid_side: inside}",
                                "{cylinder: {centre: [0, 0, 0], axis: [1, 1, 0], radius: 0.5, length: 1}, fluid_side: outside}",
                                "{cylinder: {centre: [0, 0, 0], axis: [0, 0, 1], radius: 0.5, length: 1, caps: false}, fluid_side: inside}"}));
  const TriangleMesh a = as_mesh(s.walls[0].mesh), b = as_mesh(s.walls[1].mesh), tube = as_mesh(s.walls[2].mesh);
  CHECK(a.triangles.size() == 4 * 16);
  CHECK(b.triangles.size() == 4 * 32);
  CHECK(s.walls[0].closed);
  CHECK(mesh_problem(a, true).empty());
  CHECK(mesh_problem(b, true).empty());
  // the inscribed polygon: the circle's volume times sin(2 pi / N) N / (2 pi)
  CHECK(signed_volume(a) == Approx(-pi * 0.25 * std::sin(2 * pi / 16) * 16 / (2 * pi)));
  CHECK(signed_volume(b) == Approx(pi * 0.25 * std::sin(2 * pi / 32) * 32 / (2 * pi)));
  // every side triangle of the tank faces the axis; of the body, away from it
  const Point axis_b = (1 / std::sqrt(2.0)) * Point{1, 1, 0};
  for (std::size_t t = 0; t < 2 * 16; ++t) {
    const Point c = centroid(a, static_cast<int>(t));
    CHECK(dot(area_normal(a, static_cast<int>(t)), Point{-c[0], -c[1], 0}) > 0);
  }
  for (std::size_t t = 0; t < 2 * 32; ++t) {
    const Point c = centroid(b, static_cast<int>(t));
    const Point radial = c - dot(c, axis_b) * axis_b;
    CHECK(dot(area_normal(b, static_cast<int>(t)), radial) > 0);
  }
  CHECK(tube.triangles.size() == 2 * 32);
  CHECK_FALSE(s.walls[2].closed);
  CHECK(count_open_edges(tube) == 2 * 32);
  for (std::size_t t = 0; t < tube.triangles.size(); ++t) {
    const Point c = centroid(tube, static_cast<int>(t));
    CHECK(dot(area_normal(tube, static_cast<int>(t)), Point{-c[0], -c[1], 0}) > 0);
  }
}

TEST_CASE("Wall placement: scale, then rotate about x, y, z, then translate", "[unit][case]") {
  MeshTransform t;
  t.scale = {2, 2, 2};
  t.rotate_degrees = {0, 0, 90};
  t.translate = {1, 0, 0};
  const Point p = place(t, Point{1, 0, 0});
  CHECK(p[0] == 1);  // (2, 0, 0), turned to (0, 2, 0), moved to (1, 2, 0): exact at 90 degrees
  CHECK(p[1] == 2);
  CHECK(p[2] == 0);
  MeshTransform xy;
  xy.rotate_degrees = {90, 90, 0};  // about x first: (0, 1, 0) -> (0, 0, 1) -> (1, 0, 0)
  const Point q = place(xy, Point{0, 1, 0});
  CHECK(q[0] == Approx(1));
  CHECK(q[1] == Approx(0).margin(1e-15));
  CHECK(q[2] == Approx(0).margin(1e-15));
  MeshTransform r30;
  r30.rotate_degrees = {0, 0, 30};
  const Point u = place(r30, Point{1, 0, 0});
  CHECK(u[0] == Approx(std::sqrt(3.0) / 2));
  CHECK(u[1] == Approx(0.5));

  // in a case: the unit box scaled by [2, 1, 0.5], turned by 90 degrees about z, moved
  const Scene s = parse(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1]}, scale: [2, 1, 0.5], rotate: [0, 0, 90], "
                                "translate: [1, 0, 0], fluid_side: outside}"}));
  const TriangleMesh m = as_mesh(s.walls[0].mesh);
  Point lo = m.vertices[0], hi = lo;
  for (const Point& v : m.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  CHECK(lo == Point{0, 0, 0});
  CHECK(hi == Point{1, 2, 0.5});
  CHECK(signed_volume(m) == Approx(1.0));
}

TEST_CASE("STL walls: binary and ASCII files give the same mesh, in their units", "[unit][case]") {
  const TempFolder tmp;
  const std::string& dir = tmp.path;
  write_binary_stl(dir + "/cube_bin.stl", unit_cube());
  write_ascii_stl(dir + "/cube_ascii.stl", unit_cube());
  const TriangleMesh bin = read_stl(dir + "/cube_bin.stl"), ascii = read_stl(dir + "/cube_ascii.stl");
  CHECK(bin.triangles.size() == 12);
  CHECK(bin.vertices.size() == 8);  // the corners welded into shared vertices
  CHECK(bin.vertices == ascii.vertices);
  CHECK(bin.triangles == ascii.triangles);
  CHECK(count_open_edges(bin) == 0);
  CHECK(signed_volume(bin) == Approx(1.0));  // the file's order: normals out
  // corners within the tolerance become one vertex, farther ones stay apart; the order is kept
  const TriangleMesh near = weld({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-12, 0, 0}, {0, 1, 0}, {1, 0, 0}}, 1e-9);
  CHECK(near.vertices.size() == 3);
  CHECK(near.triangles[1] == Triangle{0, 2, 1});
  CHECK(weld({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-6, 0, 0}, {0, 1, 0}, {1, 0, 0}}, 1e-9).vertices.size() == 4);

  // a 1000 mm cube, as a tank and as a body; the relative path from the case's folder
  Soup mm = unit_cube();
  for (auto& t : mm)
    for (Point& p : t) p = 1000.0 * p;
  write_binary_stl(dir + "/cube_mm.stl", mm);
  const Scene s = parse(case3d({"{name: tank, stl: cube_mm.stl, units: mm, fluid_side: inside}",
                                "{name: body, stl: cube_ascii.stl, scale: 0.5, translate: [0.1, 0.1, 0.1], fluid_side: outside}"}),
                        dir);
  const TriangleMesh tank = as_mesh(s.walls[0].mesh), body = as_mesh(s.walls[1].mesh);
  CHECK(s.walls[0].closed);
  CHECK(s.walls[0].fluid_inside);
  CHECK(s.walls[0].mesh.source == "stl 'cube_mm.stl'");
  CHECK(signed_volume(tank) == Approx(-1.0));  // 1 m^3, turned to face into the tank
  for (int t = 0; t < 12; ++t) CHECK(dot(area_normal(tank, t), Point{0.5, 0.5, 0.5} - centroid(tank, t)) > 0);
  CHECK(signed_volume(body) == Approx(0.125));
  CHECK_FALSE(s.walls[1].fluid_inside);

  // an open surface (a square) faces the side of its normals by vertex order (front) or the other
  write_ascii_stl(dir + "/square.stl", {{Point{0, 0, 0}, Point{1, 0, 0}, Point{1, 1, 0}}, {Point{0, 0, 0}, Point{1, 1, 0}, Point{0, 1, 0}}});
  const Scene o = parse(case3d({"{stl: square.stl, fluid_side: front}", "{stl: square.stl, fluid_side: back}"}), dir);
  CHECK_FALSE(o.walls[0].closed);
  CHECK(area_normal(as_mesh(o.walls[0].mesh), 0)[2] > 0);
  CHECK(area_normal(as_mesh(o.walls[1].mesh), 0)[2] < 0);
}

TEST_CASE("Bad 3D walls are refused naming the key, the file and the triangle", "[unit][case]") {
  const TempFolder tmp;
  const std::string& dir = tmp.path;
  const auto stl_error = [&](const std::string& name, const Soup& soup, const std::string& side = "inside") {
    write_binary_stl(dir + "/" + name, soup);
    return error_of(case3d({"{stl: " + name + ", fluid_side: " + side + "}"}), dir);
  };
  const std::string at = dir + "/case.yaml:8:";

  SECTION("a triangle of zero area") {
    Soup s = unit_cube();
    s.push_back({Point{0, 0, 0}, Point{1, 0, 0}, Point{0.5, 0, 0}});
    CHECK_THAT(stl_error("flat.stl", s), Contains(at) && Contains("key 'walls[0].stl'") && Contains("flat.stl") &&
                                             Contains("triangle 12 (0-based) has zero area") && Contains("(0.5, 0, 0)"));
  }
  SECTION("a triangle twice") {
    Soup s = unit_cube();
    s.push_back({s[3][1], s[3][0], s[3][2]});
    CHECK_THAT(stl_error("twice.stl", s), Contains("key 'walls[0].stl'") && Contains("triangles 3 and 12 (0-based) are the same triangle"));
  }
  SECTION("a hole where a closed surface is needed") {
    Soup s = unit_cube();
    s.erase(s.begin() + 7);
    const std::string m = stl_error("hole.stl", s);
    CHECK_THAT(m, Contains("key 'walls[0].stl'") && Contains("hole.stl") && Contains("not closed: 3 edges belong to one triangle only") &&
                      Contains("(0-based)") && Contains("front or back takes an open one"));
    CHECK(stl_error("hole.stl", s, "front").empty());  // an open surface may face front
  }
  SECTION("an edge of three triangles") {
    Soup s = unit_cube();
    s.push_back({Point{0, 0, 0}, Point{1, 0, 0}, Point{0.5, -1, 0.5}});
    CHECK_THAT(stl_error("fin.stl", s), Contains("key 'walls[0].stl'") && Contains("is shared by 3 triangles") && Contains("12") &&
                                            Contains("expected at most 2"));
  }
  SECTION("a triangle turned inside out") {
    Soup s = unit_cube();
    std::swap(s[5][1], s[5][2]);
    CHECK_THAT(stl_error("flipped.stl", s), Contains("key 'walls[0].stl'") && Contains("ordered inconsistently") && Contains(" and 5 (0-based)"));
  }
  SECTION("a closed surface around no volume") {
    // a tetrahedron flattened: its apex in the plane of its base
    const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0.25, 0.25, 0};
    CHECK_THAT(stl_error("flat_tet.stl", {{a, c, b}, {a, b, d}, {b, c, d}, {c, a, d}}), Contains("encloses no volume"));
  }
  SECTION("two shells that cross, and two that do not") {
    const auto shifted = [](Soup s, double by) {
      for (auto& t : s)
        for (auto& p : t)
          for (int k = 0; k < 3; ++k) p[k] += by;
      return s;
    };
    Soup s = unit_cube();
    const Soup b = shifted(unit_cube(), 0.5);  // overlapping the first: their faces cross
    s.insert(s.end(), b.begin(), b.end());
    CHECK_THAT(stl_error("overlap.stl", s), Contains("key 'walls[0].stl'") && Contains("overlap.stl") && Contains("(0-based) cross each other") &&
                                                Contains("expected a surface that does not meet itself"));
    Soup apart = unit_cube();
    const Soup c = shifted(unit_cube(), 2.0);
    apart.insert(apart.end(), c.begin(), c.end());
    CHECK(stl_error("apart.stl", apart).empty());  // two closed shells apart are one valid wall
  }
  SECTION("a non-finite coordinate") {
    Soup s = unit_cube();
    s[2][1][0] = std::nan("");
    CHECK_THAT(stl_error("nan.stl", s), Contains("key 'walls[0].stl'") && Contains("non-finite coordinate"));
  }
  SECTION("a closed surface given front or back") {
    CHECK_THAT(stl_error("cube.stl", unit_cube(), "front"), Contains("key 'walls[0].fluid_side'") && Contains("the surface is closed"));
  }
  SECTION("a file that is not STL, and a missing file") {
    std::ofstream(dir + "/junk.stl") << "this is not an STL file at all, not even close, really not at all, no no no no no";
    const std::string m = error_of(case3d({"{stl: junk.stl, fluid_side: inside}"}), dir);
    CHECK_THAT(m, Contains("key 'walls[0].stl'") && Contains("'" + dir + "/junk.stl' cannot be read as STL (assimp: ") &&
                      Contains("expected a binary STL"));
    CHECK_THAT(error_of(case3d({"{stl: nothere.stl, fluid_side: inside}"}), dir),
               Contains("key 'walls[0].stl'") && Contains("cannot open '" + dir + "/nothere.stl'"));
  }
  SECTION("keys of the other dimension") {
    CHECK_THAT(error_of(case3d({"{points: [[0, 0], [1, 0]], fluid_side: left}"})),
               Contains("key 'walls[0].points'") && Contains("a key of 2D walls") && Contains("box, rectangle, prism, cylinder, stl"));
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1]}, closed: true, fluid_side: inside}"})),
               Contains("key 'walls[0].closed'") && Contains("a key of 2D walls"));
    const std::string two_d = R"(dimension: 2
domain: {min: [0, 0], max: [1, 1]}
fluid: {rho0: 1000, sound_speed: 10}
discretisation: {dx: 0.1}
fluid_blocks: [{min: [0, 0], max: [1, 0.5]}]
time: {duration: 1, output_interval: 1}
walls: [{box: {min: [0, 0], max: [1, 1]}, fluid_side: inside}]
)";
    CHECK_THAT(error_of(two_d), Contains("key 'walls[0].box'") && Contains("a key of 3D walls") && Contains("expected points"));
  }
  SECTION("primitives with bad parameters") {
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 0, 1]}, fluid_side: inside}"})),
               Contains("key 'walls[0].box.max'") && Contains("max > min"));
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1], open_top: true}, fluid_side: outside}"})),
               Contains("key 'walls[0].fluid_side'") && Contains("open-top box"));
    CHECK_THAT(error_of(case3d({"{rectangle: {origin: [0, 0, 0], u: [1, 0, 0], v: [2, 0, 0]}, fluid_side: front}"})),
               Contains("key 'walls[0].rectangle.v'") && Contains("parallel"));
    CHECK_THAT(error_of(case3d({"{prism: {base: [[0, 0], [1, 0], [1, 0], [0, 1]], z: [0, 1]}, fluid_side: inside}"})),
               Contains("key 'walls[0].prism.base'") && Contains("from point 1 to point 2 (0-based) has zero length"));
    // a bowtie (its two lobes' areas cancel): named as crossing edges, not as points in line
    CHECK_THAT(error_of(case3d({"{prism: {base: [[0, 0], [1, 1], [1, 0], [0, 1]], z: [0, 1]}, fluid_side: outside}"})),
               Contains("key 'walls[0].prism.base'") &&
                   Contains("the edges from point 0 to point 1 and from point 2 to point 3 (0-based) meet; expected a simple polygon"));
    // a polygon touching itself at a vertex
    CHECK_THAT(error_of(case3d({"{prism: {base: [[0, 0], [2, 0], [1, 1], [2, 2], [0, 2], [1, 1]], z: [0, 1]}, fluid_side: outside}"})),
               Contains("key 'walls[0].prism.base'") && Contains("meet; expected a simple polygon"));
    CHECK_THAT(error_of(case3d({"{prism: {base: [[0, 0], [1, 0], [0, 1]], z: [1, 0]}, fluid_side: inside}"})),
               Contains("key 'walls[0].prism.z'") && Contains("z1 > z0"));
    CHECK_THAT(error_of(case3d({"{cylinder: {centre: [0, 0, 0], axis: [0, 0, 0], radius: 1, length: 1}, fluid_side: inside}"})),
               Contains("key 'walls[0].cylinder.axis'") && Contains("non-zero"));
    CHECK_THAT(error_of(case3d({"{cylinder: {centre: [0, 0, 0], axis: [0, 0, 1], radius: 1, length: 1, segments: 2}, fluid_side: inside}"})),
               Contains("key 'walls[0].cylinder.segments'") && Contains("[3, 100000]"));
    CHECK_THAT(error_of(case3d({"{rectangle: {origin: [0, 0, 0], u: [1, 0, 0], v: [0, 1, 0]}, fluid_side: inside}"})),
               Contains("key 'walls[0].fluid_side'") && Contains("front | back"));
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1]}}"})),
               Contains("key 'walls[0].fluid_side'") && Contains("required for a box: inside (a tank) or outside (a body)"));
    CHECK_THAT(error_of(case3d({"{fluid_side: inside}"})), Contains("key 'walls[0]'") && Contains("one geometry key"));
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1]}, stl: a.stl, fluid_side: inside}"})),
               Contains("key 'walls[0].stl'") && Contains("not both box and stl"));
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1]}, units: mm, fluid_side: inside}"})),
               Contains("key 'walls[0].units'") && Contains("stl file"));
    CHECK_THAT(error_of(case3d({"{box: {min: [0, 0, 0], max: [1, 1, 1]}, scale: [1, -1, 1], fluid_side: inside}"})),
               Contains("key 'walls[0].scale[1]'") && Contains("positive"));
  }
  SECTION("3D walls with refinement zones are accepted") {
    CHECK(error_of(case3d({"{box: {min: [-1, -1, -1], max: [2, 2, 2]}, fluid_side: inside}"},
                          "refinement: {zones: [{name: z, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}]}\n")) == "");
  }
  SECTION("a wall across a periodic axis") {
    std::string y = case3d({"{box: {min: [-4, 0, 0], max: [1, 1, 1]}, fluid_side: outside}"});
    const std::string from = "max: [3, 3, 3]}";
    y.replace(y.find(from), from.size(), "max: [3, 3, 3], periodic: [true, false, false]}");
    CHECK_THAT(error_of(y), Contains("key 'walls[0].box'") && Contains("periodic axis x"));
  }
}
