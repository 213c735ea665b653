#include "io/Checkpoint.hpp"

#include "io/H5Collective.hpp"

namespace ondine {

void write_checkpoint(const std::string& path, const CheckpointHeader& h, std::int64_t local_rows,
                      const std::map<std::string, std::pair<std::vector<double>, int>>& fields, const Communicator& comm) {
  H5CollectiveFile f(path, comm, local_rows);
  f.attribute("format", std::string("ondine-checkpoint-1"));
  f.attribute("case", h.case_name);
  f.attribute("dimension", h.dimension);
  f.attribute("dx", h.dx);
  f.attribute("time", h.time);
  f.attribute("step", h.step);
  f.attribute("particles", f.global_rows());
  f.attribute("snapshots", h.snapshots);
  f.attribute("initial_mass", h.initial_mass);
  f.attribute("initial_momentum_x", h.initial_momentum[0]);
  f.attribute("initial_momentum_y", h.initial_momentum[1]);
  f.attribute("initial_momentum_z", h.initial_momentum[2]);
  f.attribute("checksum", h.checksum);
  for (const auto& [label, sum] : h.field_checksums) f.attribute(("checksum_" + label).c_str(), sum);
  f.attribute("wall_corrections", h.wall_corrections);
  f.attribute("langevin_impulse", std::vector<double>(h.langevin_impulse, h.langevin_impulse + 3));
  f.attribute("run_wall_seconds", h.run_wall_seconds);
  f.attribute("run_cpu_seconds", h.run_cpu_seconds);
  f.attribute("initial_particles", h.initial_particles);
  f.attribute("rho0", h.rho0);
  f.attribute("domain", h.domain);
  std::vector<std::string> names = checkpoint_fields();
  if (h.refinement.present) {
    const CheckpointRefinement& a = h.refinement;
    f.attribute("refinement_zones", a.zones);
    f.attribute("refinement_next_id", a.next_id);
    f.attribute("refinement_refined", a.refined);
    f.attribute("refinement_deleted", a.deleted);
    f.attribute("refinement_families_moved", a.families_moved);
    f.attribute("refinement_adopted", a.adopted);
    f.attribute("refinement_orphans_deleted", a.orphans_deleted);
    f.attribute("refinement_outflow_daughters", a.outflow_daughters);
    f.attribute("refinement_guard_shifts", a.guard_shifts);
    f.attribute("refinement_guards_limited", a.guards_limited);
    if (!a.level_steps.empty()) f.attribute("refinement_level_steps", a.level_steps);
    if (!a.level_particle_steps.empty()) f.attribute("refinement_level_particle_steps", a.level_particle_steps);
    f.attribute("refinement_momentum_change", std::vector<double>(a.momentum_change, a.momentum_change + 3));
    f.attribute("refinement_momentum_scale", a.momentum_scale);
    f.attribute("refinement_zone_offset", a.offset);
    f.attribute("refinement_zone_lo_at_update", a.lo_at_update);
    f.attribute("refinement_checksum", a.checksum);
    for (const std::string& name : checkpoint_refinement_fields()) names.push_back(name);
  }
  if (h.open.present) {
    f.attribute("open_next_id", h.open.next_id);
    f.attribute("open_state", h.open.state);
    names.push_back("open_role");
  }
  // k-epsilon's transported state and the Langevin model's path-averaged gradient
  // (solver/CheckpointFields.hpp), where the run has them
  for (const std::string& name : optional_checkpoint_fields())
    if (fields.count(name)) names.push_back(name);
  for (const std::string& name : names) {
    const auto it = fields.find(name);
    if (it == fields.end()) throw std::logic_error("write_checkpoint: field " + name + " not given");
    f.dataset(name, it->second.first, it->second.second);
  }
  f.attribute("complete", 1);  // last: a file with this attribute has every dataset
  f.commit();
}

CheckpointSlice read_checkpoint(const std::string& path, const Communicator& comm) {
  try {
    H5CollectiveReader r(path, comm);
    if (!r.has("format") || r.attribute_string("format") != "ondine-checkpoint-1")
      throw CheckpointError(path + ": not an Ondine checkpoint (attribute 'format' is not ondine-checkpoint-1)");
    if (!r.has("complete")) throw CheckpointError(path + ": incomplete checkpoint (written by a run that stopped mid-write)");
    CheckpointSlice s;
    CheckpointHeader& h = s.header;
    h.case_name = r.attribute_string("case");
    h.dimension = static_cast<int>(r.attribute_int("dimension"));
    h.dx = r.attribute_double("dx");
    h.time = r.attribute_double("time");
    h.step = r.attribute_int("step");
    h.particles = r.attribute_int("particles");
    h.snapshots = r.attribute_int("snapshots");
    h.initial_mass = r.attribute_double("initial_mass");
    h.initial_momentum[0] = r.attribute_double("initial_momentum_x");
    h.initial_momentum[1] = r.attribute_double("initial_momentum_y");
    h.initial_momentum[2] = r.attribute_double("initial_momentum_z");
    h.checksum = r.attribute_u64("checksum");
    // counters added after the format's first files: 0 when absent
    h.wall_corrections = r.has("wall_corrections") ? r.attribute_int("wall_corrections") : 0;
    if (r.has("langevin_impulse")) {
      const std::vector<double> v = r.attribute_doubles("langevin_impulse");
      for (std::size_t k = 0; k < 3 && k < v.size(); ++k) h.langevin_impulse[k] = v[k];
    }
    h.run_wall_seconds = r.has("run_wall_seconds") ? r.attribute_double("run_wall_seconds") : 0;
    h.run_cpu_seconds = r.has("run_cpu_seconds") ? r.attribute_double("run_cpu_seconds") : 0;
    h.initial_particles = r.has("initial_particles") ? r.attribute_int("initial_particles") : 0;
    h.rho0 = r.has("rho0") ? r.attribute_double("rho0") : 0;
    if (r.has("domain")) h.domain = r.attribute_doubles("domain");
    for (const std::string& label : optional_checkpoint_fields())
      if (r.has(("checksum_" + label).c_str())) h.field_checksums[label] = r.attribute_u64(("checksum_" + label).c_str());
    if (r.has("checksum_open_role")) h.field_checksums["open_role"] = r.attribute_u64("checksum_open_role");
    std::vector<std::string> names = checkpoint_fields();
    if (r.has("refinement_zones")) {
      // written by a run with refinement zones: its APR state and fields (all of them)
      CheckpointRefinement& a = h.refinement;
      a.present = true;
      a.zones = r.attribute_string("refinement_zones");
      a.next_id = r.attribute_int("refinement_next_id");
      a.refined = r.attribute_int("refinement_refined");
      a.deleted = r.attribute_int("refinement_deleted");
      a.families_moved = r.has("refinement_families_moved") ? r.attribute_int("refinement_families_moved") : 0;
      a.adopted = r.has("refinement_adopted") ? r.attribute_int("refinement_adopted") : 0;
      a.orphans_deleted = r.has("refinement_orphans_deleted") ? r.attribute_int("refinement_orphans_deleted") : 0;
      a.outflow_daughters = r.has("refinement_outflow_daughters") ? r.attribute_int("refinement_outflow_daughters") : 0;
      a.guard_shifts = r.has("refinement_guard_shifts") ? r.attribute_int("refinement_guard_shifts") : 0;
      a.guards_limited = r.has("refinement_guards_limited") ? r.attribute_int("refinement_guards_limited") : 0;
      if (r.has("refinement_level_steps")) a.level_steps = r.attribute_doubles("refinement_level_steps");
      if (r.has("refinement_level_particle_steps")) a.level_particle_steps = r.attribute_doubles("refinement_level_particle_steps");
      const std::vector<double> dp = r.attribute_doubles("refinement_momentum_change");
      if (dp.size() != 3) throw CheckpointError(path + ": attribute 'refinement_momentum_change' does not have 3 values");
      for (int k = 0; k < 3; ++k) a.momentum_change[k] = dp[k];
      a.momentum_scale = r.attribute_double("refinement_momentum_scale");
      a.offset = r.attribute_doubles("refinement_zone_offset");
      a.lo_at_update = r.attribute_doubles("refinement_zone_lo_at_update");
      if (a.offset.size() % 3 != 0 || a.lo_at_update.size() != a.offset.size())
        throw CheckpointError(path + ": attributes 'refinement_zone_offset' and 'refinement_zone_lo_at_update' do not hold 3 values per zone");
      a.checksum = r.attribute_u64("refinement_checksum");
      for (const std::string& name : checkpoint_refinement_fields()) {
        if (!r.has(name.c_str()))
          throw CheckpointError(path + ": dataset '" + name + "' is missing (the checkpoint of a run with refinement zones holds "
                                "birth_level, level, guard, mother and parent_id)");
        names.push_back(name);
      }
    }
    if (r.has("open_next_id")) {
      // written by a run with open boundaries
      h.open.present = true;
      h.open.next_id = r.attribute_int("open_next_id");
      h.open.state = r.attribute_doubles("open_state");
      if (!r.has("open_role")) throw CheckpointError(path + ": dataset 'open_role' is missing (the checkpoint of a run with open boundaries holds it)");
      names.push_back("open_role");
    }
    for (const std::string& name : optional_checkpoint_fields())  // written by a k-epsilon or Langevin run
      if (r.has(name.c_str())) names.push_back(name);
    const std::int64_t first = h.particles * comm.rank() / comm.size();
    s.rows = h.particles * (comm.rank() + 1) / comm.size() - first;
    for (const std::string& name : names) {
      std::int64_t rows = 0;
      int comps = 0;
      r.shape(name, rows, comps);
      const int expect = (name == "position" || name == "velocity" || name.rfind("langevin_gradient_", 0) == 0) ? h.dimension : 1;
      if (rows != h.particles || comps != expect)
        throw CheckpointError(path + ": dataset '" + name + "' has " + std::to_string(rows) + " x " + std::to_string(comps) +
                              " values, expected " + std::to_string(h.particles) + " x " + std::to_string(expect));
      s.fields[name] = r.rows(name, first, s.rows);
    }
    return s;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw CheckpointError(e.what());
  }
}

}  // namespace ondine
