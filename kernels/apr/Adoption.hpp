#pragma once
// Adoption (not in the seed; docs/apr.md "Derefinement"): a daughter of a dying
// mother that is an SPH particle of its level (inside Z_r) is not deleted with her
// family but re-parented to the nearest mother guard of level r - 1 within R_{r-1},
// and its mass moves with it: the dying mother keeps the mass of the daughters that
// go with her (or goes herself when none does), the adopter's grows by the
// daughter's, and so up to the coarsest level, so that every mother holds the sum
// of her daughters' masses (5.3-5.4) and the leaves' mass stays exact. Deleting the
// family whole empties the fine zone where a daughter has drifted far from her
// mother (a wake); adoption keeps the fine level's volume where it is.
#include <cstdint>

#include "kernels/CellList.hpp"
#include "kernels/ParticleSetEdit.hpp"
#include "kernels/apr/Refinement.hpp"
#include "kernels/apr/RefinementZones.hpp"
#include "kernels/apr/CutTrim.hpp"

namespace ondine::apr {

// Level-r daughter i marked Delete by DaughterRemoval and inside Z_r: its adopter is
// the nearest particle j (owned or halo) of level r - 1 that was a mother before this
// bookkeeping and stays one (not refining: its new daughters take their mass from it
// next), lies inside Z_r (a mother guard: it does not derefine) and whose own family
// is not dying (its parent is not in `dying_above`, the ids of level r - 2 whose
// daughters go); ties by the smaller id, so that the choice does not depend on the
// rank count. Adopted: i takes back its classified action, `from(i)` is its old
// mother and `parent(i)` the adopter. Counts (adopted, left without an adopter).
template <int D>
struct Adoption {
  using value_type = long[];
  int value_count = 2;
  CellList<D> cells;
  PeriodicBox<D> box;
  RefinementZones<D> zones;
  field_view_t<field::Position, D> x;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;
  field_view_t<field::AprParent, D> parent;
  field_view_t<field::GlobalId, D> id;
  Kokkos::View<int*, MemSpace> action, classified;
  Kokkos::View<std::int64_t*, MemSpace> dying_above, from;
  int level, n;  // r, the owned count

  KOKKOS_INLINE_FUNCTION bool adopts(const int j) const {
    if (birth(j) != level - 1 || mother(j) != 1) return false;
    if (j < n && action(j) != Keep) return false;
    if (zones.distance_to_level(load<D>(x, j), level) > 0.0) return false;
    if (dying_above.extent(0) == 0) return true;
    const std::int64_t p = parent(j);
    const int k = edit::rank_among(dying_above, p);
    return !(k < static_cast<int>(dying_above.extent(0)) && dying_above(k) == p);
  }

  KOKKOS_INLINE_FUNCTION void init(long* v) const { v[0] = v[1] = 0; }
  KOKKOS_INLINE_FUNCTION void join(volatile long* a, const volatile long* b) const {
    a[0] += b[0];
    a[1] += b[1];
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int i, long* count) const {
    from(i) = -1;
    if (birth(i) != level || action(i) != Delete) return;
    const Vec<D> xi = load<D>(x, i);
    if (zones.distance_to_level(xi, level) > 0.0) return;  // a daughter guard goes with her family
    const double R = zones.R[level - 1];
    double best = R * R;
    int found = -1;
    int home[D];
    for (int a = 0; a < D; ++a) home[a] = cells.grid.coord(xi[a], a);
    const auto start = cells.cell_start;
    const auto perm = cells.sorted;
    for_each_adjacent_cell<D>(cells.grid, home, [&](const int c) {
      for (int s = start(c); s < start(c + 1); ++s) {
        const int j = perm(s);
        if (!adopts(j)) continue;
        const double r2 = norm2(box.delta(xi, load<D>(x, j)));
        if (r2 < best || (r2 == best && found >= 0 && id(j) < id(found))) {
          best = r2;
          found = j;
        }
      }
    });
    if (found < 0) {
      ++count[1];
      return;
    }
    from(i) = parent(i);
    parent(i) = id(found);
    action(i) = classified(i);
    ++count[0];
  }
};

// The (mother id, mass change) pairs of the adoptions of one level, packed: the old
// mother loses the daughter's mass, the adopter gains it.
template <int D>
struct AdoptionScan {
  Kokkos::View<std::int64_t*, MemSpace> from;
  field_view_t<field::AprParent, D> parent;
  field_view_t<field::Mass, D> m;
  Kokkos::View<double*, MemSpace> pairs;  // 4 per adoption; sized by a first pass with pairs empty
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& k, const bool final) const {
    if (from(i) < 0) return;
    if (final && pairs.extent(0) > 0) {
      pairs(4 * k) = static_cast<double>(from(i));
      pairs(4 * k + 1) = -m(i);
      pairs(4 * k + 2) = static_cast<double>(parent(i));
      pairs(4 * k + 3) = m(i);
    }
    ++k;
  }
};

// The mass changes of level `level`'s particles (sorted by id; sums of m_m / 2^D,
// exact in binary): m += the sum of its changes; a particle left without mass (a
// dying mother whose daughters were all adopted) goes. `change(i)`: what it passes
// on to its own mother (packed by LossScan, kernels/apr/CutTrim.hpp).
template <int D>
struct MassChange {
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::GlobalId, D> id;
  Kokkos::View<std::int64_t*, MemSpace> target;
  Kokkos::View<double*, MemSpace> delta;
  Kokkos::View<int*, MemSpace> action;
  Kokkos::View<double*, MemSpace> change;
  int level;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    change(i) = 0.0;
    if (birth(i) != level) return;
    const double sum = sum_for_id(target, delta, id(i));
    if (sum == 0.0) return;
    const double before = m(i);
    m(i) = before + sum;
    change(i) = sum;
    if (m(i) <= 1e-9 * before) {
      m(i) = 0.0;
      action(i) = Delete;
    }
  }
};

}  // namespace ondine::apr
