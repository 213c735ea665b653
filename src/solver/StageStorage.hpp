#pragma once
// The explicit Runge-Kutta integrators' stage storage (kernels/Integrator.hpp): the fields
// that hold y0 and the RK4 sums, allocated at the first step, and the views of a stage.
#include "kernels/Integrator.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D>
void allocate_stage_storage(ParticleSet<D>& p, const Scene& scene) {
  if (p.has(field::StagePosition{})) return;
  p.allocate(field::StagePosition{});
  p.allocate(field::StageVelocity{});
  p.allocate(field::StageDensity{});
  if (scene.integrator == TimeIntegrator::RK4) {
    p.allocate(field::StagePositionSum{});
    p.allocate(field::StageVelocitySum{});
    p.allocate(field::StageDensitySum{});
  }
  if (p.has(field::MassRate{})) {
    p.allocate(field::StageMass{});
    if (scene.integrator == TimeIntegrator::RK4) p.allocate(field::StageMassSum{});
  }
}

// The state, its derivatives and the integrator's stage storage (RK4 sums only with RK4).
template <int D>
RungeKuttaViews<D> stage_views(const ParticleSet<D>& p, const Scene& scene) {
  const bool rk4 = scene.integrator == TimeIntegrator::RK4;
  RungeKuttaViews<D> v{p.get(field::Position{}),
          p.get(field::Velocity{}),
          p.get(field::Density{}),
          p.get(field::Acceleration{}),
          p.get(field::DensityRate{}),
          p.get(field::StagePosition{}),
          rk4 ? p.get(field::StagePositionSum{}) : field_view_t<field::Position, D>(),
          p.get(field::StageVelocity{}),
          rk4 ? p.get(field::StageVelocitySum{}) : field_view_t<field::Velocity, D>(),
          p.get(field::StageDensity{}),
          rk4 ? p.get(field::StageDensitySum{}) : field_view_t<field::Density, D>()};
  if (p.has(field::TransportCorrection{})) {
    v.du0 = p.get(field::TransportCorrection{});
    v.transport = true;
  }
  if (p.has(field::MassRate{})) {
    v.m = p.get(field::Mass{});
    v.m0 = p.get(field::StageMass{});
    if (rk4) v.ma = p.get(field::StageMassSum{});
    v.dm = p.get(field::MassRate{});
    v.masses = true;
  }
  return v;
}

}  // namespace ondine
