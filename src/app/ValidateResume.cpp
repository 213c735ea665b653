#include "app/ValidateResume.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/AtomicFile.hpp"

namespace ondine::validate {

namespace fs = std::filesystem;

namespace {

// dir/name parsed; a null json when the file is absent; ResumeError when it does not parse
nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) return nullptr;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) throw ResumeError(path + ": not a JSON object (a file cut short?); remove the folder to run the rung again");
  return j;
}

}  // namespace

nlohmann::json rung_identity(const std::string& source_dir, const std::string& case_file, const std::vector<std::string>& sets) {
  std::ifstream in(source_dir + "/" + case_file, std::ios::binary);
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (char c; in.get(c);) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return {{"case_file", case_file}, {"case_text_fnv1a", hex}, {"sets", sets}};
}

RungState resume_state(const std::string& dir, const nlohmann::json& identity) {
  RungState st;
  if (!fs::exists(dir) || fs::is_empty(dir)) return st;
  const std::string id_path = dir + "/" + rung_file();
  const nlohmann::json id = read_json(id_path);
  if (id.is_null())
    throw ResumeError(dir + ": holds output without " + rung_file() + " (a run not started by `ondine validate --resume`); remove it "
                      "or choose another --out");
  for (const char* key : {"case_file", "case_text_fnv1a", "sets"})
    if (!id.contains(key) || id[key] != identity[key])
      throw ResumeError(id_path + ": the rung in this folder ran with " + key + " " + (id.contains(key) ? id[key].dump() : "(missing)") +
                        ", this validation asks for " + identity[key].dump() + "; remove the folder or choose another --out");
  if (fs::exists(dir + "/summary.json")) {
    const RunReport rep = report_from_summary(dir);
    if (rep.status == "completed") {
      st.kind = RungState::Kind::Completed;
      st.report = rep;
      return st;
    }
    if (rep.status == "diverged")  // a restart would only diverge again: run it from t = 0
      return st;
  }
  if (fs::exists(dir + "/checkpoint.h5")) {
    st.kind = RungState::Kind::Restart;
    st.checkpoint = dir + "/checkpoint.h5";
  }
  return st;
}

void write_rung_identity(const std::string& dir, const nlohmann::json& identity, const std::string& commit) {
  fs::create_directories(dir);
  nlohmann::json j = identity;
  j["commits"] = rung_commits(dir);
  j["commits"].push_back(commit);
  write_text_atomically(dir + "/" + rung_file(), j.dump(2) + "\n");
}

std::vector<std::string> rung_commits(const std::string& dir) {
  const nlohmann::json j = read_json(dir + "/" + rung_file());
  std::vector<std::string> c;
  if (j.is_object() && j.contains("commits") && j["commits"].is_array())
    for (const auto& s : j["commits"])
      if (s.is_string()) c.push_back(s.get<std::string>());
  return c;
}

RunReport report_from_summary(const std::string& dir) {
  const std::string path = dir + "/summary.json";
  const nlohmann::json j = read_json(path);
  RunReport r;
  try {
    if (j.is_null()) throw ResumeError(path + ": cannot be read");
    r.status = j.at("status").get<std::string>();
    r.message = j.value("message", "");
    r.particles = j.at("particles").get<std::size_t>();
    r.simulated_time = j.at("simulated_time").get<double>();
    r.steps = r.total_steps = j.at("total_steps").get<std::int64_t>();
    // a summary written before the totals were recorded: that process's own figures
    r.wall_seconds = r.total_wall_seconds = j.value("total_wall_seconds", j.at("wall_seconds").get<double>());
    r.cpu_seconds = r.total_cpu_seconds = j.value("total_cpu_seconds", j.at("cpu_seconds").get<double>());
    for (const auto& [name, v] : j.at("errors").items())
      if (v.is_number()) r.errors[name] = v.get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw ResumeError(path + ": " + e.what());
  }
  return r;
}

}  // namespace ondine::validate
