#pragma once
// diagnostics.csv (mass, momentum, kinetic energy, speed, density range, escapes, balance,
// potential energy) and the stability figures over the whole run (validation.md):
// max_density_deviation, max_kinetic_energy_ratio (of 1/2 M u_ref^2), max_outside_domain,
// non_finite; with gravity, mechanical_energy_ratio: (E_k + E_p) at the run's end over its
// value at the first sample (the thesis' Fig. 5.14), E_p = -sum m g.x from the coordinates' origin.
#include <algorithm>
#include <cmath>

#include "io/CsvSeries.hpp"
#include "observers/Observer.hpp"

namespace ondine {

template <int D>
class DiagnosticsSeries : public Observer<D> {
 public:
  DiagnosticsSeries(const Scene& scene, const std::string& out_dir, bool writer)
      : rho0_(scene.rho0), u_ref_(scene.reference_velocity),
        gravity_(scene.gravity[0] != 0.0 || scene.gravity[1] != 0.0 || scene.gravity[2] != 0.0), csv_(out_dir + "/diagnostics.csv", writer) {
    csv_.text() << "time,step,dt,mass,momentum_x,momentum_y" << (D == 3 ? ",momentum_z" : "")
                << ",kinetic_energy,max_speed,rho_min,rho_max,outside_domain,balance,potential_energy\n";
  }

  void record(OutputInstant<D>& now) override {
    const Diagnostics& d = now.diagnostics();
    csv_.text() << now.sim.time() << "," << now.sim.steps() << "," << now.last_dt << "," << d.mass;
    for (int k = 0; k < D; ++k) csv_.text() << "," << d.momentum[k];
    csv_.text() << "," << d.kinetic_energy << "," << d.max_speed << "," << d.rho_min << "," << d.rho_max << "," << d.outside_domain
                << "," << now.sim.domain().balance() << "," << d.potential_energy << "\n";
    csv_.flush();
    keep(d.kinetic_energy, d.rho_min, d.rho_max, d.outside_domain);
    mechanical(d.kinetic_energy + d.potential_energy);
  }

  void resume(double t_start, ResumedRows& rows) override {
    if (!csv_.resume(t_start)) return;
    rows["diagnostics.csv"] = csv_.resumed_rows();
    const std::size_t c = 6 + (D == 3);  // kinetic_energy
    for (const auto& row : csv_.resumed_rows())
      if (row.size() >= c + 5) {
        keep(row[c], row[c + 2], row[c + 3], static_cast<std::int64_t>(row[c + 4]));
        if (row.size() >= c + 7) mechanical(row[c] + row[c + 6]);
        else energy_unknown_ = true;  // a file written before the column: no E(0) to divide by
      }
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    const double ke_scale = 0.5 * end.mass * u_ref_ * u_ref_;
    errors["max_density_deviation"] = max_rho_dev_;
    errors["max_kinetic_energy_ratio"] = ke_scale > 0 ? max_ke_ / ke_scale : 0.0;
    errors["max_outside_domain"] = static_cast<double>(max_outside_);
    errors["non_finite"] = end.diverged ? 1.0 : 0.0;
    if (gravity_ && !energy_unknown_ && samples_ > 1 && e0_ != 0.0) errors["mechanical_energy_ratio"] = e_last_ / e0_;
  }

 private:
  void keep(double ke, double rho_min, double rho_max, std::int64_t outside) {
    max_rho_dev_ = std::max({max_rho_dev_, std::abs(rho_max / rho0_ - 1), std::abs(rho_min / rho0_ - 1)});
    max_ke_ = std::max(max_ke_, ke);
    max_outside_ = std::max(max_outside_, outside);
  }

  void mechanical(double e) {
    if (samples_++ == 0) e0_ = e;
    e_last_ = e;
  }

  double rho0_, u_ref_;
  bool gravity_, energy_unknown_ = false;
  double e0_ = 0, e_last_ = 0;
  long samples_ = 0;
  CsvSeries csv_;
  double max_rho_dev_ = 0, max_ke_ = 0;
  std::int64_t max_outside_ = 0;
};

}  // namespace ondine
