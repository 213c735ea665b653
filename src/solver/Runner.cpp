#include "solver/Runner.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "app/BuildInfo.hpp"
#include "io/AtomicFile.hpp"
#include "io/SnapshotWriter.hpp"
#include "solver/References.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

namespace {

std::atomic<bool> stop_requested{false};

using Clock = std::chrono::steady_clock;

std::string fmt_seconds(double s) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
  return o.str();
}

template <int D>
RunReport run(const Scene& scene, const RunOptions& opt) {
  namespace fs = std::filesystem;
  const auto wall0 = Clock::now();
  Simulation<D> sim(scene);
  fs::create_directories(opt.out_dir);
  SnapshotWriter snapshots(opt.out_dir, scene.name);

  std::ostringstream diag_csv, probe_csv;
  diag_csv << "time,step,dt,mass,momentum_x,momentum_y" << (D == 3 ? ",momentum_z" : "")
           << ",kinetic_energy,max_speed,rho_min,rho_max,outside_domain\n";
  probe_csv << "time,step";
  for (const Probe& p : scene.probes) {
    probe_csv << "," << p.name << ".pressure," << p.name << ".density";
    for (int k = 0; k < D; ++k) probe_csv << "," << p.name << ".u" << "xyz"[k];
  }
  probe_csv << "\n";
  diag_csv << std::setprecision(12);
  probe_csv << std::setprecision(12);

  RunReport report;
  report.particles = sim.size();
  double max_rho_dev = 0, max_ke = 0;
  std::int64_t max_outside = 0;
  double last_dt = 0;
  bool diverged = false;
  std::ostringstream wall_csv, front_csv;
  wall_csv << std::setprecision(12) << "time,step";
  if (sim.has_walls())
    for (const WallForce& f : sim.wall_forces())
      for (const char* part : {"pressure", "viscous"})
        for (int k = 0; k < D; ++k) wall_csv << "," << f.name << "." << part << "_f" << "xyz"[k];
  wall_csv << "\n";
  const bool dam_break = scene.reference.kind == ReferenceKind::MartinMoyce;
  const double a = scene.reference.length;
  const double g = std::abs(scene.gravity[1]);
  std::vector<std::pair<double, double>> front;  // (T, Z)
  front_csv << std::setprecision(8) << "T,Z,Z_experiment\n";
  auto record = [&]() {
    sim.prepare_output();
    snapshots.write(sim.particles(), sim.time(), sim.steps());
    if (sim.has_walls()) {
      wall_csv << sim.time() << "," << sim.steps();
      for (const WallForce& f : sim.wall_forces()) {
        for (int k = 0; k < D; ++k) wall_csv << "," << f.pressure[k];
        for (int k = 0; k < D; ++k) wall_csv << "," << f.viscous[k];
      }
      wall_csv << "\n";
      write_text_atomically(opt.out_dir + "/walls.csv", wall_csv.str());
    }
    if (dam_break) {
      const double T = sim.time() * std::sqrt(2 * g / a);
      const double Z = (sim.front_position() - scene.reference.origin[0]) / a;
      front.emplace_back(T, Z);
      front_csv << T << "," << Z << "," << reference::interpolate(reference::martin_moyce_front(), T) << "\n";
      write_text_atomically(opt.out_dir + "/front.csv", front_csv.str());
    }
    const Diagnostics d = sim.diagnostics();
    diag_csv << sim.time() << "," << sim.steps() << "," << last_dt << "," << d.mass;
    for (int k = 0; k < D; ++k) diag_csv << "," << d.momentum[k];
    diag_csv << "," << d.kinetic_energy << "," << d.max_speed << "," << d.rho_min << "," << d.rho_max << ","
             << d.outside_domain << "\n";
    if (!scene.probes.empty()) {
      probe_csv << sim.time() << "," << sim.steps();
      for (const ProbeSample& s : sim.sample_probes()) {
        probe_csv << "," << s.pressure << "," << s.density;
        for (int k = 0; k < D; ++k) probe_csv << "," << s.velocity[k];
      }
      probe_csv << "\n";
      write_text_atomically(opt.out_dir + "/probes.csv", probe_csv.str());
    }
    write_text_atomically(opt.out_dir + "/diagnostics.csv", diag_csv.str());
    diverged = !d.finite;
    // stability figures over the whole run (validation.md): density range, kinetic energy, escapes
    max_rho_dev = std::max({max_rho_dev, std::abs(d.rho_max / scene.rho0 - 1), std::abs(d.rho_min / scene.rho0 - 1)});
    max_ke = std::max(max_ke, d.kinetic_energy);
    max_outside = std::max(max_outside, d.outside_domain);
  };

  record();
  const auto loop0 = Clock::now();
  auto last_progress = loop0;
  std::int64_t pair_samples = 0;
  double pair_sum = 0;
  int output_index = 1;
  report.status = "completed";
  while (sim.time() < scene.duration * (1 - 1e-12)) {
    const double next_output = std::min(scene.duration, output_index * scene.output_interval);
    try {
      last_dt = sim.step(next_output);
    } catch (const BlowUp& e) {
      // the particles hold the state at the start of the failed step: write it
      std::fprintf(stderr, "ondine: %s; the last good state (t = %g s) is the last snapshot\n", e.what(), sim.time());
      snapshots.write(sim.particles(), sim.time(), sim.steps());
      report.message = e.what();
      diverged = true;
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "ondine: step %lld: %s\n", static_cast<long long>(sim.steps()), e.what());
      report.message = e.what();
      diverged = true;
    }
    if (diverged) {
      report.status = "diverged";
      break;
    }
    if (sim.time() >= next_output * (1 - 1e-12)) {
      ++output_index;
      record();
      if (diverged) {
        report.status = "diverged";
        break;
      }
      if (pair_samples < 8) {
        pair_sum += static_cast<double>(sim.pair_count());
        ++pair_samples;
      }
    }
    if (stop_requested.load()) {
      report.status = "interrupted";
      if (sim.time() > snapshots.entries().back().time) record();
      break;
    }
    if (scene.max_steps > 0 && sim.steps() >= scene.max_steps) {
      report.status = "max_steps";
      if (sim.time() > snapshots.entries().back().time) record();
      break;
    }
    const auto now = Clock::now();
    if (opt.progress && std::chrono::duration<double>(now - last_progress).count() >= opt.progress_interval) {
      last_progress = now;
      const double el = std::chrono::duration<double>(now - loop0).count();
      const double rate = sim.steps() / el;
      const double eta = el * (scene.duration - sim.time()) / std::max(sim.time(), 1e-300);
      std::fprintf(stderr, "  t = %.4g / %.4g s   step %lld   %.1f steps/s   dt %.3g s   ETA %s\n", sim.time(),
                   scene.duration, static_cast<long long>(sim.steps()), rate, last_dt, fmt_seconds(eta).c_str());
    }
  }
  const double loop_seconds = std::chrono::duration<double>(Clock::now() - loop0).count();
  report.steps = sim.steps();
  report.simulated_time = sim.time();
  report.wall_seconds = std::chrono::duration<double>(Clock::now() - wall0).count();
  if (report.status != "diverged") report.errors = sim.errors();
  {
    // kinetic energy scale: 1/2 M u_ref^2 with u_ref the case's reference velocity
    const double ke_scale = 0.5 * sim.diagnostics().mass * scene.reference_velocity * scene.reference_velocity;
    report.errors["max_density_deviation"] = max_rho_dev;
    report.errors["max_kinetic_energy_ratio"] = ke_scale > 0 ? max_ke / ke_scale : 0.0;
    report.errors["max_outside_domain"] = static_cast<double>(max_outside);
    report.errors["non_finite"] = report.status == "diverged" ? 1.0 : 0.0;
  }
  if (dam_break && report.status != "diverged")
    for (const auto& [k, v] : reference::martin_moyce_errors(front)) report.errors[k] = v;

  nlohmann::json j;
  j["case"] = scene.name;
  j["source"] = scene.source_file;
  j["status"] = report.status;
  if (!report.message.empty()) j["message"] = report.message;
  j["dimension"] = D;
  j["particles"] = sim.size();
  j["steps"] = sim.steps();
  j["simulated_time"] = sim.time();
  j["wall_seconds"] = report.wall_seconds;
  j["loop_seconds"] = loop_seconds;
  j["particle_steps_per_second"] = loop_seconds > 0 ? sim.size() * static_cast<double>(sim.steps()) / loop_seconds : 0.0;
  j["mean_neighbours"] = pair_samples > 0 ? pair_sum / pair_samples / sim.size() : 0.0;
  j["neighbour_list_builds"] = sim.neighbour_builds();
  j["backend"] = default_backend();
  j["threads"] = backend_threads();
  j["ranks"] = opt.ranks;
  j["kokkos_version"] = kokkos_version();
  j["ondine_version"] = ondine_version();
  j["scheme"] = {{"kernel", to_string(scene.kernel)},
                 {"R_over_dx", scene.R_over_dx},
                 {"dx", scene.dx},
                 {"c0", scene.c0},
                 {"eos", to_string(scene.eos)},
                 {"viscous_term", to_string(scene.viscous_term)},
                 {"nu", scene.nu},
                 {"delta_sph", scene.delta_sph},
                 {"artificial_viscosity", scene.artificial_viscosity},
                 {"background_pressure", scene.background_pressure},
                 {"time_integrator", to_string(scene.integrator)}};
  j["errors"] = report.errors;
  j["snapshots"] = snapshots.entries().size();
  write_text_atomically(opt.out_dir + "/summary.json", j.dump(2) + "\n");
  return report;
}

}  // namespace

void request_stop() { stop_requested.store(true); }

RunReport run_scene(const Scene& scene, const RunOptions& options) {
  return scene.dimension == 2 ? run<2>(scene, options) : run<3>(scene, options);
}

}  // namespace ondine
