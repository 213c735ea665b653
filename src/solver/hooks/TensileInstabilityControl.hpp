#pragma once
// scheme.tensile_instability_control: no tension on the free surface. The free-surface flags
// (4.86)-(4.87) of the step's first stage, level by level, held through its stages: the pressure
// gradient reads (P_j - P_i) for a surface particle in tension (kernels/terms/PressureGradient.hpp),
// and at the step's end a surface particle's density is put back to rho0 where it fell below.
#include <stdexcept>

#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class TensileInstabilityControl final : public StepHook<D> {
 public:
  const char* name() const override { return "tensile_instability_control"; }
  void allocate(ParticleSet<D>& p) override {
    if (!p.has(field::FreeSurface{}))
      throw std::invalid_argument(
          "scheme.tensile_instability_control: the domain is periodic in every direction, so no particle is on a free surface: remove it");
  }
  void before_flux(StepState<D>& s, bool later_stage) override {
    ParticleSet<D>& p = s.particles();
    if (!later_stage)
      for (const LevelSpan<D>& L : s.levels())
        if (L.active_end > L.first) s.scheme().free_surface(s.context(L));
    // at every stage: a list rebuilt since may have made new halo copies
    s.domain().refresh(p, field::FreeSurface{});
  }
  // the free surface at the atmosphere's pressure: a flagged particle's density is not let below rho0
  void step_end(StepState<D>& s, double) override {
    ParticleSet<D>& p = s.particles();
    const auto rho = p.get(field::Density{});
    const auto fs = p.get(field::FreeSurface{});
    const double rho0 = s.scene().rho0;
    for (const LevelSpan<D>& L : s.levels())
      Kokkos::parallel_for("ondine::FreeSurfaceDensityFloor", Kokkos::RangePolicy<ExecSpace>(L.first, L.active_end), KOKKOS_LAMBDA(int i) {
        if (fs(i) > 0.5 && rho(i) < rho0) rho(i) = rho0;
      });
  }
};

}  // namespace ondine
