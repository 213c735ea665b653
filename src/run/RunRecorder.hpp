#pragma once
// What a run writes at each output instant: the snapshot (HDF5 + XDMF) and the rows of
// its time series (diagnostics.csv, probes.csv, walls.csv, front.csv, waves.csv), and the
// figures it keeps over the whole run (density range, kinetic energy, escapes, the
// dam-break front). A restarted run takes back the rows of the earlier run up to the
// restart time. Collective; rank 0 writes the text files.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/SnapshotWriter.hpp"
#include "reference/ForceCoefficients.hpp"
#include "reference/References.hpp"
#include "reference/SensorSeries.hpp"
#include "run/RunOutput.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
class RunRecorder {
 public:
  RunRecorder(const Scene& scene, const std::string& out_dir, const Communicator& comm, Simulation<D>& sim)
      : scene_(scene),
        snapshots_(out_dir, scene.name, comm),
        diag_(out_dir + "/diagnostics.csv", comm.rank() == 0),
        probes_(out_dir + "/probes.csv", comm.rank() == 0),
        walls_(out_dir + "/walls.csv", comm.rank() == 0),
        front_(out_dir + "/front.csv", comm.rank() == 0),
        waves_(out_dir + "/waves.csv", comm.rank() == 0) {
    waves_.text() << "time,step";
    for (const WaveGauge& g : scene.wave_gauges) waves_.text() << "," << g.name << ".elevation";
    waves_.text() << "\n";
    diag_.text() << "time,step,dt,mass,momentum_x,momentum_y" << (D == 3 ? ",momentum_z" : "")
                 << ",kinetic_energy,max_speed,rho_min,rho_max,outside_domain,balance";
    // open boundaries: the fluid region's mass, and per boundary the masses that crossed its
    // plane into and out of the fluid since t = 0 and the net flux into the fluid over the
    // interval since the previous row (kg/s; per metre of span in 2D)
    if (sim.open_on()) {
      diag_.text() << ",fluid_mass";
      for (const OpenFlux& f : sim.open_boundaries().fluxes())
        diag_.text() << "," << f.name << ".mass_in," << f.name << ".mass_out," << f.name << ".mass_flux";
      open_previous(sim);
    }
    diag_.text() << "\n";
    probes_.text() << "time,step";
    for (const Probe& p : scene.probes) {
      probes_.text() << "," << p.name << ".pressure," << p.name << ".density";
      for (int k = 0; k < D; ++k) probes_.text() << "," << p.name << ".u" << "xyz"[k];
    }
    probes_.text() << "\n";
    walls_.text() << "time,step";
    if (sim.has_walls())
      for (const WallForce& f : sim.wall_forces()) {
        for (const char* part : {"pressure", "viscous"})
          for (int k = 0; k < D; ++k) walls_.text() << "," << f.name << "." << part << "_f" << "xyz"[k];
        for (int k = D == 2 ? 2 : 0; k < 3; ++k) walls_.text() << "," << f.name << ".moment_" << "xyz"[k];
      }
    walls_.text() << "\n";
    front_.text().precision(8);
    front_.text() << "T,Z,Z_experiment\n";
  }

  // a new run: no snapshot of an earlier run with this name is left in the folder
  void start() { snapshots_.remove_from(0); }

  // a restart at t_start: the series of the earlier run up to it, and the figures over them
  void resume(double t_start, std::size_t snapshots) {
    snapshots_.resume(snapshots);
    if (diag_.resume(t_start))
      for (const auto& row : diag_.resumed_rows()) {
        const std::size_t c = 6 + (D == 3);  // kinetic_energy
        if (row.size() < c + 5) continue;
        max_ke_ = std::max(max_ke_, row[c]);
        max_rho_dev_ = std::max({max_rho_dev_, std::abs(row[c + 2] / scene_.rho0 - 1), std::abs(row[c + 3] / scene_.rho0 - 1)});
        max_outside_ = std::max(max_outside_, static_cast<std::int64_t>(row[c + 4]));
      }
    probes_.resume(t_start);
    waves_.resume(t_start);
    for (const auto& row : probes_.resumed_rows())  // the series a reference compares
      for (std::size_t k = 0; k < scene_.probes.size(); ++k)
        if (row.size() > 2 + k * (2 + D)) keep_sensor(scene_.probes[k].name, row[0], row[2 + k * (2 + D)]);
    for (const auto& row : waves_.resumed_rows())
      for (std::size_t k = 0; k < scene_.wave_gauges.size(); ++k)
        if (row.size() > 2 + k) keep_sensor(scene_.wave_gauges[k].name, row[0], row[2 + k]);
    walls_.resume(t_start);
    if (cylinder()) {
      // the body's force series: per wall D pressure, D viscous and the moment's components
      const int per_wall = 2 * D + (D == 2 ? 1 : 3);
      int w = 0;
      for (std::size_t k = 0; k < scene_.walls.size(); ++k)
        if (scene_.walls[k].name == scene_.reference.wall) w = static_cast<int>(k);
      const std::size_t c = 2 + static_cast<std::size_t>(w * per_wall);
      for (const auto& row : walls_.resumed_rows())
        if (row.size() >= c + 2 * D) body_force_.push_back({row[0], row[c] + row[c + D], row[c + 1] + row[c + D + 1]});
    }
    if (dam_break() && front_.resume(t_start * front_time_scale()))
      for (const auto& row : front_.resumed_rows())
        if (row.size() >= 2) front_points_.emplace_back(row[0], row[1]);
  }

