#include <cmath>
#include <sstream>

#include "scene/CaseSections.hpp"

namespace ondine::case_file {

namespace {

// the normal into the fluid: a unit vector along one axis
void read_normal(const Reader& r, const YAML::Node& item, const std::string& key, const Scene& s, OpenBoundary& b) {
  const int D = s.dimension;
  const Vec3 n = r.vector(r.required(item, key, "normal"), key + ".normal", D, " (a unit vector along an axis, into the fluid)");
  int axis = -1, nonzero = 0;
  for (int k = 0; k < D; ++k)
    if (n[k] != 0) {
      ++nonzero;
      axis = k;
    }
  if (nonzero != 1 || std::abs(std::abs(n[axis]) - 1) > 1e-12)
    r.fail(item["normal"], key + ".normal", "expected a unit vector along an axis, such as [1, 0] (the plane is normal to an axis)");
  b.axis = axis;
  b.sign = n[axis] > 0 ? 1 : -1;
  if (s.periodic[axis]) r.fail(item["normal"], key + ".normal", "the domain is periodic along this axis: an open boundary needs a non-periodic one");
}

// the buffer [position - layers dx, position] (inlet facing +axis) lies inside the domain and
// inside a fluid block, so that it starts full
void check_buffer(const Reader& r, const YAML::Node& item, const std::string& key, const Scene& s, const OpenBoundary& b) {
  const double L = b.layers * s.dx;
  const double outer = b.position - b.sign * L;
  const int a = b.axis;
  const double lo = std::min(outer, b.position), hi = std::max(outer, b.position);
  if (lo < s.domain.min[a] - 1e-9 * s.dx || hi > s.domain.max[a] + 1e-9 * s.dx) {
    std::ostringstream m;
    m << "the buffer layer [" << lo << ", " << hi << "] m along " << "xyz"[a] << " (layers x dx) must lie inside the domain";
    r.fail(item["position"], key + ".position", m.str());
  }
  bool filled = false;
  for (const FluidBlock& f : s.blocks) filled = filled || (f.box.min[a] <= lo + 1e-9 * s.dx && f.box.max[a] >= hi - 1e-9 * s.dx);
  if (!filled)
    r.fail(item["position"], key + ".position", "no fluid block covers the buffer layer: extend a fluid block over it, so that the buffer starts full");
}

// the refinement zones (with their transition layers) keep clear of the buffer and of the
// fluid the buffer particles act on (within R of the plane) and read (the facets' sample
// points R/2 inside, with their supports): 1.5 R, and no zone moves (it could drift there);
// the particles there are coarse SPH particles
void check_zones_clear(const Reader& r, const YAML::Node& item, const std::string& key, const Scene& s, const OpenBoundary& b) {
  const int a = b.axis;
  const double L = b.layers * s.dx, reach = 1.5 * s.R();
  const double lo = b.sign > 0 ? b.position - L : b.position - reach, hi = b.sign > 0 ? b.position + reach : b.position + L;
  for (const RefinementZone& z : s.refinement_zones) {
    if (z.motion != ZoneMotion::Static)
      r.fail(item, key, "the refinement zone '" + z.name + "' moves: open boundaries take static zones only (a moving zone could reach a buffer)");
    const double w = s.refinement_transition * s.R() / std::ldexp(1.0, z.level - 1);
    if (z.box.min[a] - w < hi && z.box.max[a] + w > lo) {
      std::ostringstream m;
      m << "the refinement zone '" << z.name << "' (with its transition layer of " << w << " m) reaches the buffer layer or the fluid it "
        << "works with ([" << lo << ", " << hi << "] m along " << "xyz"[a] << "): keep the zones clear of the open boundaries";
      r.fail(item["position"], key + ".position", m.str());
    }
  }
}

void read_inlet(const Reader& r, const YAML::Node& item, const std::string& key, const Scene& s, OpenBoundary& b) {
  const int D = s.dimension;
  b.velocity = r.vector(r.required(item, key, "velocity"), key + ".velocity", D, " (m/s)");
  if (!(b.velocity[b.axis] * b.sign > 0))
    r.fail(item["velocity"], key + ".velocity", "an inlet's velocity must point into the fluid (along its normal)");
  if (item["pressure"]) r.fail(item["pressure"], key + ".pressure", "an inlet imposes its velocity; pressure belongs to an outlet");
  if (!item["profile"]) return;
  const std::string p = r.word(item["profile"], key + ".profile", {"uniform", "parabolic"});
  if (p == "uniform") return;
  b.profile = InletProfile::Parabolic;
  const std::string ax = r.word(r.required(item, key, "profile_axis"), key + ".profile_axis", {"x", "y", "z"});
  b.profile_axis = ax[0] - 'x';
  if (b.profile_axis >= D || b.profile_axis == b.axis)
    r.fail(item["profile_axis"], key + ".profile_axis", "expected an axis of the plane (not its normal's)");
  const YAML::Node span = r.required(item, key, "profile_span");
  if (!span.IsSequence() || span.size() != 2) r.fail(span, key + ".profile_span", "expected [lo, hi] (m) along profile_axis");
  b.span_lo = r.number(span[0], key + ".profile_span", "a coordinate (m)");
  b.span_hi = r.number(span[1], key + ".profile_span", "a coordinate (m)");
  if (!(b.span_hi > b.span_lo)) r.fail(span, key + ".profile_span", "expected lo < hi");
}

}  // namespace

void read_open_boundaries(const Reader& r, YAML::Node& root, Scene& s) {
  const YAML::Node ob = root["open_boundaries"];
  if (!ob) return;
  if (!ob.IsSequence() || ob.size() == 0) r.fail(ob, "open_boundaries", "expected a list of inlets and outlets");
  if (ob.size() > static_cast<std::size_t>(kMaxOpenBoundaries))
    r.fail(ob, "open_boundaries", "more than " + std::to_string(kMaxOpenBoundaries) + " open boundaries");
  if (s.flux == FluxScheme::Riemann && s.riemann_variant == RiemannVariant::Vila)
    r.fail(ob, "open_boundaries", "Vila's Riemann-SPH (masses that change by fluxes) is not supported with open boundaries: use scheme.riemann.variant: leduc");
  for (std::size_t i = 0; i < ob.size(); ++i) {
    const std::string key = "open_boundaries[" + std::to_string(i) + "]";
    const YAML::Node item = ob[i];
    r.only_keys(item, key, {"name", "type", "normal", "position", "layers", "velocity", "profile", "profile_axis", "profile_span",
                            "pressure", "non_reflecting", "relaxation_time"});
    OpenBoundary b;
    b.name = r.text(r.required(item, key, "name"), key + ".name", "a name");
    if (b.name.find_first_of(", \"") != std::string::npos)
      r.fail(item["name"], key + ".name", "expected a name without commas, spaces or quotes (it heads CSV columns)");
    for (const OpenBoundary& o : s.open_boundaries)
      if (o.name == b.name) r.fail(item["name"], key + ".name", "duplicate open boundary name '" + b.name + "'");
    b.kind = r.word(r.required(item, key, "type"), key + ".type", {"inlet", "outlet"}) == "inlet" ? OpenKind::Inlet : OpenKind::Outlet;
    read_normal(r, item, key, s, b);
    for (const OpenBoundary& o : s.open_boundaries)
      if (o.axis != b.axis)
        r.fail(item["normal"], key + ".normal", "all open boundaries must be normal to the same axis (their buffer layers would cross)");
    b.position = r.number(r.required(item, key, "position"), key + ".position", "a coordinate (m) along the normal's axis");
    const int min_layers = static_cast<int>(std::ceil(s.R_over_dx - 1e-9));
    b.layers = item["layers"] ? static_cast<int>(r.integer(item["layers"], key + ".layers", min_layers, 64)) : min_layers;
    check_buffer(r, item, key, s, b);
    if (b.kind == OpenKind::Inlet) {
      read_inlet(r, item, key, s, b);
    } else {
      for (const char* k : {"velocity", "profile", "profile_axis", "profile_span"})
        if (item[k]) r.fail(item[k], key + "." + k, "an outlet's velocity is extrapolated from the fluid; velocity and profile belong to an inlet");
      if (item["pressure"]) b.pressure = r.number(item["pressure"], key + ".pressure", "a pressure (Pa)");
    }
    if (item["non_reflecting"]) b.non_reflecting = r.boolean(item["non_reflecting"], key + ".non_reflecting");
    // default filter time: one acoustic crossing of the domain along the normal
    b.relaxation_time = (s.domain.max[b.axis] - s.domain.min[b.axis]) / s.c0;
    if (item["relaxation_time"]) b.relaxation_time = r.positive(item["relaxation_time"], key + ".relaxation_time", " (s)");
    for (const OpenBoundary& o : s.open_boundaries) {
      const double lo = std::min(b.position, b.position - b.sign * b.layers * s.dx), hi = std::max(b.position, b.position - b.sign * b.layers * s.dx);
      const double olo = std::min(o.position, o.position - o.sign * o.layers * s.dx), ohi = std::max(o.position, o.position - o.sign * o.layers * s.dx);
      if (lo < ohi && olo < hi) r.fail(item["position"], key + ".position", "its buffer layer overlaps the one of '" + o.name + "'");
    }
    check_zones_clear(r, item, key, s, b);
    // the boundaries face each other: each plane lies on the fluid side of the others
    for (const OpenBoundary& o : s.open_boundaries)
      if (o.sign * (b.position - o.position) <= 0 || b.sign * (o.position - b.position) <= 0)
        r.fail(item["normal"], key + ".normal",
               "the fluid side of '" + b.name + "' and that of '" + o.name + "' do not overlap: each normal must point towards the other plane");
    // the fluid side holds fluid: the plane is not at the domain's face it faces
    {
      const double inner = b.sign > 0 ? s.domain.max[b.axis] - b.position : b.position - s.domain.min[b.axis];
      if (inner < b.layers * s.dx) r.fail(item["normal"], key + ".normal", "the normal must point into the domain, towards the fluid");
    }
    s.open_boundaries.push_back(b);
  }
}

}  // namespace ondine::case_file
