#pragma once
// Internal to `ondine validate` (src/app/Validate*.cpp): the validation cases, the
// report they fill, and the figures read back from the run folders.
#include <nlohmann/json.hpp>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/Validate.hpp"
#include "scene/Scene.hpp"

namespace ondine::validate {

struct Rung {
  double dx;
  bool full_only;
  bool accuracy = true;  // false: only the stability figures (non_finite, max_*) are bounded on this rung
  // APR comparisons: the run's name (coarse, apr, fine: its folder) and, for the APR
  // run, its own case file (the uniform runs use the case's)
  std::string variant = "";
  std::string file = "";
  std::vector<std::string> sets = {};  // this rung's own overrides, after the case's
};

// One validation case: its file, the length that defines "resolution"
// (particles per reference length = length / dx), the ladder, and the bounds
// its error figures must stay under (the figures the tests and issues use).
struct ValidationCase {
  std::string name, file;
  double length;
  std::vector<Rung> ladder;
  std::map<std::string, double> thresholds;
  std::vector<std::string> sets;  // overrides for every rung
  // when set: each rung is run a second time with these overrides appended (same dx), and
  // front_contrast_difference compares the two surge fronts (dam break)
  std::vector<std::string> contrast = {};
  std::vector<std::string> shown = {};  // errors shown in the table without a bound
  std::vector<std::string> quick_sets = {};  // overrides added at the quick level only
};

// validation.json (j) and validation.md (md) as the runs fill them
struct Report {
  nlohmann::json j;
  std::ostringstream md;
  bool all_passed = true;
  std::string commit, date;  // the binary's source commit (cmake/SourceCommit.cmake); when the runs started (UTC)
  int threads = 0;           // the backend's threads
  std::string device = "host";  // the GPU's name where the runs took place on one
};

// The current time, UTC, as 2026-11-25T10:00:00Z.
std::string utc_now();

// A figure in the report: 4 significant digits.
std::string fmt(double v);

// profile.csv of a run: the solution next to its reference, for the plots.
void write_profile(const Scene& s, const std::string& dir);

// Surge fronts of two runs (front.csv: T,Z,...): max over 0.3 <= T <= 3 of |Z_a - Z_b| / Z_b.
double front_difference(const std::string& a, const std::string& b);

// APR comparisons: the APR (and coarse) runs of case `c` against its fine run.
void compare_with_fine(const ValidateOptions& opt, const ValidationCase& c, Report& report);

// The observed orders, validation.json, the plots and validation.md; the exit code.
int write_report(const ValidateOptions& opt, Report& report);

}  // namespace ondine::validate
