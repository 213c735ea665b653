// buoyancy_error (reference/ErrorNorms.hpp): Archimedes' force on submerged bodies.
#include <algorithm>
#include <cmath>

#include "reference/ErrorNorms.hpp"
#include "reference/References.hpp"

namespace ondine {

double buoyancy_error(const Scene& scene, const std::vector<WallForce>& forces) {
  const double surface = scene.reference.origin[1] + scene.reference.length;
  double worst = -1;
  for (const Wall& w : scene.walls) {
    bool below = w.closed && !w.fluid_inside;
    for (const auto& pt : w.points) below = below && pt[1] < surface;
    if (!below) continue;
    const double A = reference::polygon_area(w.points);
    const double gn = std::hypot(scene.gravity[0], scene.gravity[1]);
    for (const WallForce& f : forces) {
      if (f.name != w.name) continue;
      double e2 = 0;
      for (int k = 0; k < 2; ++k) {
        const double d = f.pressure[k] + f.viscous[k] + scene.rho0 * scene.gravity[k] * A;
        e2 += d * d;
      }
      worst = std::max(worst, std::sqrt(e2) / (scene.rho0 * gn * A));
    }
  }
  return worst;
}

}  // namespace ondine
