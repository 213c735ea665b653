#include "app/ValidateReport.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>

#include "io/AtomicFile.hpp"
#include "io/SnapshotWriter.hpp"
#include "kernels/turbulence/LogLaw.hpp"
#include "observers/ChannelReference.hpp"
#include "reference/References.hpp"
#include "reference/WedgeImpact.hpp"

namespace ondine::validate {

namespace {

// The last snapshot of a run folder (<case>_<NNNNNN>.h5: the last name in order); empty if none.
std::string last_snapshot(const std::string& dir) {
  std::string last;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".h5" && e.path().string() > last) last = e.path().string();
  return last;
}

// Taylor-Green max speed and E_k over time against the decay
void write_taylor_green_profile(const Scene& s, const std::string& dir, std::ostringstream& o) {
  // diagnostics.csv: time,step,dt,mass,momentum_x,momentum_y,kinetic_energy,max_speed,...
  const auto rows = reference::read_table(dir + "/diagnostics.csv");
  const FluidBlock& b = s.blocks.front();
  const double k = 2 * M_PI / b.tg_wavelength;
  o << "t,max_speed,max_speed_exact,kinetic_energy,kinetic_energy_exact\n";
  for (const auto& r : rows) {
    const double decay = std::exp(-2 * s.nu * k * k * r[0]);
    o << r[0] << "," << r[7] << "," << b.tg_amplitude * decay << "," << r[6] << "," << rows.front()[6] * decay * decay << "\n";
  }
}

// Poiseuille / Couette u(y) and hydrostatic p(z) per particle at the end, cavity centreline
// velocities (Ghia's points are plotted from cases/reference/); false without a snapshot
bool write_snapshot_profile(const Scene& s, const std::string& dir, std::ostringstream& o) {
  const ReferenceKind kind = s.reference.kind;
  const std::string file = last_snapshot(dir);
  if (file.empty()) return false;
  const SnapshotData d = read_snapshot(file);
  auto column = [&](const std::string& name) -> const std::vector<double>& {
    for (std::size_t k = 0; k < d.names.size(); ++k)
      if (d.names[k] == name) return d.values[k];
    throw std::runtime_error(file + ": no dataset '" + name + "'");
  };
  const auto& x = column("position");
  const std::vector<double>& u = column("velocity");
  const Vec3 o0 = s.reference.origin;
  const double L = s.reference.length;
  if (kind == ReferenceKind::Poiseuille || kind == ReferenceKind::Couette) {
    o << "y,u,u_exact\n";
    for (std::size_t i = 0; i < d.particles; ++i) {
      const double y = x[3 * i + 1] - o0[1];
      o << y << "," << u[3 * i] << "," << channel_startup(s, y, d.time) << "\n";
    }
  } else if (kind == ReferenceKind::LogLaw) {
    // every particle's u against the law with u_* = sqrt(F H) (observers/ErrorNormsImpl.hpp, log_law)
    const Turbulence& tu = s.turbulence;
    const LogLaw law = LogLaw::make(tu.kappa, s.nu, tu.smooth_constant, tu.wall_function == WallLaw::Rough ? tu.roughness : 0.0,
                                    tu.rough_constant);
    const double us = std::sqrt((s.body_force[0] + s.gravity[0]) * L);
    o << "y,u,u_exact\n";
    for (std::size_t i = 0; i < d.particles; ++i) {
      const double y = x[3 * i + 1] - o0[1];
      if (y > 0) o << y << "," << u[3 * i] << "," << law.speed(us, y) << "\n";
    }
  } else if (kind == ReferenceKind::OpenChannel) {
    // the particles within dx/2 of the measured section, against the parabola of the inlet's mean
    o << "y,u,u_exact\n";
    for (std::size_t i = 0; i < d.particles; ++i)
      if (std::abs(x[3 * i] - o0[0]) < 0.5 * s.dx) {
        const double y = x[3 * i + 1] - o0[1];
        o << y << "," << u[3 * i] << "," << 6 * s.reference.velocity * y * (L - y) / (L * L) << "\n";
      }
  } else if (kind == ReferenceKind::Hydrostatic) {
    const auto& p = column("pressure");
    const double g = std::abs(s.gravity[1]);
    o << "z,p,p_exact\n";
    for (std::size_t i = 0; i < d.particles; ++i) {
      const double z = x[3 * i + 1] - o0[1];
      o << z << "," << p[i] << "," << s.rho0 * g * (L - z) << "\n";
    }
  } else {
    // particles within dx/2 of each centreline: line u (x = L/2, s = y/L), line v (y = L/2, s = x/L), velocity / U
    o << "line,s,velocity\n";
    for (std::size_t i = 0; i < d.particles; ++i)
      for (int line = 0; line < 2; ++line)
        if (std::abs(x[3 * i + line] - o0[line] - 0.5 * L) < 0.5 * s.dx)
          o << (line == 0 ? "u" : "v") << "," << (x[3 * i + 1 - line] - o0[1 - line]) / L << ","
            << u[3 * i + line] / s.reference_velocity << "\n";
  }
  return true;
}

// the last probe's pressure over time (probes.csv), relative L2 difference to the fine run's
// (the runs must have written the same output times)
void probe_pressure_difference(const std::string& pa, const std::string& pb, nlohmann::json& e) {
  namespace fs = std::filesystem;
  std::vector<std::vector<double>> a, b;
  if (fs::exists(pa) && fs::exists(pb)) {
    a = reference::read_table(pa);
    b = reference::read_table(pb);
  }
  // the column of the last probe's pressure, from the header (time, step, then per probe
  // pressure, density and the D velocity components)
  std::size_t col = 0;
  if (!a.empty()) {
    std::ifstream in(pa);
    std::string header, name;
    std::getline(in, header);
    std::istringstream cols(header);
    for (std::size_t k = 0; std::getline(cols, name, ','); ++k)
      if (name.size() > 9 && name.compare(name.size() - 9, 9, ".pressure") == 0) col = k;
  }
  if (col > 0 && a.size() == b.size() && a.front().size() > col && a.front().size() == b.front().size()) {
    double num = 0, den = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      num += (a[k][col] - b[k][col]) * (a[k][col] - b[k][col]);
      den += b[k][col] * b[k][col];
    }
    if (den > 0) e["probe_pressure_difference_vs_fine"] = std::sqrt(num / den);
  }
}

