#include "run/Runner.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "run/BuildInfo.hpp"
#include "io/AtomicFile.hpp"
#include "io/Checkpoint.hpp"
#include "run/RunRecorder.hpp"
#include "run/RunRestart.hpp"
#include "solver/Simulation.hpp"
#include "solver/hooks/OpenBoundaryStep.hpp"

namespace ondine {

namespace {

std::atomic<int> stop_signal{-1};

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string fmt_seconds(double s) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
  return o.str();
}

// The restart file of a run and when to write it: every N steps, every T wall seconds,
// at a clean stop and at the end. A restart from it takes the same path as the run.
template <int D>
class Checkpointer {
 public:
  Checkpointer(const Scene& scene, const RunOptions& opt, const Communicator& comm)
      : scene_(scene), path_(opt.out_dir + "/checkpoint.h5"), comm_(comm), progress_(opt.progress && comm.rank() == 0) {}

  bool due(const Simulation<D>& sim) const {
    const bool by_steps = scene_.checkpoint_every_steps > 0 && sim.steps() % scene_.checkpoint_every_steps == 0;
    const bool by_wall = scene_.checkpoint_every_wall_seconds > 0 &&
                         comm_.any(seconds_since(last_) >= scene_.checkpoint_every_wall_seconds);
    return by_steps || by_wall;
  }

  // cost: the run's wall and CPU seconds since t = 0 (RunTiming::cost)
  void write(Simulation<D>& sim, std::size_t snapshots, std::pair<double, double> cost, std::size_t initial_particles) {
    const auto c0 = Clock::now();
    CheckpointHeader h;
    h.case_name = scene_.name;
    h.dimension = D;
    h.dx = scene_.dx;
    h.time = sim.time();
    h.step = sim.steps();
    h.snapshots = static_cast<std::int64_t>(snapshots);
    const Diagnostics& d0 = sim.initial_diagnostics();
    h.initial_mass = d0.mass;
    for (int k = 0; k < 3; ++k) h.initial_momentum[k] = d0.momentum[k];
    h.checksum = state_checksum(sim);
    h.field_checksums = field_checksums(sim);
    h.run_wall_seconds = comm_.max(cost.first);
    h.run_cpu_seconds = cost.second;
    h.initial_particles = static_cast<std::int64_t>(initial_particles);
    h.rho0 = scene_.rho0;
    h.domain = {scene_.domain.min[0], scene_.domain.min[1], scene_.domain.min[2],
                scene_.domain.max[0], scene_.domain.max[1], scene_.domain.max[2]};
    sim.save_hooks(h);  // the impermeability guard's count, the open boundaries' state
    if (sim.refinement_on()) {
      h.refinement = refinement_state(sim);
      h.refinement.zones = refinement_zone_text(scene_);
    }
    write_checkpoint(path_, h, static_cast<std::int64_t>(sim.size()), state_rows(sim), comm_);
    sim.invalidate_neighbours();  // a restart from this file takes the same path from here
    last_ = Clock::now();
    const double took = std::chrono::duration<double>(last_ - c0).count();
    seconds_ += took;
    ++count_;
    if (progress_)
      std::fprintf(stderr, "  checkpoint: step %lld, t = %.6g s -> %s (%.2f s)\n", static_cast<long long>(sim.steps()), sim.time(),
                   path_.c_str(), took);
  }

  nlohmann::json summary() const { return {{"count", count_}, {"seconds", seconds_}, {"file", path_}}; }

