#include "solver/Runner.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "app/BuildInfo.hpp"
#include "io/AtomicFile.hpp"
#include "io/Checkpoint.hpp"
#include "io/SnapshotWriter.hpp"
#include "solver/RunOutput.hpp"
#include "solver/References.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

namespace {

std::atomic<int> stop_signal{-1};

using Clock = std::chrono::steady_clock;

std::string fmt_seconds(double s) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
  return o.str();
}

// The refinement zones of a case as a checkpoint records them (attribute
// `refinement_zones`): the transition width, then one line per zone, each number with
// the fewest significant digits that read back as the same double. A restart requires
// the case's to be the same text.
std::string shortest(double v) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string refinement_zone_text(const Scene& s) {
  std::ostringstream o;
  auto vec = [&](const Vec3& v) {
    o << "[";
    for (int k = 0; k < s.dimension; ++k) o << (k ? ", " : "") << shortest(v[k]);
    o << "]";
  };
  o << "transition " << shortest(s.refinement_transition) << "\n";
  for (const RefinementZone& z : s.refinement_zones) {
    o << "zone " << z.name << ": level " << z.level << ", in "
      << (z.parent >= 0 ? s.refinement_zones[static_cast<std::size_t>(z.parent)].name : std::string("-")) << ", min ";
    vec(z.box.min);
    o << ", max ";
    vec(z.box.max);
    if (z.motion == ZoneMotion::Translation) {
      o << ", velocity ";
      vec(z.velocity);
    } else if (z.motion == ZoneMotion::Criterion) {
      o << ", follow " << (z.criterion == ZoneCriterion::Pressure ? "pressure" : "speed") << " every " << z.every << " in ";
      vec(z.search.min);
      o << " .. ";
      vec(z.search.max);
    } else {
      o << ", static";
    }
    o << "\n";
  }
  return o.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// A checkpoint's APR state against the case: both or neither have refinement zones,
// and the same ones. Throws CheckpointError naming the file and the difference.
void check_refinement_restart(const Scene& scene, const CheckpointHeader& h, const std::string& path) {
  const CheckpointRefinement& a = h.refinement;
  const bool zones = !scene.refinement_zones.empty();
  if (zones && !a.present)
    throw CheckpointError(path + ": it has no refinement state (no attribute 'refinement_zones', no datasets birth_level, level, "
                          "guard, mother, parent_id): it was written by a run without refinement zones, and the case " +
                          scene.source_file + " has " + std::to_string(scene.refinement_zones.size()) +
                          (scene.refinement_zones.size() == 1 ? " zone" : " zones") + " (key 'refinement'); restart it with the case that wrote it, or start this case anew");
  if (!zones && a.present)
    throw CheckpointError(path + ": it was written by a run with refinement zones (it holds their APR fields and state), and the case " +
                          scene.source_file + " has none (no key 'refinement'); restart it with the case that wrote it");
  if (!zones) return;
  const std::string mine = refinement_zone_text(scene);
  if (mine == a.zones) return;
  const auto saved = lines_of(a.zones), ours = lines_of(mine);
  std::string what;
  for (std::size_t k = 0; k < std::max(saved.size(), ours.size()) && what.empty(); ++k) {
    if (k >= saved.size()) what = "the case has '" + ours[k] + "', the checkpoint no such zone";
    else if (k >= ours.size()) what = "the checkpoint has '" + saved[k] + "', the case no such zone";
    else if (saved[k] != ours[k]) what = "the checkpoint has '" + saved[k] + "', the case has '" + ours[k] + "'";
  }
  auto zones_count = [](std::size_t lines) { return std::to_string(lines - 1) + (lines == 2 ? " zone" : " zones"); };
  throw CheckpointError(path + ": it was written with other refinement zones than those of the case " + scene.source_file +
                        " (key 'refinement'): " + what + " (" + zones_count(saved.size()) + " in the checkpoint, " +
                        zones_count(ours.size()) + " in the case); a run with zones restarts with the zones it was written with");
}

template <int D>
RunReport run(const Scene& scene, const RunOptions& opt) {
  namespace fs = std::filesystem;
  const auto wall0 = Clock::now();
  const std::clock_t cpu0 = std::clock();
  const Communicator comm;
  const bool root = comm.rank() == 0;
  CheckpointSlice restart;
  const bool restarting = !opt.restart.empty();
  if (restarting) {
    restart = read_checkpoint(opt.restart, comm);
    const CheckpointHeader& h = restart.header;
    if (h.dimension != D || std::abs(h.dx - scene.dx) > 1e-12 * scene.dx)
      throw CheckpointError(opt.restart + ": written by a " + std::to_string(h.dimension) + "D run with dx = " + std::to_string(h.dx) +
                            " m; the case has dimension " + std::to_string(D) + " and dx = " + std::to_string(scene.dx) + " m");
    check_refinement_restart(scene, h, opt.restart);
  }
  auto make_simulation = [&]() {
    if (!restarting) return Simulation<D>(scene, nullptr);
    try {
      return Simulation<D>(scene, &restart);
    } catch (const CheckpointError&) {
      throw;
    } catch (const std::runtime_error& e) {  // the state read does not make a run (e.g. APR roles outside the zone table)
      throw CheckpointError(opt.restart + ": " + e.what());
    }
  };
  Simulation<D> sim = make_simulation();
  if (restarting && sim.state_checksum() != restart.header.checksum)
    throw CheckpointError(opt.restart + ": the particle state does not match the checksum stored with it: the file is corrupted");
  if (restarting && sim.refinement_on() && sim.refinement_checksum() != restart.header.refinement.checksum)
    throw CheckpointError(opt.restart + ": the APR fields (birth_level, level, guard, mother, parent_id) do not match the checksum "
                          "stored with them (refinement_checksum): the file is corrupted");
  if (root) fs::create_directories(opt.out_dir);
  comm.barrier();
  SnapshotWriter snapshots(opt.out_dir, scene.name, comm);
  if (!restarting) snapshots.remove_from(0);
  const double t_start = sim.time();

  CsvSeries diag_csv(opt.out_dir + "/diagnostics.csv", root), probe_csv(opt.out_dir + "/probes.csv", root),
      wall_csv(opt.out_dir + "/walls.csv", root), front_csv(opt.out_dir + "/front.csv", root),
      wave_csv(opt.out_dir + "/waves.csv", root);
  wave_csv.text() << "time,step";
  for (const WaveGauge& g : scene.wave_gauges) wave_csv.text() << "," << g.name << ".elevation";
  wave_csv.text() << "\n";
  diag_csv.text() << "time,step,dt,mass,momentum_x,momentum_y" << (D == 3 ? ",momentum_z" : "")
                  << ",kinetic_energy,max_speed,rho_min,rho_max,outside_domain,balance\n";
  probe_csv.text() << "time,step";
  for (const Probe& p : scene.probes) {
    probe_csv.text() << "," << p.name << ".pressure," << p.name << ".density";
    for (int k = 0; k < D; ++k) probe_csv.text() << "," << p.name << ".u" << "xyz"[k];
  }
  probe_csv.text() << "\n";

  RunReport report;
  report.particles = static_cast<std::size_t>(sim.global_size());
  double max_rho_dev = 0, max_ke = 0;
  std::int64_t max_outside = 0;
  double last_dt = 0;
  bool diverged = false;
  wall_csv.text() << "time,step";
  if (sim.has_walls())
    for (const WallForce& f : sim.wall_forces())
      for (const char* part : {"pressure", "viscous"})
        for (int k = 0; k < D; ++k) wall_csv.text() << "," << f.name << "." << part << "_f" << "xyz"[k];
  wall_csv.text() << "\n";
  const bool dam_break = scene.reference.kind == ReferenceKind::MartinMoyce;
  const double a = scene.reference.length;
  const double g = std::abs(scene.gravity[1]);
  std::vector<std::pair<double, double>> front;  // (T, Z)
  front_csv.text().precision(8);
  front_csv.text() << "T,Z,Z_experiment\n";
  if (restarting) {
    // the series of the earlier run up to the restart time, and the figures taken over them
    snapshots.resume(static_cast<std::size_t>(restart.header.snapshots));
    if (diag_csv.resume(t_start))
      for (const auto& row : diag_csv.resumed_rows()) {
        const std::size_t c = 6 + (D == 3);  // kinetic_energy
        if (row.size() < c + 5) continue;
        max_ke = std::max(max_ke, row[c]);
        max_rho_dev = std::max({max_rho_dev, std::abs(row[c + 2] / scene.rho0 - 1), std::abs(row[c + 3] / scene.rho0 - 1)});
        max_outside = std::max(max_outside, static_cast<std::int64_t>(row[c + 4]));
      }
    probe_csv.resume(t_start);
    wave_csv.resume(t_start);
    wall_csv.resume(t_start);
    if (dam_break && front_csv.resume(t_start * std::sqrt(2 * g / a)))
      for (const auto& row : front_csv.resumed_rows())
        if (row.size() >= 2) front.emplace_back(row[0], row[1]);
  }
  auto record = [&]() {
    sim.prepare_output();
    snapshots.write(sim.particles(), sim.time(), sim.steps(), static_cast<std::int64_t>(sim.size()));
    if (sim.has_walls()) {
      const auto forces = sim.wall_forces();
      wall_csv.text() << sim.time() << "," << sim.steps();
      for (const WallForce& f : forces) {
        for (int k = 0; k < D; ++k) wall_csv.text() << "," << f.pressure[k];
        for (int k = 0; k < D; ++k) wall_csv.text() << "," << f.viscous[k];
      }
      wall_csv.text() << "\n";
      wall_csv.flush();
    }
    if (dam_break) {
      const double T = sim.time() * std::sqrt(2 * g / a);
      const double Z = (sim.front_position() - scene.reference.origin[0]) / a;
      front.emplace_back(T, Z);
      front_csv.text() << T << "," << Z << "," << reference::interpolate(reference::martin_moyce_front(), T) << "\n";
      front_csv.flush();
    }
    const Diagnostics d = sim.diagnostics();
    diag_csv.text() << sim.time() << "," << sim.steps() << "," << last_dt << "," << d.mass;
    for (int k = 0; k < D; ++k) diag_csv.text() << "," << d.momentum[k];
    diag_csv.text() << "," << d.kinetic_energy << "," << d.max_speed << "," << d.rho_min << "," << d.rho_max << ","
                    << d.outside_domain << "," << sim.balance() << "\n";
    if (!scene.probes.empty()) {
      const auto samples = sim.sample_probes();
      probe_csv.text() << sim.time() << "," << sim.steps();
      for (const ProbeSample& s : samples) {
        probe_csv.text() << "," << s.pressure << "," << s.density;
        for (int k = 0; k < D; ++k) probe_csv.text() << "," << s.velocity[k];
      }
      probe_csv.text() << "\n";
      probe_csv.flush();
    }
    if (!scene.wave_gauges.empty()) {
      const auto levels = sim.wave_elevations();
      wave_csv.text() << sim.time() << "," << sim.steps();
      for (double z : levels) wave_csv.text() << "," << z;
      wave_csv.text() << "\n";
      wave_csv.flush();
    }
    diag_csv.flush();
    diverged = !d.finite;
    sim.finish_output();  // the run goes on from its own state (APR: the guards as they were)
    // stability figures over the whole run (validation.md): density range, kinetic energy, escapes
    max_rho_dev = std::max({max_rho_dev, std::abs(d.rho_max / scene.rho0 - 1), std::abs(d.rho_min / scene.rho0 - 1)});
    max_ke = std::max(max_ke, d.kinetic_energy);
    max_outside = std::max(max_outside, d.outside_domain);
  };

  // checkpoints: every N steps, every T wall seconds, at a clean stop and at the end
  const std::string checkpoint_path = opt.out_dir + "/checkpoint.h5";
  double checkpoint_seconds = 0;
  int checkpoints = 0;
  auto last_checkpoint = Clock::now();
  auto checkpoint = [&]() {
    const auto c0 = Clock::now();
    CheckpointHeader h;
    h.case_name = scene.name;
    h.dimension = D;
    h.dx = scene.dx;
    h.time = sim.time();
    h.step = sim.steps();
    h.snapshots = static_cast<std::int64_t>(snapshots.entries().size());
    const Diagnostics& d0 = sim.initial_diagnostics();
    h.initial_mass = d0.mass;
    for (int k = 0; k < 3; ++k) h.initial_momentum[k] = d0.momentum[k];
    h.checksum = sim.state_checksum();
    h.wall_corrections = sim.wall_corrections();
    if (sim.refinement_on()) {
      h.refinement = sim.refinement_state();
      h.refinement.zones = refinement_zone_text(scene);
    }
    write_checkpoint(checkpoint_path, h, static_cast<std::int64_t>(sim.size()), sim.state_rows(), comm);
    sim.invalidate_neighbours();  // a restart from this file takes the same path from here
    last_checkpoint = Clock::now();
    checkpoint_seconds += std::chrono::duration<double>(last_checkpoint - c0).count();
    ++checkpoints;
    if (root && opt.progress)
      std::fprintf(stderr, "  checkpoint: step %lld, t = %.6g s -> %s (%.2f s)\n", static_cast<long long>(sim.steps()), sim.time(),
                   checkpoint_path.c_str(), std::chrono::duration<double>(last_checkpoint - c0).count());
  };

  if (!restarting) record();
  const auto loop0 = Clock::now();
  auto last_progress = loop0;
  std::int64_t pair_samples = 0;
  double pair_sum = 0;
  int output_index = static_cast<int>(std::floor(sim.time() / scene.output_interval * (1 + 1e-12))) + 1;
  report.status = "completed";
  while (sim.time() < scene.duration * (1 - 1e-12)) {
    const double next_output = std::min(scene.duration, output_index * scene.output_interval);
    try {
      last_dt = sim.step(next_output);
    } catch (const BlowUp& e) {
      // the particles hold the state at the start of the failed step: write it
      if (root) std::fprintf(stderr, "ondine: %s; the last good state (t = %g s) is the last snapshot\n", e.what(), sim.time());
      snapshots.write(sim.particles(), sim.time(), sim.steps(), static_cast<std::int64_t>(sim.size()));
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
    const int sig = static_cast<int>(comm.max(static_cast<std::int64_t>(stop_signal.load())));
    if (sig >= 0) {
      report.status = "interrupted";
      report.signal = sig;
      if (snapshots.entries().empty() || sim.time() > snapshots.entries().back().time) record();
      break;
    }
    if (scene.max_steps > 0 && sim.steps() >= scene.max_steps) {
      report.status = "max_steps";
      if (snapshots.entries().empty() || sim.time() > snapshots.entries().back().time) record();
      break;
    }
    const auto now = Clock::now();
    const bool by_steps = scene.checkpoint_every_steps > 0 && sim.steps() % scene.checkpoint_every_steps == 0;
    const bool by_wall = scene.checkpoint_every_wall_seconds > 0 &&
                         comm.any(std::chrono::duration<double>(now - last_checkpoint).count() >= scene.checkpoint_every_wall_seconds);
    if (by_steps || by_wall) checkpoint();
    if (root && opt.progress && std::chrono::duration<double>(now - last_progress).count() >= opt.progress_interval) {
      last_progress = now;
      const double el = std::chrono::duration<double>(now - loop0).count();
      const double rate = (sim.steps() - (restarting ? restart.header.step : 0)) / el;
      const double eta = el * (scene.duration - sim.time()) / std::max(sim.time() - t_start, 1e-300);
      std::fprintf(stderr, "  t = %.4g / %.4g s   step %lld   %.1f steps/s   dt %.3g s   ETA %s\n", sim.time(),
                   scene.duration, static_cast<long long>(sim.steps()), rate, last_dt, fmt_seconds(eta).c_str());
    }
  }
  if (report.status != "diverged") checkpoint();
  const double loop_seconds = std::chrono::duration<double>(Clock::now() - loop0).count();
  report.steps = sim.steps() - (restarting ? restart.header.step : 0);
  report.simulated_time = sim.time();
  report.wall_seconds = std::chrono::duration<double>(Clock::now() - wall0).count();
  report.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
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
  if (D == 2 && scene.reference.kind == ReferenceKind::Hydrostatic && sim.has_walls() && report.status != "diverged") {
    // Still water: the force on a body (a closed wall with the fluid outside) lying wholly
    // under the surface y = origin_y + H is Archimedes' -rho0 g A. buoyancy_error:
    // |F_pressure + F_viscous - (-rho0 g A)| / (rho0 |g| A), the largest over such bodies.
    const double surface = scene.reference.origin[1] + scene.reference.length;
    const auto forces = sim.wall_forces();
    double worst = -1;
    for (const Wall& w : scene.walls) {
      bool below = w.closed && !w.fluid_inside;
      for (const auto& pt : w.points) below = below && pt[1] < surface;
      if (!below) continue;
      const double A = reference::polygon_area(w.points);
      const double gn = std::hypot(scene.gravity[0], scene.gravity[1]);
      for (const WallForce& f : forces) {
        if (f.name != w.name) continue;
        double e2 = 0;
        for (int k = 0; k < 2; ++k) {
          const double d = f.pressure[k] + f.viscous[k] + scene.rho0 * scene.gravity[k] * A;
          e2 += d * d;
        }
        worst = std::max(worst, std::sqrt(e2) / (scene.rho0 * gn * A));
      }
    }
    if (worst >= 0) report.errors["buoyancy_error"] = worst;
  }

  nlohmann::json j;
  j["case"] = scene.name;
  j["source"] = scene.source_file;
  j["status"] = report.status;
  if (!report.message.empty()) j["message"] = report.message;
  j["dimension"] = D;
  j["particles"] = report.particles;
  j["steps"] = report.steps;
  j["total_steps"] = sim.steps();
  if (restarting) j["restarted_from"] = {{"file", opt.restart}, {"step", restart.header.step}, {"time", restart.header.time}};
  j["simulated_time"] = sim.time();
  j["wall_seconds"] = report.wall_seconds;
  j["cpu_seconds"] = report.cpu_seconds;
  j["loop_seconds"] = loop_seconds;
  j["particle_steps_per_second"] = loop_seconds > 0 ? report.particles * static_cast<double>(report.steps) / loop_seconds : 0.0;
  j["mean_neighbours"] = pair_samples > 0 ? pair_sum / pair_samples / report.particles : 0.0;
  j["neighbour_list_builds"] = sim.neighbour_builds();
  j["backend"] = default_backend();
  j["threads"] = backend_threads();
  j["ranks"] = comm.size();
  j["parallel"] = {{"balance_tau", sim.balance()},
                   {"rebalances", sim.rebalances()},
                   {"migrated_particles", sim.migrated()},
                   {"exchange_seconds_max", comm.max(sim.exchange_seconds())},
                   {"exchange_share_of_loop", loop_seconds > 0 ? comm.max(sim.exchange_seconds()) / loop_seconds : 0.0}};
  j["checkpoints"] = {{"count", checkpoints}, {"seconds", checkpoint_seconds}, {"file", checkpoint_path}};
  if (sim.refinement_on()) {
    const AdaptiveRefinement<D>& apr = sim.refinement();
    j["refinement"] = {{"levels", apr.levels()},
                       {"particles", sim.global_size()},
                       {"sph_particles", sim.sph_particles()},
                       {"guards", apr.guards()},
                       {"passive_guards", apr.passive()},
                       {"refined", apr.refined()},
                       {"deleted", apr.deleted()}};
  }
  j["kokkos_version"] = kokkos_version();
  j["ondine_version"] = ondine_version();
  j["scheme"] = {{"kernel", to_string(scene.kernel)},
                 {"R_over_dx", scene.R_over_dx},
                 {"dx", scene.dx},
                 {"c0", scene.c0},
                 {"reference_velocity", scene.reference_velocity},
                 {"eos", to_string(scene.eos)},
                 {"viscous_term", to_string(scene.viscous_term)},
                 {"nu", scene.nu},
                 {"morris_lattice_factor", sim.morris_factor()},
                 {"consistent_laplacian", uses_consistent_laplacian(scene)},
                 {"delta_sph", scene.delta_sph},
                 {"artificial_viscosity", scene.artificial_viscosity},
                 {"background_pressure", scene.background_pressure},
                 {"wall_velocity_reconstruction", scene.wall_velocity_reconstruction && !scene.walls.empty()},
                 {"renormalised_continuity", scene.renormalised_continuity},
                 {"time_integrator", to_string(scene.integrator)}};
  j["errors"] = report.errors;
  j["snapshots"] = snapshots.entries().size();
  if (root) write_text_atomically(opt.out_dir + "/summary.json", j.dump(2) + "\n");
  return report;
}

}  // namespace

void request_stop(int signal) { stop_signal.store(signal); }

RunReport run_scene(const Scene& scene, const RunOptions& options) {
  return scene.dimension == 2 ? run<2>(scene, options) : run<3>(scene, options);
}

}  // namespace ondine
