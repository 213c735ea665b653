#pragma once
// The fields a checkpoint carries (io/Checkpoint.hpp), for its writer and its reader.
#include "particles/ParticleSet.hpp"

namespace ondine {

// f(tag) for each field a checkpoint carries: the state, the open boundaries' roles,
// k-epsilon's k and epsilon and the Langevin model's path-averaged gradient where allocated, and with refinement zones the APR fields (level, role, mother flag and
// mother's id of each particle)
template <int D, class F>
void for_each_checkpoint_field(const ParticleSet<D>& p, bool refinement, F&& f) {
  f(field::Position{});
  f(field::Velocity{});
  f(field::Density{});
  f(field::Mass{});
  f(field::GlobalId{});
  if (p.has(field::OpenRole{})) f(field::OpenRole{});
  if (p.has(field::TurbulentKineticEnergy{})) {  // k-epsilon's transported state
    f(field::TurbulentKineticEnergy{});
    f(field::DissipationRate{});
  }
  if (p.has(field::LangevinGradientX{})) {  // the Langevin model's path-averaged gradient
    f(field::LangevinGradientX{});
    f(field::LangevinGradientY{});
    if (D == 3) f(field::LangevinGradientZ{});
  }
  if (!refinement) return;
  f(field::AprBirthLevel{});
  f(field::AprLevel{});
  f(field::AprGuard{});
  f(field::AprMother{});
  f(field::AprParent{});
}

}  // namespace ondine
