#pragma once
// open.csv (open boundaries): the fluid region's mass and, per boundary, the masses that crossed
// its plane into and out of the fluid since t = 0 and the net flux into the fluid over the
// interval since the previous row (kg/s; per metre of span in 2D); at the end the balances
// open_mass_balance (the particle set's change against created - removed) and
// open_fluid_mass_balance (the fluid region's against in - out), relative to the initial mass.
#include <cmath>

#include "io/CsvSeries.hpp"
#include "observers/Observer.hpp"
#include "solver/hooks/OpenBoundaryStep.hpp"

namespace ondine {

template <int D>
class OpenMassBalance : public Observer<D> {
 public:
  OpenMassBalance(const std::string& out_dir, bool writer, const Simulation<D>& sim)
      : open_(sim.template find_hook<OpenBoundaryStep<D>>()->boundaries()), csv_(out_dir + "/open.csv", writer) {
    csv_.text() << "time,step,fluid_mass";
    for (const OpenFlux& f : open_.fluxes())
      csv_.text() << "," << f.name << ".mass_in," << f.name << ".mass_out," << f.name << ".mass_flux";
    csv_.text() << "\n";
    keep(sim.time());
  }

  void record(OutputInstant<D>& now) override {
    csv_.text() << now.sim.time() << "," << now.sim.steps() << "," << now.diagnostics().fluid_mass;
    const auto& fl = open_.fluxes();
    const double span = now.sim.time() - t_;
    for (std::size_t b = 0; b < fl.size(); ++b) {
      const double net = (fl[b].mass_in - fl[b].mass_out) - (in_[b] - out_[b]);
      csv_.text() << "," << fl[b].mass_in << "," << fl[b].mass_out << "," << (span > 0 ? net / span : 0.0);
    }
    csv_.text() << "\n";
    csv_.flush();
    keep(now.sim.time());
  }

  void resume(double t_start, ResumedRows&) override { csv_.resume(t_start); }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    const Diagnostics d = diagnostics(end.sim);
    const OpenBoundaries<D>& ob = open_;
    const OpenFlux t = ob.total();
    errors["open_mass_balance"] = std::abs(d.mass - ob.initial_mass() - (t.created - t.removed)) / ob.initial_mass();
    errors["open_fluid_mass_balance"] = std::abs(d.fluid_mass - ob.initial_fluid_mass() - (t.mass_in - t.mass_out)) / ob.initial_mass();
  }

 private:
  // the counters at the last row (for the flux over an interval)
  void keep(double t) {
    t_ = t;
    in_.clear();
    out_.clear();
    for (const OpenFlux& f : open_.fluxes()) {
      in_.push_back(f.mass_in);
      out_.push_back(f.mass_out);
    }
  }

  const OpenBoundaries<D>& open_;  // the run's (its step hook's)
  CsvSeries csv_;
  double t_ = 0;
  std::vector<double> in_, out_;
};

}  // namespace ondine