 private:
  Scene scene_;
  std::string path_;
  Communicator comm_;
  bool progress_;
  Clock::time_point last_ = Clock::now();
  double seconds_ = 0;
  int count_ = 0;
};

// The simulation of a run: a new one, or the restart's, checked against the checksums
// stored with it. Throws CheckpointError for a restart file that cannot be used.
template <int D>
Simulation<D> start_simulation(const Scene& scene, const RunOptions& opt, const CheckpointSlice* restart) {
  auto make = [&]() {
    if (!restart) return Simulation<D>(scene, nullptr);
    try {
      return Simulation<D>(scene, restart);
    } catch (const CheckpointError&) {
      throw;
    } catch (const std::runtime_error& e) {  // the state read does not make a run (e.g. APR roles outside the zone table)
      throw CheckpointError(opt.restart + ": " + e.what());
    }
  };
  Simulation<D> sim = make();
  if (restart && state_checksum(sim) != restart->header.checksum)
    throw CheckpointError(opt.restart + ": the particle state does not match the checksum stored with it: the file is corrupted");
  if (restart && sim.refinement_on() && refinement_checksum(sim) != restart->header.refinement.checksum)
    throw CheckpointError(opt.restart + ": the APR fields (birth_level, level, guard, mother, parent_id) do not match the checksum "
                          "stored with them (refinement_checksum): the file is corrupted");
  if (restart && !restart->header.field_checksums.empty()) {
    // each field the case read from the file (one it does not need is not read)
    std::string bad;
    for (const auto& [label, sum] : field_checksums(sim)) {
      const auto stored = restart->header.field_checksums.find(label);
      if (stored != restart->header.field_checksums.end() && stored->second != sum) bad += (bad.empty() ? "" : ", ") + label;
    }
    if (!bad.empty())
      throw CheckpointError(opt.restart + ": the field " + bad + " does not match the checksum stored with it (checksum_" +
                            bad.substr(0, bad.find(',')) + "): the file is corrupted");
  }
  return sim;
}

// The checkpoint to restart from, checked against the case.
template <int D>
CheckpointSlice read_restart(const Scene& scene, const RunOptions& opt, const Communicator& comm) {
  CheckpointSlice restart = read_checkpoint(opt.restart, comm);
  const CheckpointHeader& h = restart.header;
  if (h.dimension != D || std::abs(h.dx - scene.dx) > 1e-12 * scene.dx)
    throw CheckpointError(opt.restart + ": written by a " + std::to_string(h.dimension) + "D run with dx = " + std::to_string(h.dx) +
                          " m; the case has dimension " + std::to_string(D) + " and dx = " + std::to_string(scene.dx) + " m");
  check_refinement_restart(scene, h, opt.restart);
  return restart;
}

// What the run loop measures besides the simulation: wall and loop time, pairs sampled.
struct RunTiming {
  Clock::time_point wall0 = Clock::now(), loop0 = Clock::now(), last_progress = Clock::now();
  std::clock_t cpu0 = std::clock();
  double loop_seconds = 0;
  std::int64_t pair_samples = 0;
  double pair_sum = 0;
  double wall_before = 0, cpu_before = 0;  // a restart's: what the run had cost when its checkpoint was written