  // One output instant: the snapshot and a row of every series. Returns the diagnostics
  // (d.finite false: the state is no longer finite).
  // snapshot false: the series only (time.snapshot_every > 1).
  Diagnostics record(Simulation<D>& sim, double last_dt, bool snapshot = true) {
    const OutputFrame<D> frame(sim);  // until the end of this call
    if (snapshot) snapshots_.write(sim.particles(), sim.time(), sim.steps(), static_cast<std::int64_t>(sim.size()));
    if (sim.has_walls()) {
      const auto forces = sim.wall_forces();
      walls_.text() << sim.time() << "," << sim.steps();
      for (const WallForce& f : forces) {
        if (cylinder() && f.name == scene_.reference.wall)
          body_force_.push_back({sim.time(), f.pressure[0] + f.viscous[0], f.pressure[1] + f.viscous[1]});
        for (int k = 0; k < D; ++k) walls_.text() << "," << f.pressure[k];
        for (int k = 0; k < D; ++k) walls_.text() << "," << f.viscous[k];
        for (int k = D == 2 ? 2 : 0; k < 3; ++k) walls_.text() << "," << f.moment[k];
      }
      walls_.text() << "\n";
      walls_.flush();
    }
    if (dam_break()) {
      const double a = scene_.reference.length;
      const double T = sim.time() * front_time_scale();
      const double Z = (sim.front_position() - scene_.reference.origin[0]) / a;
      front_points_.emplace_back(T, Z);
      front_.text() << T << "," << Z << "," << reference::interpolate(reference::martin_moyce_front(), T) << "\n";
      front_.flush();
    }
    const Diagnostics d = sim.diagnostics();
    diag_.text() << sim.time() << "," << sim.steps() << "," << last_dt << "," << d.mass;
    for (int k = 0; k < D; ++k) diag_.text() << "," << d.momentum[k];
    diag_.text() << "," << d.kinetic_energy << "," << d.max_speed << "," << d.rho_min << "," << d.rho_max << "," << d.outside_domain
                 << "," << sim.balance();
    if (sim.open_on()) {
      diag_.text() << "," << d.fluid_mass;
      const auto& fl = sim.open_boundaries().fluxes();
      const double span = sim.time() - open_t_;
      for (std::size_t b = 0; b < fl.size(); ++b) {
        const double net = (fl[b].mass_in - fl[b].mass_out) - (open_in_[b] - open_out_[b]);
        diag_.text() << "," << fl[b].mass_in << "," << fl[b].mass_out << "," << (span > 0 ? net / span : 0.0);
      }
      open_previous(sim);
    }
    diag_.text() << "\n";
    if (!scene_.probes.empty()) {
      const auto samples = sim.sample_probes();
      for (std::size_t k = 0; k < samples.size(); ++k) keep_sensor(scene_.probes[k].name, sim.time(), samples[k].pressure);
      probes_.text() << sim.time() << "," << sim.steps();
      for (const ProbeSample& s : samples) {
        probes_.text() << "," << s.pressure << "," << s.density;
        for (int k = 0; k < D; ++k) probes_.text() << "," << s.velocity[k];
      }
      probes_.text() << "\n";
      probes_.flush();
    }
    if (!scene_.wave_gauges.empty()) {
      const auto levels = sim.wave_elevations();
      for (std::size_t k = 0; k < levels.size(); ++k) keep_sensor(scene_.wave_gauges[k].name, sim.time(), levels[k]);
      waves_.text() << sim.time() << "," << sim.steps();
      for (double z : levels) waves_.text() << "," << z;
      waves_.text() << "\n";
      waves_.flush();
    }
    diag_.flush();
    // stability figures over the whole run (validation.md): density range, kinetic energy, escapes
    max_rho_dev_ = std::max({max_rho_dev_, std::abs(d.rho_max / scene_.rho0 - 1), std::abs(d.rho_min / scene_.rho0 - 1)});
    max_ke_ = std::max(max_ke_, d.kinetic_energy);
    max_outside_ = std::max(max_outside_, d.outside_domain);
    return d;
  }

