#include "app/Validate.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <map>
#include <sstream>

#include "io/AtomicFile.hpp"
#include "scene/CaseFile.hpp"
#include "solver/Runner.hpp"

namespace ondine {

namespace {

struct Rung {
  double dx;
  bool full_only;
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
};

const std::vector<ValidationCase>& catalogue() {
  static const std::vector<ValidationCase> c = {
      {"taylor_green_2d", "cases/taylor_green_2d.yaml", 1.0, {{0.04, false}, {0.02, false}, {0.01, true}},
       {{"velocity_l2", 0.05}, {"mass_drift", 1e-12}}, {}},
      {"poiseuille_2d", "cases/poiseuille_2d.yaml", 1.0, {{0.04, false}, {0.02, false}, {0.01, true}},
       {{"velocity_l2", 0.01}}, {}},
      {"hydrostatic_tank_2d", "cases/hydrostatic_tank_2d.yaml", 0.5, {{0.05, false}, {0.025, false}, {0.0125, true}},
       {{"pressure_linf", 0.03}, {"kinetic_over_potential", 1e-3}, {"wall_leaks", 0.5}}, {}},
      {"dam_break_2d", "cases/dam_break_2d.yaml", 0.05715, {{0.002286, false}, {0.001143, true}},
       {{"front_max_relative_error", 0.2}, {"front_speed_relative_error", 0.1}}, {}},
      // Stiff and extreme cases (`--case stability`): each long enough to show growth, checked for
      // NaN, unbounded kinetic energy (max E_k over 1/2 M u_ref^2), density leaving [0.9, 1.1] rho0
      // and particles leaving the domain.
      {"stability_dam_break_impacts", "cases/dam_break_2d.yaml", 0.05715, {{0.002286, false}, {0.001143, true}},
       {{"non_finite", 0.5}, {"max_kinetic_energy_ratio", 2.0}, {"max_density_deviation", 0.1}, {"max_outside_domain", 0.5}},
       {"time.duration=0.6", "time.output_interval=0.01"}},
      {"stability_hydrostatic_10s_undamped", "cases/hydrostatic_tank_2d.yaml", 0.5, {{0.05, false}, {0.025, true}},
       {{"non_finite", 0.5}, {"max_kinetic_energy_ratio", 0.01}, {"max_density_deviation", 0.1}, {"max_outside_domain", 0.5}},
       {"time.duration=10", "time.damping=0", "time.output_interval=0.05"}},
      {"stability_stiff_viscous_channel", "cases/poiseuille_2d.yaml", 1.0, {{0.04, false}, {0.02, true}},
       {{"non_finite", 0.5}, {"max_kinetic_energy_ratio", 2.0}, {"max_density_deviation", 0.1}, {"max_outside_domain", 0.5}},
       {"fluid.viscosity=10", "time.duration=0.5", "time.output_interval=0.05"}},
      {"stability_free_fall_high_mach", "cases/free_fall_2d.yaml", 1.0, {{0.04, false}, {0.02, true}},
       {{"non_finite", 0.5}, {"max_density_deviation", 0.1}, {"momentum_balance_error", 1e-10}},
       {"fluid.mach=0.3", "time.duration=1.0"}},
  };
  return c;
}

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

}  // namespace

int run_validation(const ValidateOptions& opt) {
  namespace fs = std::filesystem;
  // no --case: the accuracy cases; --case stability: the stability suite
  auto stability = [](const std::string& n) { return n.rfind("stability", 0) == 0; };
  const bool want_stability = std::find(opt.cases.begin(), opt.cases.end(), "stability") != opt.cases.end();
  std::vector<const ValidationCase*> chosen;
  for (const ValidationCase& c : catalogue())
    if ((opt.cases.empty() && !stability(c.name)) || (want_stability && stability(c.name)) ||
        std::find(opt.cases.begin(), opt.cases.end(), c.name) != opt.cases.end())
      chosen.push_back(&c);
  for (const std::string& n : opt.cases) {
    bool known = n == "stability";
    for (const ValidationCase& c : catalogue()) known = known || c.name == n;
    if (!known) {
      std::string list;
      for (const ValidationCase& c : catalogue()) list += " " + c.name;
      std::fprintf(stderr, "ondine validate: unknown case '%s'; expected one of:%s\n", n.c_str(), list.c_str());
      return 2;
    }
  }
  if (opt.level != "quick" && opt.level != "full") {
    std::fprintf(stderr, "ondine validate: --level must be quick or full, got '%s'\n", opt.level.c_str());
    return 2;
  }
  fs::create_directories(opt.out_dir);
  nlohmann::json j;
  j["level"] = opt.level;
  j["runs"] = nlohmann::json::array();
  j["orders"] = nlohmann::json::object();
  bool all_passed = true;
  std::ostringstream md;
  md << "# Validation (" << opt.level << ")\n\n| case | resolution | particles | steps | wall s | particle-steps/s | errors | passed |\n|---|---|---|---|---|---|---|---|\n";
  for (const ValidationCase* c : chosen) {
    std::vector<std::pair<double, std::map<std::string, double>>> ladder;
    for (const Rung& r : c->ladder) {
      if (r.full_only && opt.level != "full") continue;
      std::vector<std::string> sets = c->sets;
      std::ostringstream dx;
      dx.precision(17);
      dx << r.dx;
      sets.push_back("discretisation.dx=" + dx.str());
      const Scene scene = load_case(opt.source_dir + "/" + c->file, sets);
      const double resolution = c->length / r.dx;
      RunOptions ro;
      ro.out_dir = opt.out_dir + "/" + c->name + "/res_" + std::to_string(static_cast<long>(std::lround(resolution)));
      ro.progress = false;
      std::fprintf(stderr, "ondine validate: %s at %g particles per length ...\n", c->name.c_str(), resolution);
      const RunReport rep = run_scene(scene, ro);
      bool passed = rep.status == "completed";
      nlohmann::json run;
      run["case"] = c->name;
      run["resolution"] = resolution;
      run["dx"] = r.dx;
      run["particles"] = rep.particles;
      run["steps"] = rep.steps;
      run["wall_seconds"] = rep.wall_seconds;
      run["particle_steps_per_second"] = rep.wall_seconds > 0 ? rep.particles * static_cast<double>(rep.steps) / rep.wall_seconds : 0.0;
      run["errors"] = rep.errors;
      run["status"] = rep.status;
      nlohmann::json th = nlohmann::json::object();
      std::string errs;
      for (const auto& [name, bound] : c->thresholds) {
        th[name] = bound;
        const auto it = rep.errors.find(name);
        const bool ok = it != rep.errors.end() && std::isfinite(it->second) && it->second <= bound;
        passed = passed && ok;
        errs += name + " " + (it != rep.errors.end() ? fmt(it->second) : "missing") + (ok ? "" : " (> " + fmt(bound) + ")") + "; ";
      }
      run["thresholds"] = th;
      run["passed"] = passed;
      all_passed = all_passed && passed;
      j["runs"].push_back(run);
      md << "| " << c->name << " | " << fmt(resolution) << " | " << rep.particles << " | " << rep.steps << " | "
         << fmt(rep.wall_seconds) << " | " << fmt(run["particle_steps_per_second"].get<double>()) << " | " << errs << " | "
         << (passed ? "yes" : "**no**") << " |\n";
      ladder.emplace_back(resolution, rep.errors);
    }
    // observed order between the two finest rungs: log(e_coarse / e_fine) / log(res_fine / res_coarse)
    if (ladder.size() >= 2) {
      const auto& [r1, e1] = ladder[ladder.size() - 2];
      const auto& [r2, e2] = ladder.back();
      for (const auto& [name, v1] : e1) {
        const auto it = e2.find(name);
        if (it == e2.end() || !(v1 > 0) || !(it->second > 0)) continue;
        j["orders"][c->name][name] = std::log(v1 / it->second) / std::log(r2 / r1);
      }
    }
  }
  md << "\nObserved orders (two finest resolutions):\n\n";
  for (const auto& [cname, errs] : j["orders"].items())
    for (const auto& [ename, order] : errs.items()) md << "- " << cname << " / " << ename << ": " << fmt(order.get<double>()) << "\n";
  write_text_atomically(opt.out_dir + "/validation.json", j.dump(2) + "\n");
  // plots: error against wall time per case (main figure), if matplotlib is there
  const std::string plot = opt.source_dir + "/scripts/plot_validation.py";
  if (fs::exists(plot)) {
    const std::string cmd = "/usr/bin/python3 " + plot + " " + opt.out_dir + " > /dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) md << "\n![error against wall time](error_vs_wall_time.png)\n";
  }
  write_text_atomically(opt.out_dir + "/validation.md", md.str());
  std::fprintf(stderr, "ondine validate: %s; wrote %s/validation.json and validation.md\n",
               all_passed ? "all runs passed" : "SOME RUNS FAILED", opt.out_dir.c_str());
  return all_passed ? 0 : 1;
}

}  // namespace ondine