// One run of an APR comparison against the fine run: its ratios, issue 7's criterion, its line in the report
void compare_run_with_fine(const ValidateOptions& opt, const ValidationCase& c, nlohmann::json& run,
                           nlohmann::json& fine, Report& report) {
  auto& e = run["errors"];
  const auto& ef = fine["errors"];
  if (e.contains("velocity_l2_near_wall") && ef.contains("velocity_l2_near_wall"))
    e["near_wall_error_over_fine"] = e["velocity_l2_near_wall"].get<double>() / ef["velocity_l2_near_wall"].get<double>();
  e["wall_time_over_fine"] = run["wall_seconds"].get<double>() / fine["wall_seconds"].get<double>();
  // the same ratio in CPU time: on a shared machine the two runs meet different loads, which
  // inflate their wall times but not (with a fixed thread count) their CPU times
  if (run.contains("cpu_seconds") && fine.value("cpu_seconds", 0.0) > 0)
    e["cpu_time_over_fine"] = run["cpu_seconds"].get<double>() / fine["cpu_seconds"].get<double>();
  probe_pressure_difference(opt.out_dir + "/" + run["dir"].get<std::string>() + "/probes.csv",
                            opt.out_dir + "/" + fine["dir"].get<std::string>() + "/probes.csv", e);
  // issue 7's criterion, at the full level (the steady Poiseuille of thesis Table 5.3; the
  // quick level stops in the start-up transient, which the coarse core carries): the APR
  // run's near-wall error within 10 % of the fine run's, at under 70 % of its run time,
  // checked on CPU time (wall time where CPU time is missing), which other load does not inflate
  bool criterion = true;
  const char* time_ratio = e.contains("cpu_time_over_fine") ? "cpu_time_over_fine" : "wall_time_over_fine";
  if (opt.level == "full" && run.value("variant", "") == "apr" && e.contains("near_wall_error_over_fine")) {
    run["thresholds"]["near_wall_error_over_fine"] = 1.1;
    run["thresholds"][time_ratio] = 0.7;
    criterion = e["near_wall_error_over_fine"].get<double>() <= 1.1 && e[time_ratio].get<double>() <= 0.7;
    if (!criterion) {
      run["passed"] = false;
      report.all_passed = false;
    }
  }
  std::ostringstream& md = report.md;
  md << "\n" << c.name << " / " << run["variant"].get<std::string>() << " against fine:";
  for (const char* k : {"near_wall_error_over_fine", "wall_time_over_fine", "cpu_time_over_fine", "probe_pressure_difference_vs_fine",
                        "cpu_time_over_global_step"})
    if (e.contains(k)) md << " " << k << " " << fmt(e[k].get<double>()) << ";";
  if (!criterion) md << " **fails** (near_wall_error_over_fine <= 1.1 and " << time_ratio << " <= 0.7)";
  md << "\n";
}

// the wedge impact: the wall sensors at the last output instant (wall_sensors.csv) against
// the similarity profile's mean over each sensor's span, both over rho U^2, at eta = distance / s
void write_wedge_profile(const Scene& s, const std::string& dir, std::ostringstream& o) {
  const auto rows = reference::read_table(dir + "/wall_sensors.csv");
  if (rows.empty()) return;
  const auto& last = rows.back();
  const double U = s.reference.velocity, P0 = s.rho0 * U * U, sv = U * (last[0] - s.reference.from);
  if (!(sv > 0) || last.size() < 2 + s.wall_sensors.size()) return;
  const auto profile = reference::read_wedge_profile(s.reference.file);
  o << "eta,p,p_exact,s\n";
  for (std::size_t j = 0; j < s.wall_sensors.size(); ++j) {
    const WallSensor& w = s.wall_sensors[j];
    double d2 = 0;
    for (int k = 0; k < 2; ++k) d2 += (w.position[k] - s.reference.origin[k]) * (w.position[k] - s.reference.origin[k]);
    const double c = std::sqrt(d2);
    o << c / sv << "," << last[2 + j] / P0 << "," << reference::profile_mean(profile, (c - 0.5 * w.size) / sv, (c + 0.5 * w.size) / sv)
      << "," << sv << "\n";
  }
}

}  // namespace

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

