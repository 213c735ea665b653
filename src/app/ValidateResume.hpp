#pragma once
// `ondine validate --resume`: a rung's folder says what ran there (validate_rung.json: the case
// file and the overrides, and the commits of the validations that ran it); a rung completed
// with the same is taken as it is, one stopped part-way goes on from its checkpoint, and a
// folder that holds anything else is refused rather than mixed into the record.
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "run/Runner.hpp"

namespace ondine::validate {

// A rung folder --resume cannot use (the message names the file and what differs)
struct ResumeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a rung's folder holds for --resume
struct RungState {
  enum class Kind { Fresh, Restart, Completed } kind = Kind::Fresh;
  std::string checkpoint;  // Restart: OUT/dir/checkpoint.h5
  RunReport report;        // Completed: summary.json's, with the totals since t = 0
};

// The name of the file in a rung folder that says what ran there
inline const char* rung_file() { return "validate_rung.json"; }

// What identifies a rung's run: the case file (relative to source_dir), a hash of its text
// (FNV-1a, 64 bits: an edited case file is another run), and every override in order
nlohmann::json rung_identity(const std::string& source_dir, const std::string& case_file, const std::vector<std::string>& sets);

// The state of the rung folder `dir` against `identity`; throws ResumeError when the folder
// holds a run of other settings, an unreadable validate_rung.json or summary.json, or a run
// without validate_rung.json.
RungState resume_state(const std::string& dir, const nlohmann::json& identity);

// Creates `dir` and writes validate_rung.json: `identity` with `commit` added to the commits of
// those before it in the folder (written atomically).
void write_rung_identity(const std::string& dir, const nlohmann::json& identity, const std::string& commit);

// The commits recorded in dir/validate_rung.json (empty when there is none)
std::vector<std::string> rung_commits(const std::string& dir);

// A run's report read back from its summary.json: status, message, particles, errors, and the
// steps, wall and CPU seconds since t = 0 (total_*). Throws ResumeError naming the file.
RunReport report_from_summary(const std::string& dir);

}  // namespace ondine::validate
