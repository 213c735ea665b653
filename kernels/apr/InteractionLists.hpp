#pragma once
// The two interaction lists of APR (thesis Algorithm 3), in the CSR form of
// NeighbourList so that every existing pass reads them unchanged:
//  - L. (symmetric): for an SPH particle i of level r, the particles j of the same
//    level (SPH particles and guards) within R_r + skin. Since a particle's level is
//    its resolution, "same level" is Algorithm 3's test (a mother one level up has
//    the resolution of the daughters below); no pair of L. has two radii, so the
//    pair loop needs no test. Guards have no L. row.
//  - Lx (one way): for a guard i (active or passive), the SPH particles j of every level
//    within its interpolation radius + skin (R_{r-1} for a daughter guard of level r, which
//    fits at R_r where it can, R_{r+1} for a mother guard), the sources of its interpolation (5.24). SPH
//    particles have no Lx row; guards never see guards.
// Built in two passes (count, scan, fill) from the levels' cell lists (LevelCells.hpp),
// like NeighbourList: L. scans its own level's grid, Lx every level's.
#include "kernels/NeighbourList.hpp"
#include "kernels/apr/LevelCells.hpp"
#include "kernels/apr/RefinementZones.hpp"

namespace ondine {

namespace apr {

// Calls f(j) for every partner j of i in L. (Guards = false) or Lx (Guards = true).
template <int D, bool Guards>
struct LevelVisitor {
  LevelGrids<D> grids;
  PeriodicBox<D> box;
  Kokkos::View<int*, MemSpace> start, perm;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprGuard, D> guard;
  field_view_t<field::AprMother, D> mother;
  double cut2[kAprMaxLevels];  // (R_l + skin_l)^2
  // Lx: a guard of level r and its sources, (R + the mean of the two levels' skins)^2 with R its
  // interpolation radius: a mother guard's R_{r+1}, a daughter guard's (at most) R_{r-1}
  double mother_cut2[kAprMaxLevels], daughter_cut2[kAprMaxLevels];

  template <class F>
  KOKKOS_INLINE_FUNCTION void operator()(const int i, F&& f) const {
    if ((guard(i) != 0) != Guards) return;
    const int r = birth(i);
    // a mother guard interpolates at its daughters' radius; a daughter guard at its own,
    // or at its mother's where its own holds too few sources (GuardInterpolation.hpp)
    const double c2 = !Guards ? cut2[r] : mother(i) == 1 ? mother_cut2[r] : daughter_cut2[r];
    const double c = kmath::sqrt(c2);
    const Vec<D> xi = load<D>(x, i);
    const int first = Guards ? 0 : r, last = Guards ? grids.levels : r + 1;
    for (int l = first; l < last; ++l) {
      const int base = grids.base[l];
      for_each_cell_within<D>(grids.grid[l], xi, c, [&](const int cell) {
        for (int a = start(base + cell); a < start(base + cell + 1); ++a) {
          const int j = perm(a);
          if (j == i || (Guards && guard(j) != 0)) continue;
          if (norm2(box.delta(xi, load<D>(x, j))) < c2) f(j);
        }
      });
    }
  }
};

template <int D, bool Guards>
struct ListCount {
  LevelVisitor<D, Guards> visit;
  Kokkos::View<int*, MemSpace> off;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int cnt = 0;
    visit(i, [&](int) { ++cnt; });
    off(i + 1) = cnt;
    if (i == 0) off(0) = 0;
  }
};

struct OffsetScan {
  Kokkos::View<int*, MemSpace> off;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& partial, const bool final) const {
    partial += off(i);
    if (final) off(i) = partial;
  }
};

template <int D, bool Guards>
struct ListFill {
  LevelVisitor<D, Guards> visit;
  Kokkos::View<int*, MemSpace> off, nb;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int p = off(i);
    visit(i, [&](int j) { nb(p++) = j; });
  }
};

// Fills `list` (rows 0 .. n-1) with L. or Lx.
template <int D, bool Guards>
void build_list(NeighbourList<D>& list, const LevelVisitor<D, Guards>& visit, int n, const std::string& name) {
  if (static_cast<int>(list.offsets.extent(0)) != n + 1)
    list.offsets = Kokkos::View<int*, MemSpace>("ondine::APR::" + name + "::offsets", n + 1);
  const auto off = list.offsets;
  Kokkos::parallel_for("ondine::APR::" + name + "::count", Kokkos::RangePolicy<ExecSpace>(0, n), ListCount<D, Guards>{visit, off});
  if (n == 0) Kokkos::deep_copy(off, 0);
  Kokkos::parallel_scan("ondine::APR::" + name + "::scan", Kokkos::RangePolicy<ExecSpace>(0, n + 1), OffsetScan{off});
  const int total = list.total();
  if (static_cast<int>(list.neighbours.extent(0)) < total)
    list.neighbours = Kokkos::View<int*, MemSpace>("ondine::APR::" + name + "::neighbours", total + total / 8);
  Kokkos::parallel_for("ondine::APR::" + name + "::fill", Kokkos::RangePolicy<ExecSpace>(0, n),
                       ListFill<D, Guards>{visit, off, list.neighbours});
}

}  // namespace apr

}  // namespace ondine
