#pragma once
// The observers a scene asks for, in the order they record (an observer reads what those before
// it posted): one line each. A new observer is one file in this folder and one line here.
#include <memory>
#include <vector>

#include "observers/DiagnosticsSeries.hpp"
#include "observers/ForceCoefficients.hpp"
#include "observers/LangevinMomentumSeries.hpp"
#include "observers/OpenMassBalance.hpp"
#include "observers/ProbeSeries.hpp"
#include "observers/ReferenceFigures.hpp"
#include "observers/SphericTest2Sensors.hpp"
#include "observers/SurgeFront.hpp"
#include "observers/WallForceSeries.hpp"
#include "observers/WallSensorSeries.hpp"
#include "observers/WedgeImpact.hpp"
#include "observers/WaveGaugeSeries.hpp"

namespace ondine {

// `writer`: this rank writes the text files (rank 0)
template <int D>
std::vector<std::unique_ptr<Observer<D>>> make_observers(const Scene& s, const std::string& out, bool writer, Simulation<D>& sim) {
  std::vector<std::unique_ptr<Observer<D>>> list;
  const ReferenceKind ref = s.reference.kind;
  if (!sim.walls().empty()) list.push_back(std::make_unique<WallForceSeries<D>>(out, writer, sim));
  if (ref == ReferenceKind::MartinMoyce) list.push_back(std::make_unique<SurgeFront<D>>(s, out, writer));
  list.push_back(std::make_unique<DiagnosticsSeries<D>>(s, out, writer));
  if (sim.template find_hook<OpenBoundaryStep<D>>()) list.push_back(std::make_unique<OpenMassBalance<D>>(out, writer, sim));
  if (s.turbulence.model == TurbulenceModel::Langevin) list.push_back(std::make_unique<LangevinMomentumSeries<D>>(out, writer, sim));
  if (!s.probes.empty()) list.push_back(std::make_unique<ProbeSeries<D>>(s, out, writer));
  if (!s.wall_sensors.empty()) list.push_back(std::make_unique<WallSensorSeries<D>>(s, out, writer));
  if (!s.wave_gauges.empty()) list.push_back(std::make_unique<WaveGaugeSeries<D>>(s, out, writer));
  if (ref == ReferenceKind::Cylinder) list.push_back(std::make_unique<ForceCoefficientObserver<D>>(s));
  if (ref == ReferenceKind::SphericTest2) list.push_back(std::make_unique<SphericTest2Sensors<D>>(s));
  if (ref == ReferenceKind::WedgeImpact) list.push_back(std::make_unique<WedgeImpactObserver<D>>(s));
  list.push_back(std::make_unique<ReferenceFigures<D>>());
  return list;
}

}  // namespace ondine
