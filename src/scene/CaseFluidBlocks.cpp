#include <cmath>

#include "scene/CaseSections.hpp"

namespace ondine::case_file {

namespace {

// velocity: a uniform vector, or {taylor_green: {amplitude, wavelength}}
void read_block_velocity(const Reader& r, const YAML::Node& v, const std::string& key, int D, FluidBlock& fb) {
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

// cut: a list of half-spaces {point, normal}; the lattice points on the normal's side of a
// plane are dropped (a wedge, a sloping free surface)
void read_block_cuts(const Reader& r, const YAML::Node& c, const std::string& key, int D, FluidBlock& fb) {
  if (!c.IsSequence() || c.size() == 0 || c.size() > 8)
    r.fail(c, key + ".cut", "expected a list of 1 to 8 half-spaces {point: [...], normal: [...]}");
  for (std::size_t j = 0; j < c.size(); ++j) {
    const std::string ck = key + ".cut[" + std::to_string(j) + "]";
    r.only_keys(c[j], ck, {"point", "normal"});
    FluidBlock::Cut cut;
    cut.point = r.vector(r.required(c[j], ck, "point"), ck + ".point", D, " (m)");
    cut.normal = r.vector(r.required(c[j], ck, "normal"), ck + ".normal", D, " (out of the fluid)");
    double n2 = 0;
    for (int k = 0; k < D; ++k) n2 += cut.normal[k] * cut.normal[k];
    if (!(n2 > 0)) r.fail(c[j]["normal"], ck + ".normal", "expected a non-zero vector (the direction out of the fluid)");
    for (int k = 0; k < D; ++k) cut.normal[k] /= std::sqrt(n2);
    fb.cuts.push_back(cut);
  }
}

// one entry of fluid_blocks, checked against the domain and the blocks before it
FluidBlock read_fluid_block(const Reader& r, const YAML::Node& b, const std::string& key, const Scene& s) {
  const int D = s.dimension;
  r.only_keys(b, key, {"min", "max", "velocity", "pressure", "wall_clearance", "cut"});
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
  if (const YAML::Node v = b["velocity"]) read_block_velocity(r, v, key, D, fb);
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
  if (const YAML::Node c = b["cut"]) read_block_cuts(r, c, key, D, fb);
  for (std::size_t o = 0; o < s.blocks.size(); ++o) {
    bool overlap = true;
    for (int k = 0; k < D; ++k)
      overlap = overlap && fb.box.min[k] < s.blocks[o].box.max[k] - 0.5 * s.dx && s.blocks[o].box.min[k] < fb.box.max[k] - 0.5 * s.dx;
    if (overlap) r.fail(b, key, "overlaps fluid_blocks[" + std::to_string(o) + "]; blocks must not share volume");
  }
  return fb;
}

}  // namespace

void read_fluid_blocks(const Reader& r, YAML::Node& root, Scene& s) {
  const YAML::Node blocks = r.required(root, "", "fluid_blocks");
  if (!blocks.IsSequence() || blocks.size() == 0)
    r.fail(blocks, "fluid_blocks", "expected a non-empty list of blocks (min, max, ...)");
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string key = "fluid_blocks[" + std::to_string(i) + "]";
    const YAML::Node b = blocks[i];
    s.blocks.push_back(read_fluid_block(r, b, key, s));
  }
}

}  // namespace ondine::case_file
