#pragma once
// walls.csv: the force of the fluid on each wall, pressure and viscous parts, and its moment
// (the reaction of the wall terms 4.22 and 4.85); posts each wall's total force as
// "NAME.fx", "NAME.fy", and its pressure part "NAME.pressure_fx", for the observers after it.
#include "observers/SeriesObserver.hpp"

namespace ondine {

template <int D>
class WallForceSeries : public SeriesObserver<D> {
  using SeriesObserver<D>::csv_;
 public:
  WallForceSeries(const std::string& out_dir, bool writer, Simulation<D>& sim) : SeriesObserver<D>(out_dir, "walls.csv", writer) {
    csv_.text() << "time,step";
    for (const WallForce& f : wall_forces(sim)) {
      for (const char* part : {"pressure", "viscous"})
        for (int k = 0; k < D; ++k) csv_.text() << "," << f.name << "." << part << "_f" << "xyz"[k];
      for (int k = D == 2 ? 2 : 0; k < 3; ++k) csv_.text() << "," << f.name << ".moment_" << "xyz"[k];
    }
    csv_.text() << "\n";
  }

  // the column of a wall's pressure_fx in walls.csv (time, step, then per wall D pressure and
  // D viscous components and its moment: 1 in 2D, 3 in 3D); 2 when no wall has that name
  static std::size_t pressure_fx_column(const Scene& scene, const std::string& wall) {
    for (std::size_t k = 0; k < scene.walls.size(); ++k)
      if (scene.walls[k].name == wall) return 2 + k * (2 * D + (D == 2 ? 1 : 3));
    return 2;
  }

  void record(OutputInstant<D>& now) override {
    std::ostringstream& row = this->row(now.sim);
    for (const WallForce& f : wall_forces(now.sim)) {
      now.posted[f.name + ".fx"] = f.pressure[0] + f.viscous[0];
      now.posted[f.name + ".fy"] = f.pressure[1] + f.viscous[1];
      now.posted[f.name + ".pressure_fx"] = f.pressure[0];
      for (int k = 0; k < D; ++k) row << "," << f.pressure[k];
      for (int k = 0; k < D; ++k) row << "," << f.viscous[k];
      for (int k = D == 2 ? 2 : 0; k < 3; ++k) row << "," << f.moment[k];
    }
    this->end_row();
  }
};

}  // namespace ondine
