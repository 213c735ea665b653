#pragma once
// Shifting of the daughter guards (not in the thesis; docs/apr.md, "Pressure noise at the
// level interface"; on with `refinement.guard_shifting`). Daughters are placed at
// x_m + dx_m/4 (+-1, +-1) (5.1), a Cartesian 2x2 tile per mother: a fine lattice only
// where the mothers form a coarse Cartesian one. In the dam break's surge the coarse
// particles are well ordered but not on such a lattice, and the daughters' arrangement
// is not consistent: E_i = sum_j w_j grad W_ij (+ the wall term) of the fine particles at
// the level interface was 5x that of the fine uniform run (0.07 to 0.13 / dx_f against
// 0.01 to 0.05), their kernel sum 5 to 10 % off gamma, and a third of them had a
// neighbour closer than 0.7 dx_f (1 % in the fine run). A guard is not integrated, so
// nothing orders the daughters while they cross their transition layer; once SPH
// particles, the pressure force -(2 P / rho) E_i of that disorder shook them, and the
// fine particles at the interface's foot carried 4x the pressure noise of the uniform
// runs. The thesis meets the same defect (Figs 5.5-5.10: daughters on a Cartesian
// pattern in an anisotropic flow) with its velocity law (5.14)-(5.16) on every particle.
// Here only the daughter guards move, once per time step, by the shifting of
// (2.109)-(2.111) with the NFM wall term of (4.89):
//   grad C_i = sum_j w_j (1 + 0.2 (W_ij / W(dx_r))^4) grad_i W_ij + sum_S s_q W_iq n_out,
//   dx_i = -0.05 R_r^2 grad C_i,  clamped to |dx_i| <= 0.05 dx_r,
// over the particles j of the guard's level r (SPH particles and guards), kernel at R_r.
// A guard's fields are interpolated from the SPH particles at every stage (5.24), so
// moving it changes no mass, momentum or density of any particle and needs no Taylor
// correction (2.107). Not in the thesis, and why:
//  - the coefficient 0.05 R^2, not (2.109)'s 0.5 R^2: applied at every step, 0.5 R^2
//    is an unstable iteration (round-off on a lattice grew 5x per step, then the guards
//    jittered by the clamp at every step); 0.05 R^2 damps it;
//  - only guards whose whole support lies in E_r (distance to Z_r below the layer's
//    width minus R_r and half the mothers' spacing) and is full (sum_j w_j W_ij >=
//    0.99 gamma_i): a support cut by the layer's outer edge or a free surface has a
//    concentration gradient of its own, which would push the guards into the void;
//  - not closer than dx_r / 8 to a wall (the wall-ward part of the shift is removed
//    there; the fine particles of the uniform dam break fill the band next to the floor
//    as densely as any other, so the dx_r / 2 of GuardApply::no_penetration would be
//    too strict).
// The shifts are computed from the positions at the step's start, then applied (Jacobi).
// An exactly uniform lattice flow is disturbed by the shift of the guards (at 2.6e-2 of
// the dynamic pressure in test_apr.cpp's uniform flow, against 1e-13 without), which is
// why it is an option.
//
// Mother guards (session 7, refinement.mother_shifting). A mother guard inside Z_{r+1} is carried
// with its interpolated velocity (5.24) and nothing keeps its level ordered either; it
// becomes a coarse SPH particle again when it leaves the zone. In the dam break's run-up
// along the impact wall (t > 0.25 s) the mothers collected on the line dx_r / 2 from the
// wall (where GuardApply::no_penetration removes their wall-ward velocity, while the
// fine flow interpolated there still moves towards the wall): 55 to 64 % of the level-r
// particles within 2 dx_r of the wall had a level-r neighbour closer than dx_r / 2
// (coarse uniform run: 18 %), some coincident to 0.01 dx_r, in a layer
// 0.5 to 1.3 dx_r wide where the fine jet is 2 dx_r wide. Leaving the zone's top they
// made a coarse jet of clumped particles (kernel sum up to 2.1 gamma), whose pressure
// noise was 4x the coarse run's (docs/apr.md, session 7; the other cause there, roles
// that lagged behind the flow, is fixed in ensure_neighbours, src/solver/SimulationLists.hpp). The thesis shifts the
// mothers in the zone too ((5.14)-(5.16), Figs 5.9-5.10, run 2). Here a mother guard
// moves by the same law, but against the
// concentration of its daughters' level as reference:
//   grad C_i = sum_{j in r} w_j (1 + 0.2 (W_ij / W(dx_r))^4) grad_i W_ij
//            - sum_{j in r+1} w_j grad_i W_ij,            kernel at R_r,
// i.e. the mothers are moved towards the fluid volume the fine particles fill. The fine
// level fills a mother guard's whole support (its guards cover a layer >= R_r around
// Z_{r+1}), so a free surface or a wall cuts both sums alike and their difference needs
// neither the wall term nor the full-support test: the mothers are not pushed into the
// void. Not closer than dx_r / 4 to a wall (the coarse uniform run's particles stay
// >= 0.38 dx_r from the impact wall). A mother guard's fields are interpolated (5.23-5.24),
// so again no mass, momentum or density changes. Measured: clumps removed (level-0 pairs
// closer than dx_r / 2 next to the wall 57 % -> 0); at a still free surface the top row of
// mother guards settles 0.2 dx_r higher (where the coarse and fine sums balance); the
// uniform lattice flow of test_apr.cpp is disturbed at 1.3e-4 of q (1e-12 without).
#include "kernels/CellList.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/WallSet.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

