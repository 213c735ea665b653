#pragma once
// An observer (LAMMPS' Compute): at each output instant it reads the state and changes none
// of it, writes its rows, and may post figures for the observers after it; at the end of the
// run it adds its figures to the summary's errors. The run's recorder (run/RunRecorder.hpp)
// holds them as a list, made from the scene in observers/Observers.hpp (one line each).
#include <map>
#include <string>
#include <vector>

#include "solver/Simulation.hpp"

namespace ondine {

// One output instant, inside the simulation's OutputFrame.
template <int D>
struct OutputInstant {
  OutputInstant(Simulation<D>& s, double dt) : sim(s), last_dt(dt) {}
  Simulation<D>& sim;  // read only: its measurements may refresh halos and lists, never the state
  double last_dt = 0;  // the last step
  std::map<std::string, double> posted;  // figures of this instant from earlier observers ("P1", "body.fx")
  // the integral quantities, computed once, when first asked for
  const Diagnostics& diagnostics() {
    if (!have_diagnostics_) d_ = ondine::diagnostics(sim);
    have_diagnostics_ = true;
    return d_;
  }

 private:
  Diagnostics d_;
  bool have_diagnostics_ = false;
};

// The rows of the earlier run read back at a restart, by file name ("probes.csv"), for the
// observers after the one that owns the file.
using ResumedRows = std::map<std::string, std::vector<std::vector<double>>>;

// The end of a run: its final state, read by the observers' figures.
template <int D>
struct RunEnd {
  Simulation<D>& sim;     // read only, as in OutputInstant
  double mass = 0;        // the final total mass
  bool diverged = false;  // the run blew up: no reference figures
};

template <int D>
class Observer {
 public:
  virtual ~Observer() = default;
  virtual void record(OutputInstant<D>& now) = 0;
  // a restart at t_start: the series of the earlier run up to it, and the figures over them
  virtual void resume(double /*t_start*/, ResumedRows& /*rows*/) {}
  virtual void add_figures(std::map<std::string, double>& /*errors*/, RunEnd<D>& /*end*/) const {}
};

}  // namespace ondine
