#pragma once
// Refinement and derefinement bookkeeping of APR (thesis 5.4.1-5.4.3), as Kokkos
// passes: classify each particle (keep, delete, refine), the edit of the particle set
// (kernels/ParticleSetEdit.hpp: the survivors and 2^D copies of each refining mother),
// the renormalised prolongation gradient on the mothers
// (5.20-5.21), the daughters (5.1, 5.3, 5.22), the roles (SPH particle or guard)
// and the stable sort that makes each level contiguous. The host side is
// src/solver/AdaptiveRefinement.hpp; the design is in docs/apr.md.
#include "kernels/CellList.hpp"
#include "kernels/ParticleSetEdit.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

enum Action : int { Keep = 0, Delete = 1, Refine = 2, Derefine = 3 };

// Per particle of level r = birth level (its radius R_r):
//  - a particle that is not a mother and lies in E_{r+1} (Z_{r+1} with its
//    transition layer) becomes a mother and creates 2^D daughters;
//  - a mother more than dx_r / 2 beyond E_{r+1} stops being one (Derefine): it is
//    an SPH particle again, with the fields the guard interpolation (5.23 = 5.24)
//    gave it, and its daughters are deleted with it (DaughterRemoval), wherever
//    they are, except those inside Z_{r+1}, which are adopted (kernels/apr/Adoption.hpp).
//    Either keeps the mass of the leaves exact; a daughter that drifts beyond its
//    transition layer before its mother leaves is a passive guard until then (docs/apr.md). The dx_r / 2 hysteresis keeps a
//    mother on the layer's edge from refining and derefining at every bookkeeping.
template <int D>
struct Classify {
  RefinementZones<D> zones;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;
  Kokkos::View<int*, MemSpace> action;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const int r = birth(i);
    action(i) = Keep;
    if (r >= zones.max_level) return;
    const double d = zones.distance_to_level(xi, r + 1);
    if (mother(i) == 0 && d < zones.layer[r + 1]) {
      mother(i) = 1;
      action(i) = Refine;
    } else if (mother(i) == 1 && d >= zones.layer[r + 1] + 0.5 * zones.dx[r]) {
      mother(i) = 0;
      action(i) = Derefine;
    }
  }
};

// The global ids of the particles of level r - 1 whose daughters go: derefining
// mothers, and deleted particles that were mothers (a family leaves whole).
struct DyingScan {
  Kokkos::View<int*, MemSpace> action, birth, was_mother;
  Kokkos::View<std::int64_t*, MemSpace> id, dying;
  int level;  // r - 1
  KOKKOS_INLINE_FUNCTION bool dies(const int i) const {
    return birth(i) == level && (action(i) == Derefine || (action(i) == Delete && was_mother(i) == 1));
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& k, const bool final) const {
    if (!dies(i)) return;
    if (final) dying(k) = id(i);
    ++k;
  }
};

// Daughters (level r) of a dying mother: Delete. `dying` is sorted (binary search).
struct DaughterRemoval {
  Kokkos::View<int*, MemSpace> action, birth;
  Kokkos::View<std::int64_t*, MemSpace> parent, dying;
  int level, count;  // r
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (birth(i) != level) return;
    const std::int64_t p = parent(i);
    int lo = 0, hi = count;
    while (lo < hi) {
      const int mid = (lo + hi) / 2;
      if (dying(mid) < p) lo = mid + 1;
      else hi = mid;
    }
    if (lo < count && dying(lo) == p) action(i) = Delete;
  }
};

// Renormalised gradient over the mothers only (5.20)-(5.21): for refining mother i
// of level r, over the particles j of level r (any role) within R_r,
//   B_i = (sum_j w_j (x_j - x_i) (x) grad_i W_ij)^{-1},  G(phi)_i = B_i^T sum_j w_j (phi_j - phi_i) grad_i W_ij,
// for phi = u (each component) and rho. Kernel: the scene's kernel at R = 1, scaled.
template <int D, class UnitKernel>
struct ProlongationGradient {
  CellList<D> cells;
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  UnitKernel W1;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprBirthLevel, D> birth;
  Kokkos::View<int*, MemSpace> refining;
  Kokkos::View<double* [D + 1][D], Kokkos::LayoutRight, MemSpace> grad;  // rows: u_0 .. u_{D-1}, rho

