#include "scene/MemoryEstimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geometry/TriangleMesh.hpp"

namespace ondine {

namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (!v) return fallback;
  const int n = std::atoi(v);
  return n > 0 ? n : fallback;
}

}  // namespace

MemoryEstimate estimate_memory(const Scene& s) {
  MemoryEstimate e;
  const int D = s.dimension;
  for (const FluidBlock& b : s.blocks) {
    double c = 1;
    for (int k = 0; k < D; ++k) c *= std::round((b.box.max[k] - b.box.min[k]) / s.dx);
    e.particles += c;
  }
  // each zone of level l, widened by its guard layer (transition R_{l-1}) and clipped to the
  // domain, full of particles at dx / 2^l: a bound for a zone that moves or that fills up
  for (const RefinementZone& z : s.refinement_zones) {
    const double dx_l = s.dx / std::pow(2.0, z.level), layer = s.refinement_transition * s.R() / std::pow(2.0, z.level - 1);
    double c = 1;
    for (int k = 0; k < D; ++k) {
      const double lo = std::max(z.box.min[k] - layer, s.domain.min[k]), hi = std::min(z.box.max[k] + layer, s.domain.max[k]);
      c *= std::max(0.0, hi - lo) / dx_l;
    }
    e.refined_particles += c;
  }
  // 2D: every level at the finest level's dx / 4 (solver/SimulationSetup.hpp)
  const double dx_finest = s.dx / std::pow(2.0, s.max_refinement_level());
  if (D == 3) {
    // each level's own quadrature (solver/SimulationLists.hpp, build_level_walls)
    double area = 0;
    for (const Wall& w : s.walls) area += geometry::total_area(geometry::TriangleMesh{w.mesh.vertices, w.mesh.triangles});
    for (int l = 0; l <= s.max_refinement_level(); ++l) {
      const double h = s.wall_quadrature_spacing > 0 ? s.wall_quadrature_spacing
                       : (s.wall_quadrature_spacing_dx > 0 ? s.wall_quadrature_spacing_dx : 0.5) * s.dx / std::pow(2.0, l);
      e.wall_points += area / (h * h);
    }
  } else {
    const double h = s.wall_quadrature_spacing > 0 ? s.wall_quadrature_spacing
                     : (s.wall_quadrature_spacing_dx > 0 ? s.wall_quadrature_spacing_dx : 0.25) * dx_finest;
    for (const Wall& w : s.walls)
      for (std::size_t i = 0; i + 1 < w.points.size() + (w.closed ? 1 : 0); ++i) {
        const auto& a = w.points[i];
        const auto& b = w.points[(i + 1) % w.points.size()];
        e.wall_points += std::hypot(b[0] - a[0], b[1] - a[1]) / h;
      }
  }
  // the stored neighbour lists grow with the neighbours in a support: (R / 3 dx)^D
  const double support = std::max(1.0, std::pow(s.R_over_dx / 3.0, D));
  e.bytes_per_particle = (D == 3 ? kBytesPerParticle3D : kBytesPerParticle2D) * support;
  e.bytes_per_refined_particle = (D == 3 ? kBytesPerRefinedParticle3D : kBytesPerRefinedParticle2D) * support;
  // scheme.pair_list: half adds its list (half the entries within R + skin, 4 B each) and the
  // flux's per-thread copies of du and drho (measured at 1e6 particles in 3D, R = 2.5 dx:
  // +238 B per particle, this formula 248 B; perf/README.md)
  if (s.half_pair_list) {
    const double reach = s.R_over_dx + s.neighbour_skin, pi = 3.14159265358979;
    const double entries = D == 3 ? 4.0 / 3.0 * pi * reach * reach * reach : pi * reach * reach;
    e.bytes_per_particle += 0.5 * entries * 4.0 + 8.0 * (D + 1) * env_int("OMP_NUM_THREADS", 2);
  }
  e.ranks = env_int("OMPI_COMM_WORLD_SIZE", 1);
  e.ranks_here = std::min(env_int("OMPI_COMM_WORLD_LOCAL_SIZE", e.ranks), e.ranks);
  const double share = static_cast<double>(e.ranks_here) / e.ranks;  // of the particles, on this machine
  e.bytes_here = share * (e.particles * e.bytes_per_particle + e.refined_particles * e.bytes_per_refined_particle) +
                 e.ranks_here * (e.wall_points * kBytesPerWallPoint + kBytesPerRank);
  e.machine_bytes = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  return e;
}

std::string MemoryEstimate::breakdown() const {
  char b[400];
  int n = std::snprintf(b, sizeof b, "%.4g particles x %.0f B", particles, bytes_per_particle);
  if (refined_particles > 0)
    n += std::snprintf(b + n, sizeof b - n, ", refinement zones up to %.4g particles x %.0f B", refined_particles, bytes_per_refined_particle);
  if (wall_points > 0) n += std::snprintf(b + n, sizeof b - n, ", %.4g wall points x %.0f B per rank", wall_points, kBytesPerWallPoint);
  std::snprintf(b + n, sizeof b - n, ", %d of %d rank%s on this machine", ranks_here, ranks, ranks > 1 ? "s" : "");
  return b;
}

std::string MemoryEstimate::summary() const {
  char b[120];
  std::snprintf(b, sizeof b, "memory: about %.3g GiB of this machine's %.3g GiB (", bytes_here / 1073741824.0, machine_bytes / 1073741824.0);
  return b + breakdown() + ")";
}

}  // namespace ondine
