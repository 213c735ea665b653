// buoyancy_error (observers/ErrorNorms.hpp): Archimedes' force on submerged bodies.
#include <algorithm>
#include <cmath>

#include "geometry/TriangleMesh.hpp"
#include "observers/ErrorNorms.hpp"
#include "reference/References.hpp"

namespace ondine {


// The worst relative error of the force on the closed bodies wholly below the free surface
// (reference.origin + length along the vertical axis, y in 2D, z in 3D) against Archimedes'
// -rho0 g V (V the polygon's area in 2D, the mesh's volume in 3D); -1 without such a body.
double buoyancy_error(const Scene& scene, const std::vector<WallForce>& forces) {
  const int D = scene.dimension, up = D - 1;
  const double surface = scene.reference.origin[up] + scene.reference.length;
  double worst = -1;
  for (const Wall& w : scene.walls) {
    bool below = w.closed && !w.fluid_inside;
    for (const auto& pt : w.points) below = below && pt[1] < surface;
    for (const auto& v : w.mesh.vertices) below = below && v[2] < surface;
    if (!below) continue;
    geometry::TriangleMesh body;
    body.vertices = w.mesh.vertices;
    body.triangles = w.mesh.triangles;
    const double V = D == 2 ? reference::polygon_area(w.points) : std::abs(geometry::signed_volume(body));
    double gn = 0;
    for (int k = 0; k < D; ++k) gn += scene.gravity[k] * scene.gravity[k];
    gn = std::sqrt(gn);
    for (const WallForce& f : forces) {
      if (f.name != w.name) continue;
      double e2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = f.pressure[k] + f.viscous[k] + scene.rho0 * scene.gravity[k] * V;
        e2 += d * d;
      }
      worst = std::max(worst, std::sqrt(e2) / (scene.rho0 * gn * V));
    }
  }
  return worst;
}

}  // namespace ondine