  KOKKOS_INLINE_FUNCTION void operator()(const int k) const {
    const int i = refining(k);
    const int r = birth(i);
    const double R = zones.R[r];
    double scale = 1.0 / R;  // dW/dr at radius R from the unit kernel: W1'(r/R) / R^(D+1)
    for (int a = 0; a < D; ++a) scale /= R;
    const Vec<D> xi = load<D>(x, i), ui = load<D>(u, i);
    const double rho_i = rho(i);
    Mat<D> M = Mat<D>::zero();
    Vec<D> g[D + 1];
    for (int a = 0; a <= D; ++a) g[a] = Vec<D>::zero();
    int home[D];
    for (int a = 0; a < D; ++a) home[a] = cells.grid.coord(xi[a], a);
    const auto start = cells.cell_start;
    const auto perm = cells.sorted;
    for_each_adjacent_cell<D>(cells.grid, home, [&](const int c) {
      for (int s = start(c); s < start(c + 1); ++s) {
        const int j = perm(s);
        if (j == i || birth(j) != r) continue;
        const Vec<D> xij = box.delta(xi, load<D>(x, j));
        const double rr = kmath::sqrt(norm2(xij));
        if (rr >= R || rr <= 0.0) continue;
        const double w = m(j) / rho(j);
        const Vec<D> gradW = (W1.derivative(rr / R) * scale / rr) * xij;
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) M.a[a][b] -= w * xij[a] * gradW[b];  // (x_j - x_i) = -x_ij
        for (int a = 0; a < D; ++a) g[a] += (w * (u(j, a) - ui[a])) * gradW;
        g[D] += (w * (rho(j) - rho_i)) * gradW;
      }
    });
    Mat<D> B;
    const bool ok = invert(M, B, 1e-12);
    for (int a = 0; a <= D; ++a)
      for (int b = 0; b < D; ++b) {
        double v = 0.0;
        if (ok)
          for (int c = 0; c < D; ++c) v += B.a[c][b] * g[a][c];  // B^T g
        grad(k, a, b) = v;  // no renormalisation possible (isolated mother): injection (5.17)
      }
  }
};

// The 2^D daughters of refining mother k (5.1 with epsilon = alpha = 1/2): at
// x_m + dx_m/4 (+-1, +-1[, +-1]), mass m_m / 2^D (5.3-5.4, lambda = 1/2^D: exact
// in binary, so the mass is conserved to the last bit), u and rho by the linear
// prolongation (5.22); sum_f m_f u_f = m_m u_m since the offsets sum to zero.
template <int D>
struct DaughterFill {
  RefinementZones<D> zones;
  PeriodicBox<D> box;
  Kokkos::View<int*, MemSpace> refining, kept_index;
  Kokkos::View<double* [D + 1][D], Kokkos::LayoutRight, MemSpace> grad;
  int kept;
  std::int64_t first_id;
  // the ids of all ranks' refining mothers, sorted: family k's daughters are numbered
  // first_id + 2^D (the mother's rank in this list) + c, whatever the rank count (edit::copy_id)
  Kokkos::View<std::int64_t*, MemSpace> families;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::GlobalId, D> id;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;
  field_view_t<field::AprParent, D> parent;

  KOKKOS_INLINE_FUNCTION void operator()(const int k) const {
    const int mi = kept_index(refining(k));
    const int r = birth(mi);
    const double q = 0.25 * zones.dx[r];
    const std::int64_t family_first = edit::copy_id(families, id(mi), first_id, 1 << D, 0);
    for (int c = 0; c < (1 << D); ++c) {
      const int f = kept + (k << D) + c;
      double off[D];
      for (int a = 0; a < D; ++a) off[a] = ((c >> a) & 1) ? q : -q;
      for (int a = 0; a < D; ++a) {
        x(f, a) = box.wrap(x(mi, a) + off[a], a);
        double v = u(mi, a);
        for (int b = 0; b < D; ++b) v += grad(k, a, b) * off[b];
        u(f, a) = v;
      }
      double rf = rho(mi);
      for (int b = 0; b < D; ++b) rf += grad(k, D, b) * off[b];
      rho(f) = rf;
      m(f) = m(mi) / static_cast<double>(1 << D);
      id(f) = family_first + c;
      birth(f) = r + 1;
      mother(f) = 0;
      parent(f) = id(mi);
    }
  }
};

// Families next to a wall (not in the seed). A mother less than dx_m/4 from a wall
// (the tip of a surge sliding on the floor) would put two of its daughters on the
// solid side, where no wall term reaches them and the impermeability guard, which
// tests paths over a step, never sees them cross: 18 fine particles ended under the
// floor of the APR dam break (quick level). Mirroring them back put them within
// 0.2 dx_f of their sisters, and the fine particles on the floor became the noisiest
// of the level interface. Instead the family is moved along the wall's normal until
// its centre is dx_m/2 from the wall, so that its daughters sit dx_f/2 and 3 dx_f/2
// from it, as on a fine lattice (each facet, segment or triangle, whose span holds the
// mother's projection and that is closer than dx_m/2, periodic images included; one
// sweep per wall of a corner, D in all). Velocity and density keep their prolongation
// (5.22), so the family's momentum is unchanged; the shift is below dx_m/2.
template <int D>
struct DaughterWallClearance {
  NearFacets<D> walls;
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  Kokkos::View<int*, MemSpace> refining, kept_index;
  int kept;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;

