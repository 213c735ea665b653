#pragma once
// Open boundaries by buffer layers (docs/case-file.md, "Open boundaries"; docs/design.md).
// Each open boundary b is a plane normal to an axis with a buffer layer of thickness
// L_b = layers dx on its outer side; depth(b, x) > 0 in the fluid, in [-L_b, 0) in the
// buffer. A particle's role (field::OpenRole) is 0 in the fluid, b + 1 in the buffer of b.
//
// At each step start:
//  - OpenClassify: an inlet buffer particle that crossed into the fluid becomes fluid and
//    spawns its replacement L_b upstream (the buffer lattice goes on; one pushed out of the
//    buffer's outer face comes back at its front); a fluid particle that crossed an outlet
//    joins its buffer; an outlet buffer particle beyond -L_b is removed, as is a fluid
//    particle that flows back into an inlet's buffer. The masses that cross each
//    plane are summed (mass in/out of the fluid region, exactly the particles' masses).
//  - FacetSample: the fluid's Shepard state (2.40) at each facet's sample point (a dx-wide
//    square of the plane, its centre moved R/2 into the fluid), over fluid particles only:
//    the state the buffer particles of that facet extrapolate (zeroth order along n).
//  - BufferState: the buffer particle's state. Non-reflecting (characteristic conditions in
//    the spirit of Lastiwka et al. 2009, linear acoustics along the normal n into the fluid):
//    the invariant leaving the fluid, J_out = p_m - rho0 c0 u_m.n, comes from the facet's
//    sample; the one entering it is set so that its mean over the facet's relaxation time
//    gives the imposed quantity: J_in = <J_out> + 2 rho0 c0 U.n at an inlet (mean velocity U),
//    J_in = 2 p_out - <J_out> at an outlet (mean pressure p_out), <J_out> the facet's filtered
//    J_out; then p = (J_in + J_out) / 2, u.n = (J_in - J_out) / (2 rho0 c0).
//    A wave leaving the fluid passes into the buffer as into more fluid (J_in does not
//    follow it); variations slower than the relaxation time see a velocity inlet and a
//    pressure outlet.
//    Otherwise (reflecting): inlet u imposed, p = p_m; outlet u = u_m, p imposed.
//    The tangential velocity is the imposed one at an inlet, the sample's at an outlet.
//  - ZeroBufferRates (after each evaluation): the buffer particles are not integrated, they
//    move with their step-start velocity.
#include "kernels/CellList.hpp"
#include "kernels/Fields.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/ParticleSetEdit.hpp"
#include "kernels/PeriodicBox.hpp"
#include "kernels/Vec.hpp"

namespace ondine {

constexpr int kOpenMax = 8;  // = kMaxOpenBoundaries (scene/Scene.hpp)

// the open boundaries, on the device
template <int D>
struct OpenPlanes {
  int count = 0;
  int axis[kOpenMax] = {};
  double sign[kOpenMax] = {};
  double position[kOpenMax] = {};
  double L[kOpenMax] = {};       // buffer thickness (m)
  int inlet[kOpenMax] = {};      // 1 inlet, 0 outlet
  int non_reflecting[kOpenMax] = {};
  double velocity[kOpenMax][D] = {};
  int parabolic[kOpenMax] = {};
  int profile_axis[kOpenMax] = {};
  double span_lo[kOpenMax] = {}, span_hi[kOpenMax] = {};
  double pressure[kOpenMax] = {};
  // facets: the plane cut in squares of dx along its (D-1) tangential axes, over the domain
  int t_axis[kOpenMax][2] = {};
  double t_lo[kOpenMax][2] = {};
  int nf[kOpenMax][2] = {};
  int facet0[kOpenMax] = {};  // first facet index of boundary b (facets of all boundaries in one array)
  double dx = 0;

