#pragma once
// The fill at each level's own spacing (fluid_blocks[i].cut with refinement zones): after the
// first levels are created from the coarse lattice (which reaches beyond each cut by its
// finest descendants' reach, src/solver/FillCutsBuild.hpp), a particle that is not a mother
// and lies beyond its block's cuts goes, and a mother keeps the mass of the daughters left
// to it (sums of m_m / 2^D, exact in binary) or goes with the last of them. One level per
// pass, the finest first; `removed` holds the next level's losses by mother id.
#include <cstdint>

#include "kernels/FillCuts.hpp"
#include "kernels/ParticleSetEdit.hpp"
#include "kernels/apr/Refinement.hpp"

namespace ondine::apr {

// the sum of the values whose id (sorted, with repeats) is `id`
KOKKOS_INLINE_FUNCTION double sum_for_id(const Kokkos::View<std::int64_t*, MemSpace>& ids, const Kokkos::View<double*, MemSpace>& values,
                                         std::int64_t id) {
  double sum = 0.0;
  for (int k = edit::rank_among(ids, id); k < static_cast<int>(ids.extent(0)) && ids(k) == id; ++k) sum += values(k);
  return sum;
}

template <int D>
struct CutTrim {
  FillCuts<D> cuts;
  field_view_t<field::Position, D> x;
  field_view_t<field::Mass, D> m;
  field_view_t<field::AprBirthLevel, D> birth;
  field_view_t<field::AprMother, D> mother;
  field_view_t<field::GlobalId, D> id;
  Kokkos::View<std::int64_t*, MemSpace> removed_parent;  // the next level's losses, sorted by mother id
  Kokkos::View<double*, MemSpace> removed_mass;
  Kokkos::View<int*, MemSpace> action;  // Keep or Delete
  Kokkos::View<double*, MemSpace> lost;  // the mass this particle's mother loses with it
  int level;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    lost(i) = 0.0;
    if (birth(i) != level) return;
    if (mother(i) == 1) {
      const double gone = sum_for_id(removed_parent, removed_mass, id(i));
      if (gone == 0.0) return;
      const double before = m(i);
      if (before - gone <= 1e-9 * before) {
        action(i) = Delete;
        lost(i) = before;
      } else {
        m(i) = before - gone;
        lost(i) = gone;
      }
      return;
    }
    const Vec<D> p = load<D>(x, i);
    const int b = cuts.block_of(p);
    if (b >= 0 && !cuts.inside(b, p, false)) {
      action(i) = Delete;
      lost(i) = m(i);
    }
  }
};

// the (mother id, mass change) pairs of the particles of one level with a change (a loss of the
// trim, a change passed on by adoption, kernels/apr/Adoption.hpp), packed
template <int D>
struct LossScan {
  Kokkos::View<double*, MemSpace> lost;
  field_view_t<field::AprParent, D> parent;
  Kokkos::View<double*, MemSpace> pairs;  // 2 per change; sized by a first pass with pairs empty
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& k, const bool final) const {
    if (lost(i) == 0.0 || parent(i) < 0) return;
    if (final && pairs.extent(0) > 0) {
      pairs(2 * k) = static_cast<double>(parent(i));
      pairs(2 * k + 1) = lost(i);
    }
    ++k;
  }
};

}  // namespace ondine::apr