  double wall() const { return seconds_since(wall0); }
  double cpu() const { return static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC; }
  // wall and CPU seconds since t = 0, over this process and those before a restart
  std::pair<double, double> cost() const { return {wall_before + wall(), cpu_before + cpu()}; }
};

// summary.json: the run's status, size, timing, parallel figures, scheme and error figures
template <int D>
nlohmann::json run_summary(const Scene& scene, const RunOptions& opt, const Simulation<D>& sim, const RunReport& report,
                           const RunTiming& timing, const CheckpointHeader* restarted, const Checkpointer<D>& checkpoints,
                           std::size_t snapshot_count) {
  const Communicator& comm = sim.comm();
  const double loop_seconds = timing.loop_seconds;
  const std::int64_t pair_samples = timing.pair_samples;
  const double pair_sum = timing.pair_sum;
  nlohmann::json j;
  j["case"] = scene.name;
  j["source"] = scene.source_file;
  j["status"] = report.status;
  if (!report.message.empty()) j["message"] = report.message;
  j["dimension"] = D;
  j["particles"] = report.particles;
  j["steps"] = report.steps;
  j["total_steps"] = report.total_steps;
  if (restarted) j["restarted_from"] = {{"file", opt.restart}, {"step", restarted->step}, {"time", restarted->time}};
  j["simulated_time"] = sim.time();
  j["wall_seconds"] = report.wall_seconds;
  j["cpu_seconds"] = report.cpu_seconds;
  // since t = 0, over this process and those before its restarts
  j["total_wall_seconds"] = report.total_wall_seconds;
  j["total_cpu_seconds"] = report.total_cpu_seconds;
  j["loop_seconds"] = loop_seconds;
  j["particle_steps_per_second"] = loop_seconds > 0 ? report.particles * static_cast<double>(report.steps) / loop_seconds : 0.0;
  j["mean_neighbours"] = pair_samples > 0 ? pair_sum / pair_samples / report.particles : 0.0;
  j["neighbour_list_builds"] = sim.domain().builds();
  j["backend"] = default_backend();
  j["threads"] = backend_threads();
  j["device"] = device_name();
  j["ranks"] = comm.size();
  j["parallel"] = {{"balance_tau", sim.domain().balance()},
                   {"rebalances", sim.domain().rebalances()},
                   {"migrated_particles", sim.domain().exchange().migrated()},
                   {"exchange_seconds_max", comm.max(sim.domain().exchange().seconds())},
                   {"exchange_share_of_loop", loop_seconds > 0 ? comm.max(sim.domain().exchange().seconds()) / loop_seconds : 0.0},
                   // the slowest rank's time in each, over the loop's (a rebalance's migration and halos count in both)
                   {"halo_share_of_loop", loop_seconds > 0 ? comm.max(sim.domain().exchange().halo_seconds()) / loop_seconds : 0.0},
                   {"migration_share_of_loop", loop_seconds > 0 ? comm.max(sim.domain().exchange().migration_seconds()) / loop_seconds : 0.0},
                   {"rebalance_share_of_loop", loop_seconds > 0 ? comm.max(sim.domain().rebalance_seconds()) / loop_seconds : 0.0}};
  j["checkpoints"] = checkpoints.summary();
  if (sim.refinement_on()) {
    const AdaptiveRefinement<D>& apr = sim.refinement();
    j["refinement"] = {{"levels", apr.levels()},
                       {"particles", global_size(sim)},
                       {"sph_particles", sph_particles(sim)},
                       {"guards", apr.guards()},
                       {"passive_guards", apr.passive()},
                       {"refined", apr.refined()},
                       {"deleted", apr.deleted()},
                       {"adopted", apr.adopted()},
                       {"orphans_deleted", apr.orphans_deleted()},
                       {"outflow_daughters", apr.outflow_daughters()},
                       {"local_time_stepping", scene.refinement_local_time_stepping}};
    // with local time stepping, the steps each level took since t = 0 (2^l per coarse step where it has particles)
    if (!sim.level_steps().empty()) j["refinement"]["level_steps"] = sim.level_steps();
    // the SPH particles of each level times the steps they took since t = 0
    std::vector<double> work;
    for (const double w : sim.level_particle_steps()) work.push_back(comm.sum(w));
    j["level_particle_steps"] = work;
  }
  if (const auto* open = sim.template find_hook<OpenBoundaryStep<D>>()) {
    // open boundaries: what crossed each plane (kg since t = 0) and the particles created and removed
    const OpenBoundaries<D>& ob = open->boundaries();
    nlohmann::json list = nlohmann::json::array();
    for (const OpenFlux& f : ob.fluxes())
      list.push_back({{"name", f.name}, {"mass_in", f.mass_in}, {"mass_out", f.mass_out}, {"mass_created", f.created}, {"mass_removed", f.removed}});
    j["open_boundaries"] = {{"boundaries", list},
                            {"particles_created", ob.created_count()},
                            {"particles_removed", ob.removed_count()},
                            {"next_id", sim.next_id()}};
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
                 {"morris_lattice_factor", sim.scheme().morris_factor},
                 // c of the shift x += -c R^2 grad C (2.109), with shifting
                 {"shifting_coefficient", scene.shifting ? nlohmann::json(sim.scheme().shift_coefficient) : nlohmann::json("-")},
                 {"consistent_laplacian", uses_consistent_laplacian(scene)},
                 {"flux", to_string(scene.flux)},
                 {"riemann_reconstruction", scene.flux == FluxScheme::Riemann ? (scene.riemann_muscl ? "muscl_minmod" : "none") : "-"},
                 {"riemann_dissipation", scene.flux == FluxScheme::Riemann ? (scene.riemann_low_dissipation ? "low" : "acoustic") : "-"},
                 {"delta_sph", scene.delta_sph},
                 {"delta_sph_form", scene.delta_sph > 0 ? (scene.delta_sph_hydrostatic ? "hydrostatic" : "renormalised") : "-"},
                 {"artificial_viscosity", scene.artificial_viscosity},
                 {"background_pressure", scene.background_pressure},
                 {"wall_velocity_reconstruction", scene.wall_velocity_reconstruction && !scene.walls.empty()},
                 {"wall_contact", scene.wall_contact && !scene.walls.empty()},
                 {"renormalised_continuity", scene.renormalised_continuity},
                 {"pair_list", scene.half_pair_list ? "half" : "full"},
                 {"time_integrator", to_string(scene.integrator)}};
  j["errors"] = report.errors;
  j["snapshots"] = snapshot_count;
  return j;
}

template <int D>
RunReport run(const Scene& scene, const RunOptions& opt) {
  RunTiming timing;
  const Communicator comm;
  const bool root = comm.rank() == 0;
  const bool restarting = !opt.restart.empty();
  CheckpointSlice restart;
  if (restarting) {
    restart = read_restart<D>(scene, opt, comm);
    timing.wall_before = restart.header.run_wall_seconds;
    timing.cpu_before = restart.header.run_cpu_seconds;
  }
  Simulation<D> sim = start_simulation<D>(scene, opt, restarting ? &restart : nullptr);
  if (restarting) check_restart_case(scene, restart.header, opt.restart, opt.out_dir);
  {
    std::error_code ec;  // rank 0 creates it; every rank stops when it could not
    if (root) std::filesystem::create_directories(opt.out_dir, ec);
    if (comm.sum(std::int64_t(ec ? 1 : 0)) > 0)
      throw std::runtime_error("cannot create the output folder " + opt.out_dir + " (--out)" + (root ? ": " + ec.message() : std::string()));
  }
  RunRecorder<D> recorder(scene, opt.out_dir, comm, sim);
  Checkpointer<D> checkpoints(scene, opt, comm);
  const double t_start = sim.time();
  const std::int64_t step_start = restarting ? restart.header.step : 0;
  if (restarting) recorder.resume(t_start, static_cast<std::size_t>(restart.header.snapshots));
  else recorder.start();

  RunReport report;
  // the particles at t = 0 (a restart's checkpoint records them; one written before it did: those at the restart)
  report.particles = restarting && restart.header.initial_particles > 0 ? static_cast<std::size_t>(restart.header.initial_particles)
                                                                          : static_cast<std::size_t>(global_size(sim));
  report.status = "completed";
  double last_dt = 0;
  if (!restarting && !recorder.record(sim, last_dt).finite) report.status = "diverged";
  timing.loop0 = timing.last_progress = Clock::now();
  int output_index = static_cast<int>(std::floor(sim.time() / scene.output_interval * (1 + 1e-12))) + 1;
  while (report.status == "completed" && sim.time() < scene.duration * (1 - 1e-12)) {
    const double next_output = std::min(scene.duration, output_index * scene.output_interval);
    try {
      // time.output_at: next_step: the step is shortened only to end the run on time
      last_dt = sim.step(scene.output_at_next_step ? scene.duration : next_output);
    } catch (const BlowUp& e) {
      // the particles hold the state at the start of the failed step: write it
      if (root) std::fprintf(stderr, "ondine: %s; the last good state (t = %g s) is the last snapshot\n", e.what(), sim.time());
      recorder.record_last_state(sim);
      report.message = e.what();
      report.status = "diverged";
      break;
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "ondine: step %lld: %s\n", static_cast<long long>(sim.steps()), e.what());
      report.message = e.what();
      report.status = "diverged";
      break;
    }
    if (sim.time() >= next_output * (1 - 1e-12)) {
      // a snapshot at every snapshot_every-th output instant and at the end; with output_at:
      // next_step a step may pass several instants: one output for them all, at its time
      bool snapshot = sim.time() >= scene.duration * (1 - 1e-12);
      do {
        snapshot = snapshot || output_index % scene.snapshot_every == 0;
        ++output_index;
      } while (output_index * scene.output_interval <= sim.time() * (1 + 1e-12));
      if (!recorder.record(sim, last_dt, snapshot).finite) {
        report.status = "diverged";
        break;
      }
      if (timing.pair_samples < 8) {
        timing.pair_sum += static_cast<double>(pair_count(sim));
        ++timing.pair_samples;
      }
    }
    const int sig = static_cast<int>(comm.max(static_cast<std::int64_t>(stop_signal.load())));
    if (sig >= 0 || (scene.max_steps > 0 && sim.steps() >= scene.max_steps)) {
      report.status = sig >= 0 ? "interrupted" : "max_steps";
      report.signal = sig >= 0 ? sig : 0;
      if (recorder.behind(sim)) recorder.record(sim, last_dt);
      break;
    }
    if (checkpoints.due(sim)) checkpoints.write(sim, recorder.snapshot_count(), timing.cost(), report.particles);
    if (root && opt.progress && seconds_since(timing.last_progress) >= opt.progress_interval) {
      timing.last_progress = Clock::now();
      const double el = seconds_since(timing.loop0);
      const double eta = el * (scene.duration - sim.time()) / std::max(sim.time() - t_start, 1e-300);
      std::fprintf(stderr, "  t = %.4g / %.4g s   step %lld   %.1f steps/s   dt %.3g s   ETA %s\n", sim.time(), scene.duration,
                   static_cast<long long>(sim.steps()), (sim.steps() - step_start) / el, last_dt, fmt_seconds(eta).c_str());
    }
  }
  const bool diverged = report.status == "diverged";
  if (!diverged) checkpoints.write(sim, recorder.snapshot_count(), timing.cost(), report.particles);
  timing.loop_seconds = seconds_since(timing.loop0);
  report.steps = sim.steps() - step_start;
  report.total_steps = sim.steps();
  report.simulated_time = sim.time();
  report.wall_seconds = timing.wall();
  report.cpu_seconds = timing.cpu();
  std::tie(report.total_wall_seconds, report.total_cpu_seconds) = timing.cost();
  recorder.add_figures(report.errors, sim, diverged);
  const nlohmann::json j = run_summary(scene, opt, sim, report, timing, restarting ? &restart.header : nullptr, checkpoints,
                                       recorder.snapshot_count());
  if (root) write_text_atomically(opt.out_dir + "/summary.json", j.dump(2) + "\n");
  return report;
}

}  // namespace

void request_stop(int signal) { stop_signal.store(signal); }

RunReport run_scene(const Scene& scene, const RunOptions& options) {
  return scene.dimension == 2 ? run<2>(scene, options) : run<3>(scene, options);
}

}  // namespace ondine