  // depth(b, x) = (x - plane).n, shifted by 1e-6 dx so that a lattice column lying on the plane
  // is fluid and one lying on the buffer's outer face is buffer whatever the round-off: a
  // buffer [-L, 0) holds exactly `layers` columns of any lattice
  KOKKOS_INLINE_FUNCTION double depth(int b, const Vec<D>& x) const { return sign[b] * (x[axis[b]] - position[b]) + 1e-6 * dx; }
  KOKKOS_INLINE_FUNCTION int facet(int b, const Vec<D>& x) const {
    int f = 0, stride = 1;
    for (int t = 0; t < D - 1; ++t) {
      int c = static_cast<int>(kmath::floor((x[t_axis[b][t]] - t_lo[b][t]) / dx));
      c = c < 0 ? 0 : (c >= nf[b][t] ? nf[b][t] - 1 : c);
      f += c * stride;
      stride *= nf[b][t];
    }
    return facet0[b] + f;
  }
  // the inlet's imposed velocity at x (the profile scales the normal component)
  KOKKOS_INLINE_FUNCTION Vec<D> imposed_velocity(int b, const Vec<D>& x) const {
    Vec<D> u;
    for (int k = 0; k < D; ++k) u[k] = velocity[b][k];
    if (parabolic[b]) {
      const double s = x[profile_axis[b]], lo = span_lo[b], hi = span_hi[b];
      const double shape = (s <= lo || s >= hi) ? 0.0 : 6.0 * (s - lo) * (hi - s) / ((hi - lo) * (hi - lo));
      for (int k = 0; k < D; ++k) u[k] *= shape;
    }
    return u;
  }
};

// what the step start does with a particle
namespace open_action {
constexpr int keep = 0, remove = 1, spawn = 2;
}

// per boundary: [0] mass into the fluid, [1] mass out of it, [2] mass created, [3] mass removed
using OpenTally = Kokkos::View<double* [4], Kokkos::LayoutRight, MemSpace>;

template <int D>
struct OpenClassify {
  OpenPlanes<D> planes;
  field_view_t<field::Position, D> x;
  field_view_t<field::Mass, D> m;
  field_view_t<field::OpenRole, D> role;
  Kokkos::View<int*, MemSpace> action, spawn_boundary;
  OpenTally tally;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const int r = role(i);
    int act = open_action::keep;
    if (r == 0) {
      for (int b = 0; b < planes.count; ++b) {
        if (planes.depth(b, xi) >= 0) continue;
        Kokkos::atomic_add(&tally(b, 1), m(i));
        if (planes.inlet[b]) {  // back into an inlet's buffer: removed
          act = open_action::remove;
          Kokkos::atomic_add(&tally(b, 3), m(i));
        } else {
          role(i) = b + 1;
        }
        break;
      }
    } else {
      const int b = r - 1;
      const double d = planes.depth(b, xi);
      if (d >= 0) {  // into the fluid
        role(i) = 0;
        Kokkos::atomic_add(&tally(b, 0), m(i));
        if (planes.inlet[b]) {
          act = open_action::spawn;
          spawn_boundary(i) = b;
          Kokkos::atomic_add(&tally(b, 2), m(i));
        }
      } else if (d < -planes.L[b]) {  // beyond the buffer's outer face
        if (planes.inlet[b]) {
          // an inlet's lane is a ring of length L: a particle pushed back out of it (by a strong
          // pressure wave) comes back at its front, so that the lane keeps its particles
          x(i, planes.axis[b]) += planes.sign[b] * planes.L[b];
        } else {
          act = open_action::remove;
          Kokkos::atomic_add(&tally(b, 3), m(i));
        }
      }
    }
    action(i) = act;
  }
};

// With refinement zones: the removed particles that have a mother (a daughter that drifted
// out with the stream while her mother stays a mother), packed as (mother level, mother id,
// -m) for AdaptiveRefinement::remove_from_families, so that every mother keeps holding her
// daughters' mass (the leaves' mass stays exact when the mother derefines)
template <int D>
struct OpenFamilyLosses {
  Kokkos::View<int*, MemSpace> action;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprParent, D> parent;
  field_view_t<field::Mass, D> m;
  Kokkos::View<double*, MemSpace> out;  // 3 per loss; sized by a first pass with out empty
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& k, const bool final) const {
    if (action(i) != open_action::remove || parent(i) < 0) return;
    if (final && out.extent(0) > 0) {
      out(3 * k) = static_cast<double>(birth(i) - 1);
      out(3 * k + 1) = static_cast<double>(parent(i));
      out(3 * k + 2) = -m(i);
    }
    ++k;
  }
};

// the spawned copies [kept, kept + n), after the gather (kernels/ParticleSetEdit.hpp): moved L_b
// upstream, into the buffer of the boundary their source crossed (spawn_boundary, by the
// source's index before the gather), with new ids next_id + (the rank of their source's id
// among all the sources of all ranks)
template <int D>
struct OpenSpawnFill {
  OpenPlanes<D> planes;
  int kept;
  Kokkos::View<int*, MemSpace> spawners, spawn_boundary;
  Kokkos::View<std::int64_t*, MemSpace> all_sources;  // sorted
  std::int64_t next_id;
  field_view_t<field::Position, D> x;
  field_view_t<field::GlobalId, D> id;
  field_view_t<field::OpenRole, D> role;
  KOKKOS_INLINE_FUNCTION void operator()(const int k) const {
    const int j = kept + k, b = spawn_boundary(spawners(k));
    x(j, planes.axis[b]) -= planes.sign[b] * planes.L[b];
    role(j) = b + 1;
    id(j) = edit::copy_id(all_sources, id(j), next_id, 1, 0);  // id(j): the source's, copied by the gather
  }
};

