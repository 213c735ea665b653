#pragma once
// langevin.csv (turbulence.model: langevin): the mean force of the model's velocity increments
// over the interval since the previous row, sum_i m_i (u_1 - u)_i summed over the steps and
// divided by the interval (N; N per metre of span in 2D), and that sum since t = 0 (kg m/s):
// the increments' noise, the kernel-filtered means' non-conservation and a drift correlated with
// u' (a gradient read along the particles' paths) move the fluid's momentum. With the body force
// and the walls' force (walls.csv) it closes the momentum budget of d(momentum)/dt
// (diagnostics.csv). A restart takes the sum from the checkpoint and the last kept row's.
// Figures, over the run's second half, from the first output instant at or after t_end / 2 to
// t_end (the samples at the output instants;
// V6's budget, validation.md), each over the drive F = (body force + gravity)_x M:
//   langevin_force_ratio: the increments' mean force, (I(t_end) - I(t_a)) / (t_end - t_a);
//   wall_force_ratio: the walls' mean force on the fluid, minus the trapezoid mean of walls.csv's
//     x components summed over the walls;
//   momentum_budget_residual: |F + walls + Langevin - (P_x(t_end) - P_x(t_a)) / (t_end - t_a)| / F,
//     P_x the fluid's momentum: what the three forces leave unexplained.
#include <cmath>
#include <vector>

#include "observers/SeriesObserver.hpp"
#include "observers/WallForceSeries.hpp"
#include "solver/hooks/EddyViscosity.hpp"

namespace ondine {

template <int D>
class LangevinMomentumSeries : public SeriesObserver<D> {
  using SeriesObserver<D>::csv_;
 public:
  LangevinMomentumSeries(const std::string& out_dir, bool writer, const Simulation<D>& sim)
      : SeriesObserver<D>(out_dir, "langevin.csv", writer), hook_(*sim.template find_hook<EddyViscosity<D>>()),
        last_(hook_.langevin_impulse(sim.comm())), t_(sim.time()),
        drive_x_(sim.scene().body_force[0] + sim.scene().gravity[0]) {
    if (!sim.walls().empty())  // walls.csv's pressure_fx column of each wall (viscous_fx is D further)
      for (const auto& w : sim.scene().walls) wall_columns_.push_back(WallForceSeries<D>::pressure_fx_column(sim.scene(), w.name));
    csv_.text() << "time,step";
    for (int k = 0; k < D; ++k) csv_.text() << ",force_" << "xyz"[k];
    for (int k = 0; k < D; ++k) csv_.text() << ",impulse_" << "xyz"[k];
    csv_.text() << "\n";
  }

  void record(OutputInstant<D>& now) override {
    const std::vector<double> impulse = hook_.langevin_impulse(now.sim.comm());
    const Scene& scene = now.sim.scene();
    double walls = 0;
    for (const auto& w : scene.walls) walls += now.posted[w.name + ".fx"];
    const Diagnostics& d = now.diagnostics();
    samples_.push_back({now.sim.time(), impulse[0], walls, d.momentum[0], drive_x_ * d.mass});
    const double span = now.sim.time() - t_;
    std::ostringstream& row = this->row(now.sim);
    for (int k = 0; k < D; ++k) row << "," << (span > 0 ? (impulse[k] - last_[k]) / span : 0.0);
    for (int k = 0; k < D; ++k) row << "," << impulse[k];
    this->end_row();
    last_ = impulse;
    t_ = now.sim.time();
  }

  // the last kept row's time and sum: the next row's interval starts there; the budget's samples
  // from the kept rows of langevin.csv, walls.csv and diagnostics.csv (matched by time)
  void resume(double t_start, ResumedRows& rows) override {
    SeriesObserver<D>::resume(t_start, rows);
    const auto& kept = csv_.resumed_rows();
    const auto& diag_rows = rows["diagnostics.csv"];
    if (kept.empty() || kept.back().size() < 2 + 2 * D) {
      budget_unknown_ = !diag_rows.empty();  // an earlier run without langevin.csv's rows: no budget
      return;
    }
    t_ = kept.back()[0];
    for (int k = 0; k < D; ++k) last_[k] = kept.back()[2 + D + k];
    const auto& wall_rows = rows["walls.csv"];
    const bool has_walls = !wall_columns_.empty();
    if ((has_walls && wall_rows.size() != kept.size()) || diag_rows.size() != kept.size()) {
      budget_unknown_ = true;  // an earlier run's rows that do not line up: no budget
      return;
    }
    for (std::size_t r = 0; r < kept.size(); ++r) {
      double walls = 0;
      bool short_row = false;
      for (const std::size_t c : wall_columns_)
        if (c + D < wall_rows[r].size()) walls += wall_rows[r][c] + wall_rows[r][c + D];
        else short_row = true;
      // diagnostics.csv: time, step, dt, mass, momentum_x
      if (short_row || diag_rows[r].size() < 5 || (has_walls && wall_rows[r][0] != kept[r][0]) || diag_rows[r][0] != kept[r][0]) {
        budget_unknown_ = true;
        samples_.clear();
        return;
      }
      samples_.push_back({kept[r][0], kept[r][2 + D], walls, diag_rows[r][4], drive_x_ * diag_rows[r][3]});
    }
  }

  void add_figures(std::map<std::string, double>& errors, RunEnd<D>& end) const override {
    if (budget_unknown_ || end.diverged || samples_.size() < 3) return;
    const double t_end = samples_.back().t, t_a = 0.5 * t_end;
    std::size_t a = 0;
    // the first sample at or after t_end / 2 (a resumed time is read back to 12 digits)
    while (a + 2 < samples_.size() && samples_[a].t < t_a * (1.0 - 1e-9)) ++a;
    const Sample &s0 = samples_[a], &s1 = samples_.back();
    const double span = s1.t - s0.t;
    if (!(span > 0)) return;
    double walls = 0, drive = 0;  // trapezoid means over [s0.t, s1.t]
    for (std::size_t k = a; k + 1 < samples_.size(); ++k) {
      const double h = samples_[k + 1].t - samples_[k].t;
      walls += 0.5 * h * (samples_[k].walls + samples_[k + 1].walls);
      drive += 0.5 * h * (samples_[k].drive + samples_[k + 1].drive);
    }
    walls /= span, drive /= span;
    if (!(std::abs(drive) > 0)) return;
    const double langevin = (s1.impulse - s0.impulse) / span, rate = (s1.momentum - s0.momentum) / span;
    errors["langevin_force_ratio"] = langevin / drive;
    errors["wall_force_ratio"] = -walls / drive;
    errors["momentum_budget_residual"] = std::abs(drive - walls + langevin - rate) / std::abs(drive);
  }

 private:
  struct Sample {
    double t, impulse, walls, momentum, drive;  // x components: kg m/s, N, kg m/s, N
  };
  const EddyViscosity<D>& hook_;
  std::vector<double> last_;
  double t_;
  double drive_x_;
  std::vector<std::size_t> wall_columns_;  // empty: no walls.csv
  std::vector<Sample> samples_;  // one per output instant: a few hundred
  bool budget_unknown_ = false;
};

}  // namespace ondine
