#pragma once
// `ondine validate`: runs each validation case over a ladder of resolutions,
// compares with its reference, writes validation.json and validation.md (and
// PNG plots through scripts/plot_validation.py when python3-matplotlib is
// present), and fails when a run misses its thresholds.
#include <string>
#include <vector>

namespace ondine {

struct ValidateOptions {
  std::vector<std::string> cases;  // empty: all
  std::string level = "quick";     // quick | full
  std::string out_dir = "out/validation";
  std::string source_dir;          // where cases/ and scripts/ are
  // the fluid flux and the particle transport of every run, "case" for what the case files say:
  // flux delta_sph (its form the thesis'), delta_sph_hydrostatic or riemann (Riemann-SPH with MUSCL),
  // riemann_vila, transport lagrangian or shifting
  // (scheme_sets() in Validate.cpp); an entry's own overrides still win
  std::string flux = "case", transport = "case";
  bool list = false;  // --list: print the catalogue (name, group, case file) and run nothing
  bool dry_run = false;  // --dry-run: resolve every chosen run's scene and flux scheme, run nothing
  // --resume: take the rungs completed in out_dir as they are and go on with those stopped from their
  // checkpoints (app/ValidateResume.hpp); every rung then writes a checkpoint every 10 wall minutes
  bool resume = false;
  std::vector<std::string> variants;  // --variant: only these rungs of an APR ladder (empty: all)
};

// Returns the process exit code: 0 when every run passed its thresholds.
int run_validation(const ValidateOptions& options);

}  // namespace ondine
