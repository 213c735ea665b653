#pragma once
// The figures of the scene's analytic reference at the end of the run (observers/ErrorNorms.hpp:
// mass drift, Taylor-Green, Poiseuille, Couette, cavity, hydrostatic pressure, open channel, wall
// leaks) and, in still water, the buoyancy of submerged bodies.
#include "observers/ErrorNorms.hpp"
#include "observers/Observer.hpp"

namespace ondine {

template <int D>
class ReferenceFigures : public Observer<D> {
 public:
  void record(OutputInstant<D>&) override {}

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (end.diverged) return;
    for (const auto& [k, v] : reference_errors(end.sim)) errors[k] = v;
    if (end.sim.scene().reference.kind == ReferenceKind::Hydrostatic && !end.sim.walls().empty()) {
      const double worst = buoyancy_error(end.sim.scene(), wall_forces(end.sim));
      if (worst >= 0) errors["buoyancy_error"] = worst;
    }
  }
};

}  // namespace ondine
