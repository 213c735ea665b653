#pragma once
// The channel reference of a scene (reference.type poiseuille or couette) at height y above
// reference.origin (clamped to [0, L]) and time t: poiseuille_startup with F = body force +
// gravity along x, or couette_startup with V0 = reference.velocity (reference/References.hpp).
#include <algorithm>

#include "reference/References.hpp"
#include "scene/Scene.hpp"

namespace ondine {

inline double channel_startup(const Scene& s, double y, double t) {
  const double L = s.reference.length;
  y = std::min(std::max(y, 0.0), L);
  return s.reference.kind == ReferenceKind::Couette ? reference::couette_startup(y, t, L, s.reference.velocity, s.nu)
                                                    : reference::poiseuille_startup(y, t, L, s.body_force[0] + s.gravity[0], s.nu);
}

}  // namespace ondine
