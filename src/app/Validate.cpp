#include "app/Validate.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <map>
#include <sstream>

#include "run/BuildInfo.hpp"
#include "app/ValidateReport.hpp"
#include "app/ValidateResume.hpp"
#include "app/ValidationCatalogue.hpp"
#include "SourceCommit.hpp"  // generated: cmake/SourceCommit.cmake
#include "scene/CaseFile.hpp"
#include "io/Checkpoint.hpp"
#include "scene/FluxSchemes.hpp"
#include "run/Runner.hpp"

namespace ondine {

namespace {

using validate::Report;
using validate::Rung;
using validate::ValidationCase;
using validate::catalogue;
using validate::fmt;
using validate::group_of;
using validate::ResumeError;
using validate::RungState;

// A rung stopped by SIGINT or SIGTERM: its checkpoint is written, the validation stops
struct Interrupted {
  int signal;
};

// --resume: a rung writes a checkpoint at least this often, so that a stopped session loses at most this much
constexpr double resume_checkpoint_seconds = 600;

// --variant: the rungs of an APR ladder run (all when none is named; a ladder without variants always runs)
bool variant_chosen(const ValidateOptions& opt, const Rung& r) {
  return opt.variants.empty() || r.variant.empty() ||
         std::find(opt.variants.begin(), opt.variants.end(), r.variant) != opt.variants.end();
}

// --case: no --case: the accuracy cases; stability, apr, open, fine, turbulence, impact: that group; all: all of
// them but the fine group (hours on a CPU, minutes on a GPU); or case names
std::vector<const ValidationCase*> chosen_cases(const ValidateOptions& opt) {
  auto asked = [&](const std::string& n) { return std::find(opt.cases.begin(), opt.cases.end(), n) != opt.cases.end(); };
  std::vector<const ValidationCase*> chosen;
  for (const ValidationCase& c : catalogue()) {
    const std::string g = group_of(c.name);
    if ((opt.cases.empty() && g == "accuracy") || (asked("all") && g != "fine") || asked(g) || asked(c.name)) chosen.push_back(&c);
  }
  return chosen;
}

// false (said on stderr) for an unknown --case or --level
// --flux riemann or riemann_vila: a Riemann-SPH flux
bool riemann_flux(const ValidateOptions& opt) { return opt.flux == "riemann" || opt.flux == "riemann_vila"; }
// --flux delta_sph or delta_sph_hydrostatic: the centred flux, the delta-SPH term's form named
bool delta_sph_flux(const ValidateOptions& opt) { return opt.flux == "delta_sph" || opt.flux == "delta_sph_hydrostatic"; }

bool options_known(const ValidateOptions& opt) {
  for (const std::string& n : opt.cases) {
    bool known = n == "all";
    for (const ValidationCase& c : catalogue()) known = known || c.name == n || group_of(c.name) == n;
    if (!known) {
      std::string list;
      for (const ValidationCase& c : catalogue()) list += " " + c.name;
      std::fprintf(stderr, "ondine validate: unknown case '%s'; expected all, accuracy, stability, apr, open, fine, turbulence, impact or one of:%s\n", n.c_str(), list.c_str());
      return false;
    }
  }
  if (opt.flux != "case" && !delta_sph_flux(opt) && !riemann_flux(opt)) {
    std::fprintf(stderr, "ondine validate: --flux must be case, delta_sph, delta_sph_hydrostatic, riemann or riemann_vila, got '%s'\n",
                 opt.flux.c_str());
    return false;
  }
  if (opt.transport != "case" && opt.transport != "lagrangian" && opt.transport != "shifting" && opt.transport != "ale" &&
      opt.transport != "ale_free") {
    std::fprintf(stderr, "ondine validate: --transport must be case, lagrangian, shifting, ale or ale_free, got '%s'\n", opt.transport.c_str());
    return false;
  }
  if ((opt.transport == "ale" || opt.transport == "ale_free") && !riemann_flux(opt)) {
    std::fprintf(stderr, "ondine validate: --transport ale needs --flux riemann or riemann_vila (the ALE transport is built on Riemann-SPH)\n");
    return false;
  }
  for (const std::string& v : opt.variants) {
    bool known = false;
    for (const ValidationCase& c : catalogue())
      for (const Rung& r : c.ladder) known = known || r.variant == v;
    if (!known) {
      std::fprintf(stderr, "ondine validate: unknown --variant '%s'; expected a rung of an APR ladder (coarse, apr, apr_lts, fine, ...)\n",
                   v.c_str());
      return false;
    }
  }
  if (opt.level != "quick" && opt.level != "full") {
    std::fprintf(stderr, "ondine validate: --level must be quick or full, got '%s'\n", opt.level.c_str());
    return false;
  }
  return true;
}

// --flux riemann: Riemann-SPH with MUSCL in place of delta-SPH, every stage's gradients, and the
// thesis' acoustic CFL 0.375 (the dam-break case's 0.75 is beyond Riemann-SPH's stable step);
// riemann_vila: the same in Vila's form with mass fluxes (2.84-2.89); --flux delta_sph: the
// centred flux (the case's delta-SPH and viscosities), delta_sph_hydrostatic the same (its form:
// load_rung_scene); --transport: scheme.transport (ale_free: ale with scheme.ale.cut_supports: free)
std::vector<std::string> scheme_sets(const ValidateOptions& opt) {
  std::vector<std::string> s;
  if (riemann_flux(opt))
    s = {"scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage", "scheme.cfl.acoustic=0.375"};
  if (opt.flux == "riemann_vila") s.push_back("scheme.riemann.variant=vila");
  if (delta_sph_flux(opt)) s = {"scheme.flux=delta_sph"};
  if (opt.transport != "case") {
    s.push_back(opt.transport == "shifting" ? "scheme.shifting=true" : "scheme.shifting=false");
    if (opt.transport == "ale" || opt.transport == "ale_free") s.push_back("scheme.transport=ale");
    if (opt.transport == "ale_free") s.push_back("scheme.ale.cut_supports=free");
  }
  return s;
}

// The overrides of one rung: the scheme's (--flux, --transport), the case's, the quick level's,
// the rung's own, and the rung's dx.
std::vector<std::string> rung_sets(const ValidateOptions& opt, const ValidationCase& c, const Rung& r) {
  std::vector<std::string> sets = scheme_sets(opt);
  // Riemann-SPH takes its density rate from the Riemann velocity (2.92): an entry's renormalised
  // continuity (the c0 = 1480 dam break's) is the centred flux's fix and is left out
  for (const std::string& e : c.sets)
    if (!(riemann_flux(opt) && e.rfind("scheme.renormalised_continuity=", 0) == 0)) sets.push_back(e);
  if (opt.level != "full") sets.insert(sets.end(), c.quick_sets.begin(), c.quick_sets.end());
  sets.insert(sets.end(), r.sets.begin(), r.sets.end());
  std::ostringstream dx;
  dx.precision(17);
  dx << r.dx;
  sets.push_back("discretisation.dx=" + dx.str());
  return sets;
}

// The scale and scheme of the last run of a rung (validation.json: reference_velocity, rho0,
// and the scheme the case file and the overrides resolved to)
struct RunScale {
  double u_ref = 0, rho0 = 0;
  std::string flux, transport;
};

// The scheme a scene runs: flux delta_sph, riemann (Leduc's form) or riemann_vila; transport
// lagrangian, shifting, ale or ale_free (the names of --flux and --transport)
void resolve_scheme(const Scene& s, RunScale& scale) {
  scale.flux = s.flux == FluxScheme::DeltaSph ? (s.delta_sph_hydrostatic ? "delta_sph_hydrostatic" : "delta_sph")
                : s.riemann_variant == RiemannVariant::Vila ? "riemann_vila" : "riemann";
  scale.transport = s.ale ? (s.ale_tangential_cut ? "ale" : "ale_free") : s.shifting ? "shifting" : "lagrangian";
}

// A rung's scene: the case file with the overrides; where it has a delta-SPH term, --flux delta_sph
// gives it the thesis' form (2.60) and delta_sph_hydrostatic the hydrostatic one
// (scheme.delta_sph_form; a case without the term keeps none)
Scene load_rung_scene(const ValidateOptions& opt, const std::string& file, const std::vector<std::string>& sets) {
  Scene s = load_case(opt.source_dir + "/" + file, sets);
  if (s.delta_sph > 0 && delta_sph_flux(opt))
    s.delta_sph_hydrostatic = opt.flux == "delta_sph_hydrostatic";
  return s;
}

// One run of a rung into OUT/dir, with its profile.csv. With --resume: a run completed in
// OUT/dir with the same case file and overrides is taken as it is, one stopped part-way goes on
// from its checkpoint (ValidateResume.hpp); the report holds the totals since t = 0.
// Throws Interrupted when a signal stopped it, ResumeError for a folder --resume cannot use.
RunReport run_one(const ValidateOptions& opt, const ValidationCase& c, const Rung& r, double resolution,
                  const std::vector<std::string>& overrides, const std::string& dir, RunScale& scale) {
  const std::string file = r.file.empty() ? c.file : r.file;
  Scene scene = load_rung_scene(opt, file, overrides);
  scale.u_ref = scene.reference_velocity;
  scale.rho0 = scene.rho0;
  resolve_scheme(scene, scale);
  RunOptions ro;
  ro.out_dir = opt.out_dir + "/" + dir;
  ro.progress = false;
  if (opt.resume) {
    const nlohmann::json id = validate::rung_identity(opt.source_dir, file, overrides);
    const RungState st = validate::resume_state(ro.out_dir, id);
    if (st.kind == RungState::Kind::Completed) {
      std::fprintf(stderr, "ondine validate: %s completed before (%s/summary.json), taken as it is\n", dir.c_str(), ro.out_dir.c_str());
      return st.report;
    }
    ro.restart = st.checkpoint;
    validate::write_rung_identity(ro.out_dir, id, ONDINE_SOURCE_COMMIT);
    if (!(scene.checkpoint_every_wall_seconds > 0) || scene.checkpoint_every_wall_seconds > resume_checkpoint_seconds)
      scene.checkpoint_every_wall_seconds = resume_checkpoint_seconds;
  }
  std::fprintf(stderr, "ondine validate: %s at %g particles per length%s ...\n", dir.c_str(), resolution,
               ro.restart.empty() ? "" : (", from " + ro.restart).c_str());
  RunReport rep;
  try {
    rep = run_scene(scene, ro);
  } catch (const CheckpointError& e) {
    throw ResumeError(std::string(e.what()) + "; remove " + ro.out_dir + " to run the rung again");
  }
  if (rep.status == "interrupted") throw Interrupted{rep.signal};
  // the record's figures are the run's since t = 0, over the processes that made it
  rep.steps = rep.total_steps;
  rep.wall_seconds = rep.total_wall_seconds;
  rep.cpu_seconds = rep.total_cpu_seconds;
  try {
    validate::write_profile(scene, ro.out_dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ondine validate: no profile for %s: %s\n", dir.c_str(), e.what());
  }
  return rep;
}

// The contrast run of a rung (same dx, the case's contrast overrides appended) and the
// front difference it gives the rung's run; returns its note for the report.
std::string run_contrast(const ValidateOptions& opt, const ValidationCase& c, const Rung& r, double resolution,
                         const std::vector<std::string>& sets, const std::string& rel, RunReport& rep,
                         nlohmann::json& run, RunScale& scale) {
  std::vector<std::string> cs = sets;
  cs.insert(cs.end(), c.contrast.begin(), c.contrast.end());
  const RunReport crep = run_one(opt, c, r, resolution, cs, rel + "_contrast", scale);
  run["contrast_dir"] = rel + "_contrast";
  run["contrast_sets"] = c.contrast;
  run["contrast_wall_seconds"] = crep.wall_seconds;
  run["contrast_steps"] = crep.steps;
  run["contrast_errors"] = crep.errors;
  run["contrast_status"] = crep.status;
  const std::string note = "contrast run (" + std::to_string(crep.steps) + " steps, " + fmt(crep.wall_seconds) + " s" +
                           (crep.errors.count("front_speed") ? ", front_speed " + fmt(crep.errors.at("front_speed")) : "") + "); ";
  if (rep.status == "completed" && crep.status == "completed")
    rep.errors["front_contrast_difference"] = validate::front_difference(opt.out_dir + "/" + rel, opt.out_dir + "/" + rel + "_contrast");
  return note;
}

// The case's bounds on a run's figures (on a rung without accuracy: the stability ones only):
// records them in `th`, appends each figure to `errs`; false when one is missed.
bool check_thresholds(const ValidationCase& c, const Rung& r, const RunReport& rep, nlohmann::json& th, std::string& errs) {
  bool passed = true;
  for (const auto& [name, bound] : c.thresholds) {
    if (!r.accuracy && name != "non_finite" && name.rfind("max_", 0) != 0) continue;
    th[name] = bound;
    const auto it = rep.errors.find(name);
    const bool ok = it != rep.errors.end() && std::isfinite(it->second) && it->second <= bound;
    passed = passed && ok;
    errs += name + " " + (it != rep.errors.end() ? fmt(it->second) : "missing") + (ok ? "" : " (> " + fmt(bound) + ")") + "; ";
  }
  for (const std::string& name : c.shown)
    if (rep.errors.count(name)) errs += name + " " + fmt(rep.errors.at(name)) + " (not bounded); ";
  return passed;
}

// One rung of a case (its run, and its contrast run): its entry in validation.json and its
// row in validation.md; returns its errors for the observed order.
std::map<std::string, double> run_rung(const ValidateOptions& opt, const ValidationCase& c, const Rung& r, Report& report) {
  const std::vector<std::string> sets = rung_sets(opt, c, r);
  const double resolution = c.length / r.dx;
  const std::string rel = r.variant.empty() ? c.name + "/res_" + std::to_string(static_cast<long>(std::lround(resolution)))
                                            : c.name + "/" + r.variant;
  RunScale scale;
  RunReport rep = run_one(opt, c, r, resolution, sets, rel, scale);
  nlohmann::json run;
  std::string contrast_note;
  if (!c.contrast.empty()) contrast_note = run_contrast(opt, c, r, resolution, sets, rel, rep, run, scale);
  bool passed = rep.status == "completed";
  run["case"] = c.name;
  run["dir"] = rel;
  if (!r.variant.empty()) run["variant"] = r.variant;
  // what the record needs to tell runs apart and to re-make one: the level, the scheme asked
  // (--flux, --transport; "case": the case file's) and the one it resolved to, the commit, the threads
  run["level"] = opt.level;
  run["flux"] = opt.flux;
  run["transport"] = opt.transport;
  run["scheme"] = {{"flux", scale.flux}, {"transport", scale.transport}};
  // the commit of the binary that ran the rung (its last one, when --resume took it as it was or went on
  // from a checkpoint), not the one writing the report
  const std::vector<std::string> rung_commits = validate::rung_commits(opt.out_dir + "/" + rel);
  run["commit"] = rung_commits.empty() ? report.commit : rung_commits.back();
  run["date"] = report.date;
  run["threads"] = report.threads;
  run["device"] = report.device;
  run["sets"] = sets;
  run["reference_velocity"] = scale.u_ref;
  run["rho0"] = scale.rho0;
  run["resolution"] = resolution;
  run["dx"] = r.dx;
  run["particles"] = rep.particles;
  run["steps"] = rep.steps;
  run["wall_seconds"] = rep.wall_seconds;
  run["cpu_seconds"] = rep.cpu_seconds;
  run["particle_steps_per_second"] = rep.wall_seconds > 0 ? rep.particles * static_cast<double>(rep.steps) / rep.wall_seconds : 0.0;
  run["errors"] = rep.errors;
  run["status"] = rep.status;
  // a run made by several validations (--resume): the commits of each
  if (rung_commits.size() > 1) run["commits"] = rung_commits;
  // with refinement zones: each level's SPH particles x steps, and with local time stepping each level's steps
  {
    std::ifstream in(opt.out_dir + "/" + rel + "/summary.json");
    const nlohmann::json sj = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    if (sj.is_object() && sj.contains("level_particle_steps")) run["level_particle_steps"] = sj["level_particle_steps"];
    if (sj.is_object() && sj.contains("refinement") && sj["refinement"].contains("level_steps"))
      run["level_steps"] = sj["refinement"]["level_steps"];
  }
  if (!rep.message.empty()) run["message"] = rep.message;
  nlohmann::json th = nlohmann::json::object();
  std::string errs = rep.status == "completed" ? "" : "**" + rep.status + "** " + rep.message + "; ";
  passed = check_thresholds(c, r, rep, th, errs) && passed;
  errs += contrast_note;
  nlohmann::json shown = nlohmann::json::array();
  for (const std::string& name : c.shown)
    if (rep.errors.count(name)) shown.push_back(name);
  run["shown"] = shown;
  if (!contrast_note.empty()) run["note"] = contrast_note;
  run["thresholds"] = th;
  run["passed"] = passed;
  report.all_passed = report.all_passed && passed;
  report.j["runs"].push_back(run);
  report.md << "| " << c.name << " | " << fmt(resolution) << " | " << rep.particles << " | " << rep.steps << " | "
            << fmt(rep.wall_seconds) << " | " << fmt(run["particle_steps_per_second"].get<double>()) << " | " << errs << " | "
            << (passed ? "yes" : "**no**") << " |\n";
  return rep.errors;
}

// The key of a case's orders in validation.json: its name, and the scheme asked when not the case file's
std::string order_key(const ValidateOptions& opt, const std::string& name) {
  if (opt.flux == "case" && opt.transport == "case") return name;
  return name + " [" + opt.flux + ", " + opt.transport + "]";
}

// observed order between the two finest rungs: log(e_coarse / e_fine) / log(res_fine / res_coarse)
void observed_orders(const ValidateOptions& opt, const ValidationCase& c,
                     const std::vector<std::pair<double, std::map<std::string, double>>>& ladder, nlohmann::json& j) {
  if (ladder.size() < 2) return;
  const auto& [r1, e1] = ladder[ladder.size() - 2];
  const auto& [r2, e2] = ladder.back();
  for (const auto& [name, v1] : e1) {
    const auto it = e2.find(name);
    if (it == e2.end() || !(v1 > 0) || !(it->second > 0)) continue;
    j["orders"][order_key(opt, c.name)][name] = std::log(v1 / it->second) / std::log(r2 / r1);
  }
}

// --dry-run: every run the options choose (each rung, its contrast run) resolved to its scene and
// named flux scheme (scene/FluxSchemes.hpp), nothing run; false when a case file or its
// overrides are refused (the reader's message on stderr)
bool resolve_runs(const ValidateOptions& opt, const std::vector<const ValidationCase*>& chosen) {
  bool ok = true;
  for (const ValidationCase* c : chosen)
    for (const Rung& r : c->ladder) {
      if ((r.full_only && opt.level != "full") || !variant_chosen(opt, r)) continue;
      std::vector<std::vector<std::string>> runs{rung_sets(opt, *c, r)};
      if (!c->contrast.empty()) {
        runs.push_back(runs.front());
        runs.back().insert(runs.back().end(), c->contrast.begin(), c->contrast.end());
      }
      for (const std::vector<std::string>& sets : runs) {
        try {
          const Scene s = load_rung_scene(opt, r.file.empty() ? c->file : r.file, sets);
          std::printf("%s %s dx %g flux scheme %s\n", c->name.c_str(), r.variant.c_str(), r.dx,
                      flux_schemes[flux_scheme_index(flux_key(s))].name);  // the reader refuses a scheme not built
        } catch (const std::exception& e) {
          std::fprintf(stderr, "ondine validate: %s (dx %g): %s\n", c->name.c_str(), r.dx, e.what());
          ok = false;
        }
      }
    }
  return ok;
}

}  // namespace

int run_validation(const ValidateOptions& opt) {
  const std::vector<const ValidationCase*> chosen = chosen_cases(opt);
  if (!options_known(opt)) return 2;
  if (opt.list) {
    for (const ValidationCase& c : catalogue()) std::printf("%s %s %s\n", c.name.c_str(), group_of(c.name).c_str(), c.file.c_str());
    return 0;
  }
  if (opt.dry_run) return resolve_runs(opt, chosen) ? 0 : 1;
  std::filesystem::create_directories(opt.out_dir);
  Report report;
  report.commit = ONDINE_SOURCE_COMMIT;
  report.date = validate::utc_now();
  report.threads = backend_threads();
  report.device = device_name();
  report.j["level"] = opt.level;
  report.j["flux"] = opt.flux;
  report.j["transport"] = opt.transport;
  report.j["runs"] = nlohmann::json::array();
  report.j["orders"] = nlohmann::json::object();
  report.md << "# Validation (" << opt.level << (opt.flux == "case" ? "" : ", flux " + opt.flux)
            << (opt.transport == "case" ? "" : ", transport " + opt.transport) << ")\n\n| case | resolution | particles | steps | wall s | particle-steps/s | errors | passed |\n|---|---|---|---|---|---|---|---|\n";
  for (const ValidationCase* c : chosen) {
    std::vector<std::pair<double, std::map<std::string, double>>> ladder;
    for (const Rung& r : c->ladder) {
      if ((r.full_only && opt.level != "full") || !variant_chosen(opt, r)) continue;
      try {
        ladder.emplace_back(c->length / r.dx, run_rung(opt, *c, r, report));
      } catch (const Interrupted& i) {
        std::fprintf(stderr, "ondine validate: stopped by signal %d; the rung's checkpoint is written, no report; continue with the same "
                     "command and --resume\n", i.signal);
        return 128 + i.signal;
      } catch (const ResumeError& e) {
        std::fprintf(stderr, "ondine validate: cannot resume: %s\n", e.what());
        return 2;
      }
    }
    // APR comparisons: the APR (and coarse) run against the fine one; no observed order across them
    if (!c->ladder.empty() && !c->ladder.front().variant.empty())
      validate::compare_with_fine(opt, *c, report);
    else
      observed_orders(opt, *c, ladder, report.j);
  }
  return validate::write_report(opt, report);
}

}  // namespace ondine