  KOKKOS_INLINE_FUNCTION void operator()(const int k, long& moved) const {
    const int mi = kept_index(refining(k));
    const Vec<D> xm = load<D>(x, mi);
    const double half = 0.5 * zones.dx[birth(mi)];
    Vec<D> centre = xm;
    for (int sweep = 0; sweep < D; ++sweep) {  // one per wall of a corner: 2 in 2D, 3 in 3D
      double d_min = half;
      bool hit = false;
      Vec<D> n_hit = Vec<D>::zero();
      // the facets near the mother (the family's centre moves by less than dx_m / 2 < R)
      for_each_facet_near<D>(walls.cells, box, xm, [&](const int s, const Vec<D>& xs) {
        const Vec<D> cs = centre + (xs - xm);  // the centre in the facet's periodic image
        const Facet<D> f = walls.facets(s);
        if (!facet_spans<D>(cs, f)) return;
        const double d = facet_signed_distance<D>(cs, f);
        if (d <= -half || d >= d_min) return;
        d_min = d;
        n_hit = f.n_in;
        hit = true;
      });
      if (!hit) break;
      centre += (half - d_min) * n_hit;
    }
    const Vec<D> shift = centre - xm;
    if (norm2(shift) > 0.0) {
      for (int c = 0; c < (1 << D); ++c) {
        const int f = kept + (k << D) + c;
        for (int a = 0; a < D; ++a) x(f, a) = box.wrap(x(f, a) + shift[a], a);
      }
      ++moved;
    }
  }
};

// Momentum change of the refinement itself, per component and in sum m|u| (for
// scale): sum_f m_f u_f - m_m u_m over the new families (zero up to round-off,
// since the prolongation offsets sum to zero; Table 5.1).
template <int D>
struct FamilyMomentum {
  using value_type = double[];
  int value_count = D + 1;
  Kokkos::View<int*, MemSpace> refining, kept_index;
  int kept;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Mass, D> m;
  KOKKOS_INLINE_FUNCTION void init(double* v) const {
    for (int c = 0; c <= D; ++c) v[c] = 0.0;
  }
  KOKKOS_INLINE_FUNCTION void join(volatile double* a, const volatile double* b) const {
    for (int c = 0; c <= D; ++c) a[c] += b[c];
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int k, double* v) const {
    const int mi = kept_index(refining(k));
    for (int a = 0; a < D; ++a) {
      double s = -m(mi) * u(mi, a);
      for (int c = 0; c < (1 << D); ++c) s += m(kept + (k << D) + c) * u(kept + (k << D) + c, a);
      v[a] += s;
    }
    v[D] += m(mi) * kmath::sqrt(norm2(load<D>(u, mi)));
  }
};

// Roles (Algorithm 3's species): a mother inside Z_{r+1} is a mother guard, a
// daughter outside Z_r (in its transition layer) a daughter guard; every other
// particle is an SPH particle of its level (role 0). A guard that no SPH particle
// of its level can reach before the next bookkeeping (deeper than R_r + 2 skin
// inside Z_{r+1}, or farther than that from Z_r) is passive (role 2): it is
// interpolated at each bookkeeping only and carried with that velocity (the
// thesis' passive mothers); the others (role 1) are interpolated at every stage.
// Also the current level n^C and the sort key 3 r + role, which makes each level
// contiguous: SPH particles, guards, passive particles.
template <int D>
struct Roles {
  RefinementZones<D> zones;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;
  field_view_t<field::AprGuard, D> guard;
  field_view_t<field::AprLevel, D> level;
  Kokkos::View<int*, MemSpace> key;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    const int r = birth(i);
    int role = 0;
    if (mother(i) == 1 && r < zones.max_level && zones.distance_to_level(xi, r + 1) <= 0.0)
      role = zones.depth_inside_level(xi, r + 1) > zones.passive[r] ? 2 : 1;
    if (r >= 1) {
      const double d = zones.distance_to_level(xi, r);
      if (d > 0.0) role = d > zones.passive[r] ? 2 : 1;
    }
    guard(i) = role;
    level(i) = zones.depth(xi);
    key(i) = 3 * r + role;
  }
};

// The sort key of a particle that keeps its role (a list rebuild within a step).
struct RoleKey {
  Kokkos::View<int*, MemSpace> birth, guard, key;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { key(i) = 3 * birth(i) + guard(i); }
};

// Stable counting sort by key, one key at a time (a handful of keys): the
// particles with key `k` go to order[base + their rank], in index order.
struct KeyScatter {
  Kokkos::View<int*, MemSpace> key, order;
  int k, base;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& rank, const bool final) const {
    if (key(i) != k) return;
    if (final) order(base + rank) = i;
    ++rank;
  }
};

// Guards are interpolated, never integrated: zero derivatives, so that the
// Runge-Kutta stages move them with their interpolated velocity only.
template <int D>
struct ZeroGuardRates {
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) du(i, k) = 0.0;
    drho(i) = 0.0;
  }
};

}  // namespace apr

}  // namespace ondine
