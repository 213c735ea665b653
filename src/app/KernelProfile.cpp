#include "app/KernelProfile.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace ondine {

namespace {

using Clock = std::chrono::steady_clock;

struct Entry {
  long long calls = 0;
  double seconds = 0;
};

// kernels do not nest on the host thread that launches them: one open kernel at a time
std::map<std::string, Entry>& table() {
  static std::map<std::string, Entry> t;
  return t;
}
Entry* open_entry = nullptr;
Clock::time_point opened;

void begin(const char* name, const uint32_t, uint64_t* id) {
  *id = 0;
  open_entry = &table()[name];
  opened = Clock::now();
}

void end(const uint64_t) {
  if (!open_entry) return;
  Kokkos::fence();
  open_entry->seconds += std::chrono::duration<double>(Clock::now() - opened).count();
  ++open_entry->calls;
  open_entry = nullptr;
}

std::string group_of(const std::string& name) {
  const auto a = name.find("::");
  if (a == std::string::npos) return name;
  const auto b = name.find("::", a + 2);
  return b == std::string::npos ? name : name.substr(0, b);
}

}  // namespace

void install_kernel_profile() {
  namespace KT = Kokkos::Tools::Experimental;
  KT::set_begin_parallel_for_callback(begin);
  KT::set_begin_parallel_reduce_callback(begin);
  KT::set_begin_parallel_scan_callback(begin);
  KT::set_end_parallel_for_callback(end);
  KT::set_end_parallel_reduce_callback(end);
  KT::set_end_parallel_scan_callback(end);
}

void reset_kernel_profile() { table().clear(); }

double kernel_seconds(const std::vector<std::string>& prefixes) {
  double s = 0;
  for (const auto& [name, e] : table())
    for (const std::string& p : prefixes)
      if (name.rfind(p, 0) == 0) {
        s += e.seconds;
        break;
      }
  return s;
}

nlohmann::json kernel_profile_report() {
  std::vector<std::pair<std::string, Entry>> rows(table().begin(), table().end());
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.second.seconds > b.second.seconds; });
  double total = 0;
  for (const auto& r : rows) total += r.second.seconds;
  auto share = [&](double s) { return total > 0 ? s / total : 0.0; };
  nlohmann::json kernels = nlohmann::json::array();
  std::map<std::string, double> groups;
  for (const auto& [name, e] : rows) {
    kernels.push_back({{"name", name}, {"calls", e.calls}, {"seconds", e.seconds}, {"share", share(e.seconds)}});
    groups[group_of(name)] += e.seconds;
    if (name == "ondine::APR::GuardWeights" || name == "ondine::APR::GuardInterpolation") groups["guard_interpolation"] += e.seconds;
  }
  nlohmann::json g = nlohmann::json::object();
  for (const auto& [name, s] : groups) g[name] = {{"seconds", s}, {"share", share(s)}};
  return {{"kernel_seconds", total}, {"groups", g}, {"kernels", kernels}};
}

}  // namespace ondine