template <int D, class UnitKernel, bool Walls>
struct GuardSpacing {
  static constexpr double coef = 0.05;      // dx_i = -coef R^2 grad C_i
  static constexpr double max_step = 0.05;  // |dx_i| / dx_r per step
  static constexpr double nu_max = 0.01;    // a support short of more than 1 % of gamma is not full
  CellList<D> cells;  // positions of the owned particles and the halos (their cells may lag by the skin)
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  UnitKernel W1;      // the scene's kernel at radius 1: W(r, R) = W1(r / R) / R^D
  double R, dx;       // R_r, dx_r
  NearFacets<D> walls;       // the facets, for the clearance
  WallPoints<D> wall;        // read with Walls only
  CellList<D> wall_cells;    // the wall points binned at R_r
  field_view_t<field::Position, D> x;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;    // mother guards are not moved
  field_view_t<field::ShepardGamma, D> gamma;  // of the guards (ShepardGammaPass at R_r), read with Walls only
  Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace> shift;
  bool daughters = true;  // shift the range's daughter guards (refinement.guard_shifting)
  bool mothers = false;   // shift the range's mother guards (refinement.mother_shifting, see above)

  KOKKOS_INLINE_FUNCTION double value(const double r) const {
    double v = W1.value(r / R);
    for (int a = 0; a < D; ++a) v /= R;
    return v;
  }
  KOKKOS_INLINE_FUNCTION double derivative(const double r) const {
    double v = W1.derivative(r / R) / R;
    for (int a = 0; a < D; ++a) v /= R;
    return v;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i, long& moved) const {
    for (int a = 0; a < D; ++a) shift(i, a) = 0.0;
    const int r = birth(i);
    const Vec<D> xi = load<D>(x, i);
    const bool as_mother = mother(i) != 0;  // a mother guard (its daughters are the next level)
    if (as_mother ? !mothers : (r == 0 || !daughters)) return;
    if (!as_mother) {
      // the level's whole support in E_r (its particles reach the layer's outer edge, give or take the mothers' spacing)
      if (zones.distance_to_level(xi, r) > zones.layer[r] - R - 0.5 * zones.dx[r - 1]) return;
    }
    const double R2 = R * R, W_dx = value(dx);
    Vec<D> gradC = Vec<D>::zero();
    double sum = m(i) / rho(i) * value(0.0);
    int home[D];
    for (int a = 0; a < D; ++a) home[a] = cells.grid.coord(xi[a], a);
    const auto start = cells.cell_start;
    const auto perm = cells.sorted;
    for_each_adjacent_cell<D>(cells.grid, home, [&](const int c) {
      for (int k = start(c); k < start(c + 1); ++k) {
        const int j = perm(k);
        if (j == i) continue;
        const bool fine = as_mother && birth(j) == r + 1;  // a mother's reference: its daughters' level
        if (birth(j) != r && !fine) continue;
        const Vec<D> xij = box.delta(xi, load<D>(x, j));
        const double r2 = norm2(xij);
        if (r2 >= R2 || r2 <= 0.0) continue;
        const double rr = kmath::sqrt(r2), w = m(j) / rho(j), Wij = value(rr);
        if (fine) {
          gradC -= (w * derivative(rr) / rr) * xij;
          continue;
        }
        const double ratio = Wij / W_dx;
        gradC += (w * (1.0 + 0.2 * ratio * ratio * ratio * ratio) * derivative(rr) / rr) * xij;  // (2.110)-(2.111)
        sum += w * Wij;
      }
    });
    if (!as_mother) {
      double g = 1.0;
      if constexpr (Walls) {
        for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>&, const double rq) {
          gradC += (wall.s(q) * value(rq)) * load<D>(wall.n_out, q);  // (4.89)
        });
        g = gamma(i);
      }
      if (sum < (1.0 - nu_max) * g) return;  // a support cut by a free surface or the layer's edge
    }
    Vec<D> s = (-coef * R2) * gradC;
    const double len2 = norm2(s), cap = max_step * dx;
    if (len2 > cap * cap) s *= cap / kmath::sqrt(len2);
    // not closer than dx_r / 8 (mothers: dx_r / 4) to a wall (each facet whose span holds the guard)
    const double clearance = (as_mother ? 0.25 : 0.125) * dx;
    for_each_facet_over<D>(walls, box, xi, [&](const Facet<D>& f, const Vec<D>& xs) {
      const double sn = dot(s, f.n_in);
      if (sn < 0.0 && facet_signed_distance<D>(xs, f) + sn < clearance) s -= sn * f.n_in;
    });
    if (norm2(s) > 0.0) ++moved;
    for (int a = 0; a < D; ++a) shift(i, a) = s[a];
  }
};

// x_i += shift_i (wrapped into a periodic box)
template <int D>
struct ApplyShift {
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x;
  Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace> shift;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int a = 0; a < D; ++a) x(i, a) = box.wrap(x(i, a) + shift(i, a), a);
  }
};

}  // namespace apr

}  // namespace ondine
