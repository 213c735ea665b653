#pragma once
// Runs a validated scene to completion: time loop, snapshots (HDF5 + XDMF),
// probes, diagnostics time series, progress line, checkpoints and summary.json.
// Collective on several MPI ranks: rank 0 writes the text files.
#include <cstdint>
#include <map>
#include <string>

#include "scene/Scene.hpp"

namespace ondine {

struct RunOptions {
  std::string out_dir;           // created here; nothing is written before the scene is valid
  bool progress = true;          // progress line on stderr
  double progress_interval = 2;  // wall seconds between progress lines
  std::string restart;           // checkpoint to continue from (empty: a new run)
};

struct RunReport {
  std::string status;   // "completed", "diverged", "interrupted", "max_steps"
  std::string message;  // what went wrong, when diverged
  int signal = 0;       // the signal that interrupted the run
  std::int64_t steps = 0;
  std::size_t particles = 0;  // at t = 0, all ranks
  double wall_seconds = 0, simulated_time = 0;
  double cpu_seconds = 0;  // this process's CPU time (all its threads): what other load on the machine does not inflate
  // since t = 0 over every process that led here (a restart adds its checkpoint's): equal to
  // steps, wall_seconds and cpu_seconds for a run not restarted
  std::int64_t total_steps = 0;
  double total_wall_seconds = 0, total_cpu_seconds = 0;
  std::map<std::string, double> errors;
};

// Throws CheckpointError (io/Checkpoint.hpp) for a restart file that cannot be used.
RunReport run_scene(const Scene& scene, const RunOptions& options);

// Set by SIGINT/SIGTERM: the run writes a checkpoint and stops at the end of the current step.
void request_stop(int signal = 0);

}  // namespace ondine
