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
  for (const std::string& name : checkpoint_fields()) {
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
    const std::int64_t first = h.particles * comm.rank() / comm.size();
    s.rows = h.particles * (comm.rank() + 1) / comm.size() - first;
    for (const std::string& name : checkpoint_fields()) {
      std::int64_t rows = 0;
      int comps = 0;
      r.shape(name, rows, comps);
      const int expect = (name == "position" || name == "velocity") ? h.dimension : 1;
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
