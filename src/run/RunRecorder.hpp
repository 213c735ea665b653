#pragma once
// What a run writes at each output instant: the snapshot (HDF5 + XDMF), with walls the load on
// them point by point beside it (io/WallFieldWriter.hpp), and the rows of its
// observers (observers/Observers.hpp: diagnostics.csv, probes.csv, walls.csv, front.csv,
// waves.csv, open.csv), which also keep the figures over the whole run. A restarted run takes
// back the rows of the earlier run up to the restart time. Collective; rank 0 writes the text files.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/SnapshotWriter.hpp"
#include "io/WallFieldWriter.hpp"
#include "observers/Observers.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
class RunRecorder {
 public:
  RunRecorder(const Scene& scene, const std::string& out_dir, const Communicator& comm, Simulation<D>& sim)
      : snapshots_(out_dir, scene.name, comm),
        wall_field_(out_dir, scene.name, comm),
        observers_(make_observers<D>(scene, out_dir, comm.rank() == 0, sim)) {}

  // a new run: no snapshot of an earlier run with this name is left in the folder
  void start() {
    snapshots_.remove_from(0);
    wall_field_.remove_from(0);
  }

  // a restart at t_start: the series of the earlier run up to it, and the figures over them
  void resume(double t_start, std::size_t snapshots) {
    snapshots_.resume(snapshots);
    wall_field_.resume(snapshots);
    ResumedRows rows;
    for (const auto& o : observers_) o->resume(t_start, rows);
  }

  // One output instant: the snapshot and a row of every series. Returns the diagnostics
  // (d.finite false: the state is no longer finite).
  // snapshot false: the series only (time.snapshot_every > 1).
  Diagnostics record(Simulation<D>& sim, double last_dt, bool snapshot = true) {
    // until the end of this call; the free-surface flags only for a snapshot (no series reads them)
    const OutputFrame<D> frame(sim, snapshot);
    if (snapshot) snapshots_.write(sim.particles(), sim.time(), sim.steps(), static_cast<std::int64_t>(sim.size()));
    if (snapshot && !sim.walls().empty()) wall_field_.write(wall_load_field(sim), sim.time(), sim.steps());
    OutputInstant<D> now{sim, last_dt};
    for (const auto& o : observers_) o->record(now);
    return now.diagnostics();
  }

  // after a blow-up: the last good state (the start of the failed step) as a snapshot
  void record_last_state(const Simulation<D>& sim) {
    snapshots_.write(sim.particles(), sim.time(), sim.steps(), static_cast<std::int64_t>(sim.size()));
  }
  // whether the last snapshot is older than the simulation's time
  bool behind(const Simulation<D>& sim) const {
    return snapshots_.entries().empty() || sim.time() > snapshots_.entries().back().time;
  }
  std::size_t snapshot_count() const { return snapshots_.entries().size(); }

  // every observer's figures over the whole run and at its end into `errors`
  void add_figures(std::map<std::string, double>& errors, Simulation<D>& sim, bool diverged) const {
    RunEnd<D> end{sim, diagnostics(sim).mass, diverged};
    for (const auto& o : observers_) o->add_figures(errors, end);
  }

 private:
  SnapshotWriter snapshots_;
  WallFieldWriter wall_field_;
  std::vector<std::unique_ptr<Observer<D>>> observers_;
};

}  // namespace ondine
