#pragma once
// langevin.csv (turbulence.model: langevin): the mean force of the model's velocity increments
// over the interval since the previous row, sum_i m_i (u_1 - u)_i summed over the steps and
// divided by the interval (N; N per metre of span in 2D), and that sum since t = 0 (kg m/s):
// the increments' noise, the kernel-filtered means' non-conservation and a drift correlated with
// u' (a gradient read along the particles' paths) move the fluid's momentum. With the body force
// and the walls' force (walls.csv) it closes the momentum budget of d(momentum)/dt
// (diagnostics.csv). A restart takes the sum from the checkpoint and the last kept row's.
#include <vector>

#include "observers/SeriesObserver.hpp"
#include "solver/hooks/EddyViscosity.hpp"

namespace ondine {

template <int D>
class LangevinMomentumSeries : public SeriesObserver<D> {
  using SeriesObserver<D>::csv_;
 public:
  LangevinMomentumSeries(const std::string& out_dir, bool writer, const Simulation<D>& sim)
      : SeriesObserver<D>(out_dir, "langevin.csv", writer), hook_(*sim.template find_hook<EddyViscosity<D>>()),
        last_(hook_.langevin_impulse(sim.comm())), t_(sim.time()) {
    csv_.text() << "time,step";
    for (int k = 0; k < D; ++k) csv_.text() << ",force_" << "xyz"[k];
    for (int k = 0; k < D; ++k) csv_.text() << ",impulse_" << "xyz"[k];
    csv_.text() << "\n";
  }

  void record(OutputInstant<D>& now) override {
    const std::vector<double> impulse = hook_.langevin_impulse(now.sim.comm());
    const double span = now.sim.time() - t_;
    std::ostringstream& row = this->row(now.sim);
    for (int k = 0; k < D; ++k) row << "," << (span > 0 ? (impulse[k] - last_[k]) / span : 0.0);
    for (int k = 0; k < D; ++k) row << "," << impulse[k];
    this->end_row();
    last_ = impulse;
    t_ = now.sim.time();
  }

  // the last kept row's time and sum: the next row's interval starts there
  void resume(double t_start, ResumedRows& rows) override {
    SeriesObserver<D>::resume(t_start, rows);
    const auto& kept = csv_.resumed_rows();
    if (kept.empty() || kept.back().size() < 2 + 2 * D) return;
    t_ = kept.back()[0];
    for (int k = 0; k < D; ++k) last_[k] = kept.back()[2 + D + k];
  }

 private:
  const EddyViscosity<D>& hook_;
  std::vector<double> last_;
  double t_;
};

}  // namespace ondine