  // after a blow-up: the last good state (the start of the failed step) as a snapshot
  void record_last_state(const Simulation<D>& sim) {
    snapshots_.write(sim.particles(), sim.time(), sim.steps(), static_cast<std::int64_t>(sim.size()));
  }
  // whether the last snapshot is older than the simulation's time
  bool behind(const Simulation<D>& sim) const {
    return snapshots_.entries().empty() || sim.time() > snapshots_.entries().back().time;
  }
  std::size_t snapshot_count() const { return snapshots_.entries().size(); }

  // the figures over the whole run into `errors`: max_density_deviation,
  // max_kinetic_energy_ratio (of 1/2 M u_ref^2), max_outside_domain, and with the Martin &
  // Moyce reference the front's errors
  void add_figures(std::map<std::string, double>& errors, double mass, bool diverged) const {
    const double ke_scale = 0.5 * mass * scene_.reference_velocity * scene_.reference_velocity;
    errors["max_density_deviation"] = max_rho_dev_;
    errors["max_kinetic_energy_ratio"] = ke_scale > 0 ? max_ke_ / ke_scale : 0.0;
    errors["max_outside_domain"] = static_cast<double>(max_outside_);
    errors["non_finite"] = diverged ? 1.0 : 0.0;
    if (dam_break() && !diverged)
      for (const auto& [k, v] : reference::martin_moyce_errors(front_points_)) errors[k] = v;
    if (cylinder() && !diverged) {
      std::vector<double> t, fx, fy;
      for (const auto& r : body_force_) {
        t.push_back(r[0]);
        fx.push_back(r[1]);
        fy.push_back(r[2]);
      }
      const double U = scene_.reference.velocity, Dm = scene_.reference.length;
      const auto c = reference::force_coefficients(t, fx, fy, Dm, U, scene_.rho0, scene_.reference.from);
      errors["cd_mean"] = c.cd_mean;
      errors["cl_amplitude"] = c.cl_amplitude;
      errors["strouhal"] = c.strouhal;
      errors["shedding_periods"] = c.periods;
      errors["cd_error"] = std::abs(c.cd_mean / reference::kCylinderRe100Cd - 1);
      if (c.periods > 0) {
        errors["strouhal_error"] = std::abs(c.strouhal / reference::kCylinderRe100St - 1);
        errors["cl_amplitude_error"] = std::abs(c.cl_amplitude / reference::kCylinderRe100ClAmplitude - 1);
      }
    }
    if (scene_.reference.kind == ReferenceKind::SphericTest2 && !diverged) {
      const auto measured = reference::read_sensor_csv(scene_.reference.file, {"P1", "P3", "H2", "H4"});
      for (const auto& [k, v] : reference::spheric_test2_errors(measured, sensors_, scene_.reference.length, scene_.duration))
        errors[k] = v;
    }
  }

 private:
  bool dam_break() const { return scene_.reference.kind == ReferenceKind::MartinMoyce; }
  bool cylinder() const { return scene_.reference.kind == ReferenceKind::Cylinder; }
  // the open boundaries' counters at the last row (for the flux over an interval)
  void open_previous(const Simulation<D>& sim) {
    open_t_ = sim.time();
    open_in_.clear();
    open_out_.clear();
    for (const OpenFlux& f : sim.open_boundaries().fluxes()) {
      open_in_.push_back(f.mass_in);
      open_out_.push_back(f.mass_out);
    }
  }
  // the series a reference compares (spheric_test2: P1, P3, H2, H4), kept in memory
  void keep_sensor(const std::string& name, double t, double v) {
    if (scene_.reference.kind != ReferenceKind::SphericTest2) return;
    if (name == "P1" || name == "P3" || name == "H2" || name == "H4") sensors_[name].emplace_back(t, v);
  }
  // T = t sqrt(2 g / a), Martin & Moyce's time
  double front_time_scale() const { return std::sqrt(2 * std::abs(scene_.gravity[1]) / scene_.reference.length); }

  Scene scene_;
  SnapshotWriter snapshots_;
  CsvSeries diag_, probes_, walls_, front_, waves_;
  std::vector<std::pair<double, double>> front_points_;  // (T, Z)
  std::map<std::string, reference::Series> sensors_;     // spheric_test2: (t, value) of its sensors
  double max_rho_dev_ = 0, max_ke_ = 0;
  std::int64_t max_outside_ = 0;
  std::vector<std::array<double, 3>> body_force_;  // cylinder: (t, F_x, F_y) of the body's wall
  double open_t_ = 0;
  std::vector<double> open_in_, open_out_;
};

}  // namespace ondine