// profile.csv of a run, the solution next to its reference for the plots: Poiseuille u(y) (the
// open channel's at its section) and
// hydrostatic p(z) per particle at the end, cavity centreline velocities (Ghia's points are
// plotted from cases/reference/), Taylor-Green max speed and E_k over time against the decay,
// the wedge impact's wall sensors against the similarity profile.
void write_profile(const Scene& s, const std::string& dir) {
  std::ostringstream o;
  o.precision(8);
  const ReferenceKind kind = s.reference.kind;
  const bool tg = !s.blocks.empty() && s.blocks.front().velocity_kind == InitialVelocity::TaylorGreen;
  if (tg) {
    write_taylor_green_profile(s, dir, o);
  } else if (kind == ReferenceKind::Poiseuille || kind == ReferenceKind::Couette || kind == ReferenceKind::OpenChannel ||
             kind == ReferenceKind::LogLaw || kind == ReferenceKind::Hydrostatic ||
             kind == ReferenceKind::GhiaRe100 || kind == ReferenceKind::GhiaRe1000) {
    if (!write_snapshot_profile(s, dir, o)) return;
  } else if (kind == ReferenceKind::WedgeImpact) {
    write_wedge_profile(s, dir, o);
    if (o.str().empty()) return;
  } else {
    return;
  }
  write_text_atomically(dir + "/profile.csv", o.str());
}

double front_difference(const std::string& a, const std::string& b) {
  auto front = [](const std::string& dir) {
    std::vector<std::pair<double, double>> f;
    for (const auto& r : reference::read_table(dir + "/front.csv")) f.emplace_back(r[0], r[1]);
    return f;
  };
  return reference::front_relative_difference(front(a), front(b));
}

void compare_with_fine(const ValidateOptions& opt, const ValidationCase& c, Report& report) {
  nlohmann::json& j = report.j;
  nlohmann::json* fine = nullptr;
  for (auto& run : j["runs"])
    if (run["case"] == c.name && run.value("variant", "") == "fine") fine = &run;
  // a run with local time stepping (variant X_lts) against the same refined run with one global step (X)
  for (auto& run : j["runs"]) {
    const std::string v = run.value("variant", "");
    if (run["case"] != c.name || v.size() < 5 || v.compare(v.size() - 4, 4, "_lts") != 0) continue;
    for (const auto& base : j["runs"])
      if (base["case"] == c.name && base.value("variant", "") == v.substr(0, v.size() - 4) && base.value("cpu_seconds", 0.0) > 0 &&
          run.contains("cpu_seconds"))
        run["errors"]["cpu_time_over_global_step"] = run["cpu_seconds"].get<double>() / base["cpu_seconds"].get<double>();
  }
  if (fine && (*fine)["status"] == "completed") {
    for (auto& run : j["runs"]) {
      if (run["case"] != c.name || run.value("variant", "") == "fine") continue;
      compare_run_with_fine(opt, c, run, *fine, report);
    }
  }
}

int write_report(const ValidateOptions& opt, Report& report) {
  namespace fs = std::filesystem;
  std::ostringstream& md = report.md;
  md << "\nObserved orders (two finest resolutions):\n\n";
  for (const auto& [cname, errs] : report.j["orders"].items())
    for (const auto& [ename, order] : errs.items()) md << "- " << cname << " / " << ename << ": " << fmt(order.get<double>()) << "\n";
  write_text_atomically(opt.out_dir + "/validation.json", report.j.dump(2) + "\n");
  // plots (error against wall time, solution against reference, conserved quantities), if
  // Debian python3-matplotlib (/usr/bin/python3) is there: the script writes the PNGs and figures.md, which links them
  const std::string plot = opt.source_dir + "/scripts/plot_validation.py";
  bool plotted = false;
  if (fs::exists(plot)) {
    const std::string cmd = "/usr/bin/python3 '" + plot + "' '" + opt.out_dir + "' '" + opt.source_dir + "' > '" + opt.out_dir + "/plot.log' 2>&1";
    plotted = std::system(cmd.c_str()) == 0;
    std::ifstream figures(opt.out_dir + "/figures.md");
    if (plotted && figures) md << "\n" << figures.rdbuf();
  }
  if (!plotted) std::fprintf(stderr, "ondine validate: no plots (python3-matplotlib missing? see %s/plot.log)\n", opt.out_dir.c_str());
  write_text_atomically(opt.out_dir + "/validation.md", md.str());
  std::fprintf(stderr, "ondine validate: %s; wrote %s/validation.json and validation.md\n",
               report.all_passed ? "all runs passed" : "SOME RUNS FAILED", opt.out_dir.c_str());
  return report.all_passed ? 0 : 1;
}

}  // namespace ondine::validate
