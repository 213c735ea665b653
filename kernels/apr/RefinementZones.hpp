#pragma once
// The refinement zones of adaptive particle refinement (thesis 5.4) as a small
// trivially-copyable table read by device kernels: boxes, each with its level
// (depth of nesting), the radius R_l = R_0 / 2^l and spacing dx_l = dx_0 / 2^l of
// every level, and the width of the daughter-guard (transition) layer of each
// level, w_l = transition * R_{l-1} (thesis: R_m = 2 R_f). Z_l is the union of the
// boxes of level l; E_l = {x : dist(x, Z_l) < w_l} is Z_l with its transition layer.
#include "kernels/PeriodicBox.hpp"

namespace ondine {

constexpr int kAprMaxLevels = 7;  // levels 0 .. 6 (Scene's kMaxRefinementLevel)
constexpr int kAprMaxZones = 16;

template <int D>
struct RefinementZones {
  int count = 0;
  int max_level = 0;
  double lo[kAprMaxZones][D], hi[kAprMaxZones][D];
  int level[kAprMaxZones];
  double R[kAprMaxLevels], dx[kAprMaxLevels], layer[kAprMaxLevels];
  // a guard of level l farther than passive[l] = R_l + 2 skin from every SPH particle of
  // its level is passive: no SPH particle reaches it before the next bookkeeping
  double passive[kAprMaxLevels];
  PeriodicBox<D> box;

  // Euclidean distance from x to zone z (0 inside); minimum image along periodic axes.
  KOKKOS_INLINE_FUNCTION double distance(const int z, const Vec<D>& x) const {
    double d2 = 0.0;
    for (int k = 0; k < D; ++k) {
      double e;
      if (box.periodic[k]) {
        const double half = 0.5 * (hi[z][k] - lo[z][k]);
        if (2.0 * half >= box.len[k]) continue;  // spans the periodic axis
        double c = x[k] - 0.5 * (hi[z][k] + lo[z][k]);
        c -= box.len[k] * kmath::floor(c / box.len[k] + 0.5);
        e = (c < 0 ? -c : c) - half;
      } else {
        e = lo[z][k] - x[k];
        const double f = x[k] - hi[z][k];
        if (f > e) e = f;
      }
      if (e > 0) d2 += e * e;
    }
    return kmath::sqrt(d2);
  }

  // distance from x to Z_l (a large number when level l has no zone)
  KOKKOS_INLINE_FUNCTION double distance_to_level(const Vec<D>& x, const int l) const {
    double d = 1e300;
    for (int z = 0; z < count; ++z)
      if (level[z] == l) {
        const double e = distance(z, x);
        if (e < d) d = e;
      }
    return d;
  }

  // how deep x lies inside Z_l: the largest, over the zones of level l, of the
  // distance from x to the zone's faces (0 outside); axes a zone spans are ignored
  KOKKOS_INLINE_FUNCTION double depth_inside_level(const Vec<D>& x, const int l) const {
    double best = 0.0;
    for (int z = 0; z < count; ++z) {
      if (level[z] != l) continue;
      double m = 1e300;
      for (int k = 0; k < D; ++k) {
        double e;
        if (box.periodic[k]) {
          const double half = 0.5 * (hi[z][k] - lo[z][k]);
          if (2.0 * half >= box.len[k]) continue;
          double c = x[k] - 0.5 * (hi[z][k] + lo[z][k]);
          c -= box.len[k] * kmath::floor(c / box.len[k] + 0.5);
          e = half - (c < 0 ? -c : c);
        } else {
          e = x[k] - lo[z][k];
          const double f = hi[z][k] - x[k];
          if (f < e) e = f;
        }
        if (e < m) m = e;
      }
      if (m > best) best = m;
    }
    return best;
  }

  // current level n^C of a point: the depth of the deepest zone containing it
  KOKKOS_INLINE_FUNCTION int depth(const Vec<D>& x) const {
    int l = 0;
    for (int z = 0; z < count; ++z)
      if (level[z] > l && distance(z, x) <= 0.0) l = level[z];
    return l;
  }
};

// W(r, R_l) = W1(r / R_l) / R_l^D of a particle of level l, from the scene's kernel at
// radius 1 (the per-level Shepard sums of the probes, wall forces and wave gauges); 0 at
// r >= R_l.
template <int D, class UnitKernel>
KOKKOS_INLINE_FUNCTION double level_kernel(const RefinementZones<D>& zones, const UnitKernel& W1, const int level, const double r) {
  const double R = zones.R[level];
  if (r >= R) return 0.0;
  double RD = 1.0;
  for (int k = 0; k < D; ++k) RD *= R;
  return W1.value(r / R) / RD;
}

}  // namespace ondine
