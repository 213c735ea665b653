#pragma once
// Runs a validated scene to completion: time loop, snapshots (HDF5 + XDMF),
// probes, diagnostics time series, progress line and summary.json.
#include <map>
#include <string>

#include "scene/Scene.hpp"

namespace ondine {

struct RunOptions {
  std::string out_dir;           // created here; nothing is written before the scene is valid
  bool progress = true;          // progress line on stderr
  double progress_interval = 2;  // wall seconds between progress lines
  int ranks = 1;
};

struct RunReport {
  std::string status;  // "completed", "diverged", "interrupted", "max_steps"
  std::string message;  // what went wrong, when diverged
  std::int64_t steps = 0;
  std::size_t particles = 0;
  double wall_seconds = 0, simulated_time = 0;
  std::map<std::string, double> errors;
};

RunReport run_scene(const Scene& scene, const RunOptions& options);

// Set by SIGINT/SIGTERM: the run stops cleanly at the end of the current step.
void request_stop();

}  // namespace ondine
