#pragma once
// Impermeability guard of the NFM walls (not in the thesis). The wall terms of
// (4.20)-(4.25) keep particles out of a wall only through the wall pressure
// P_p = P_f + rho c (u - u_w).n (4.14): a particle of a thin film or jet at about
// zero pressure that drifts onto a wall feels no restoring force, and one pushed
// hard enough (an impact, a start 0.01 dx from a corner) goes through the wall and
// is lost behind it or blows up (docs/validation.md, stability suite).
// After each time step, the path of each particle over the step, from x0 (the
// start of the step, moved with the wall's normal motion: x0 + (u_w.n) n dt) to x1, is tested against
// every wall facet near its end (a segment in 2D, a triangle in 3D); where it crosses one
// from the fluid side (the earliest crossing, corners included), x1 is mirrored back
// across that facet's line or plane,
// x1 <- x1 - 2 d1 n_in, and the velocity relative to the wall loses its component
// into the wall (an inelastic collision: no energy is added). Two sweeps, for the
// second wall of a corner. Mass is untouched; the momentum removed is the wall's
// reaction. Each corrected particle is counted (summary.json errors
// `wall_corrections`), so a run says how often the guard acted; the leak
// diagnostics (wall_leaks, outside_domain) still count particles that end close
// to a wall. The facets are those of the cell of the path's end (kernels/WallSet.hpp), which
// holds every facet within R of it: a path over one step is much shorter than R.
#include "kernels/WallSet.hpp"

namespace ondine {

template <int D>
struct WallImpermeability {
  WallFacets<D> facets;
  FacetCells<D> cells;  // the facets near the end of the path (a path shorter than R)
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> wall_velocity;  // per wall
  double dt;
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x0;  // the start of the step (stage storage)
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  // per wall: angular velocity (3) and centre (3) of a rotating wall; empty: none rotates
  Kokkos::View<double* [6], Kokkos::LayoutRight, MemSpace> wall_spin = {};

  // the velocity of wall w's material point at p: its translation, plus omega x (p - centre)
  KOKKOS_INLINE_FUNCTION Vec<D> wall_point_velocity(const int w, const Vec<D>& p) const {
    Vec<D> v = load<D>(wall_velocity, w);
    if (wall_spin.extent(0) == 0) return v;
    double r[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) r[k] = p[k] - wall_spin(w, 3 + k);
    const double cr[3] = {wall_spin(w, 1) * r[2] - wall_spin(w, 2) * r[1], wall_spin(w, 2) * r[0] - wall_spin(w, 0) * r[2],
                          wall_spin(w, 0) * r[1] - wall_spin(w, 1) * r[0]};
    for (int k = 0; k < D; ++k) v[k] += cr[k];
    return v;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i, long& corrected) const {
    const Vec<D> x1_stored = load<D>(x, i);
    Vec<D> from = load<D>(x0, i);
    Vec<D> to = from + box.delta(x1_stored, from);  // unwrapped end of the path
    Vec<D> ui = load<D>(u, i);
    bool moved = false;
    bool first_sweep = true;
    for (int sweep = 0; sweep < 2; ++sweep) {
      int hit = -1;
      double tau_hit = 2.0, d_end = 0.0;
      Vec<D> image = Vec<D>::zero();
      Vec<D> q;  // the end of the path wrapped into the box: its cell lists the facets near it
      for (int k = 0; k < D; ++k) q[k] = box.wrap(to[k], k);
      for_each_facet_near<D>(cells, box, q, [&](const int s, const Vec<D>& xs) {
        Facet<D> f = facets(s);
        const Vec<D> off = xs - to;  // the facet's image in the frame of the path: f - off
        f.a -= off;
        f.b -= off;
        f.c -= off;
        const Vec<D> n = f.n_in;
        // the start moves with the wall's normal motion over the step (first sweep; then it
        // is on the wall). Only the normal part: a sliding wall (a cavity lid) keeps its
        // facets in place, and shifting by its tangential velocity would carry the path
        // past the facet's edge and miss a crossing next to a corner.
        const Vec<D> p0 = first_sweep ? from + (dt * dot(wall_point_velocity(facets.wall(s), from), n)) * n : from;
        const double d0 = facet_signed_distance<D>(p0, f), d1 = facet_signed_distance<D>(to, f);
        if (!(d0 >= 0.0 && d1 < 0.0)) return;
        const double tau = d0 / (d0 - d1);
        const Vec<D> pc = p0 + tau * (to - p0);
        if (!facet_spans<D>(pc, f, 1e-9) || tau >= tau_hit) return;
        tau_hit = tau;
        hit = s;
        d_end = d1;
        image = pc;
      });
      if (hit < 0) break;
      const Vec<D> n = load<D>(facets.n_in, hit);
      to += (-2.0 * d_end) * n;
      const double vn = dot(ui - wall_point_velocity(facets.wall(hit), image), n);
      if (vn < 0.0) ui += (-vn) * n;
      from = image + (1e-12 * box.len[0]) * n;  // the crossing point, on the fluid side
      first_sweep = false;
      moved = true;
    }
    if (moved) {
      // back in the same periodic image as the stored position
      store<D>(x, i, x1_stored + (to - (load<D>(x0, i) + box.delta(x1_stored, load<D>(x0, i)))));
      store<D>(u, i, ui);
      ++corrected;
    }
  }

  long run(int n) const { return run(0, n); }
  long run(int first, int end) const {
    long c = 0;
    Kokkos::parallel_reduce("ondine::NFM::impermeability", Kokkos::RangePolicy<ExecSpace>(first, end), *this, c);
    return c;
  }
};

}  // namespace ondine