// the roles at the start of a run: buffer particles by position, fluid elsewhere; keep(i) = 0
// beyond a buffer's outer face
template <int D>
struct OpenInitialRoles {
  OpenPlanes<D> planes;
  field_view_t<field::Position, D> x;
  field_view_t<field::OpenRole, D> role;
  Kokkos::View<int*, MemSpace> keep;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    int r = 0, k = 1;
    for (int b = planes.count - 1; b >= 0; --b) {  // the first boundary behind which it lies, as OpenClassify
      const double d = planes.depth(b, xi);
      if (d < 0) r = b + 1;
      if (d < -planes.L[b]) k = 0;
    }
    role(i) = r;
    keep(i) = k;
  }
};

// the fluid's Shepard sums (2.40) at each facet's sample point, R/2 inside the fluid from the
// facet's centre, over the fluid particles this rank owns (the ranks' sums are added: a point
// outside a rank's cells is farther than R from its particles): w, w p, w u_k per facet
template <int D, class Kernel>
struct FacetSample {
  CellList<D> cells;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  int owned;
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> points;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::OpenRole, D> role;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> sums;  // facets x (D + 2)

  KOKKOS_INLINE_FUNCTION void operator()(const int f) const {
    const Vec<D> xs = load<D>(points, f);
    double s = 0, p = 0, us[D] = {};
    for_each_point_within<D>(cells, box, x, xs, R2, [&](const int j, const Vec<D>&, const double r) {
      if (j >= owned || role(j) != 0) return;
      const double w = m(j) / rho(j) * W.value(r);
      s += w;
      p += w * P(j);
      for (int k = 0; k < D; ++k) us[k] += w * u(j, k);
    });
    sums(f, 0) = s;
    sums(f, 1) = p;
    for (int k = 0; k < D; ++k) sums(f, 2 + k) = us[k];
  }
};

// the buffer particles' state (see the top of this file); rho from the pressure by the EOS
template <int D, class Eos>
struct BufferState {
  OpenPlanes<D> planes;
  Eos eos;
  double rho0, c0;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::OpenRole, D> role;
  // per facet: the fluid's state at its sample point now (p, u_0 .. u_D-1) and the filtered
  // invariant leaving the fluid, <J_out>
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> state;
  Kokkos::View<double*, MemSpace> J_mean;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (role(i) == 0) return;
    const int b = role(i) - 1, a = planes.axis[b];
    const double sg = planes.sign[b];
    const Vec<D> xi = load<D>(x, i);
    const int f = planes.facet(b, xi);
    Vec<D> um;
    for (int k = 0; k < D; ++k) um[k] = state(f, 1 + k);
    const double pm = state(f, 0);
    double p, un;
    Vec<D> ut;  // the velocity whose tangential components the particle takes
    // the invariant leaving the fluid, now (its mean over the relaxation time: J_mean(f))
    const double J_out = pm - rho0 * c0 * um[a] * sg;
    if (planes.inlet[b]) {
      ut = planes.imposed_velocity(b, xi);
      const double u_ref = ut[a] * sg;
      if (planes.non_reflecting[b]) {
        const double J_in = J_mean(f) + 2.0 * rho0 * c0 * u_ref;  // the mean of u.n is u_ref
        p = 0.5 * (J_in + J_out);
        un = 0.5 * (J_in - J_out) / (rho0 * c0);
      } else {
        p = pm;
        un = u_ref;
      }
    } else {
      ut = um;
      if (planes.non_reflecting[b]) {
        const double J_in = 2.0 * planes.pressure[b] - J_mean(f);  // the mean of p is the imposed pressure
        p = 0.5 * (J_in + J_out);
        un = 0.5 * (J_in - J_out) / (rho0 * c0);
      } else {
        p = planes.pressure[b];
        un = um[a] * sg;
      }
    }
    for (int k = 0; k < D; ++k) u(i, k) = ut[k];
    u(i, a) = un * sg;
    rho(i) = eos.density(p);
    P(i) = p;
  }
};

// after a shifting pass: the buffer particles keep their state and position (their lanes)
template <int D>
struct KeepBuffers {
  field_view_t<field::OpenRole, D> role;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Position, D> x_out;
  field_view_t<field::Velocity, D> u_out;
  field_view_t<field::Density, D> rho_out;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (role(i) == 0) return;
    for (int k = 0; k < D; ++k) {
      x_out(i, k) = x(i, k);
      u_out(i, k) = u(i, k);
    }
    rho_out(i) = rho(i);
  }
};

// the buffer particles are not integrated: no rates (their velocity holds through the step)
template <int D>
struct ZeroBufferRates {
  field_view_t<field::OpenRole, D> role;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  field_view_t<field::TransportCorrection, D> du0;  // unallocated without scheme.transport: ale
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (role(i) == 0) return;
    for (int k = 0; k < D; ++k) du(i, k) = 0;
    drho(i) = 0;
    if (du0.extent(0) > 0)
      for (int k = 0; k < D; ++k) du0(i, k) = 0;
  }
};

}  // namespace ondine
