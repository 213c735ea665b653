#include "io/SnapshotWriter.hpp"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "io/AtomicFile.hpp"
#include "io/H5Collective.hpp"
#include "io/H5Handle.hpp"
#include "io/XdmfSeries.hpp"

namespace ondine {

namespace {

// Packs the first n values of a field into a host row-major n x 3 (vectors) or n
// (scalars) double array; the transposition runs on the device.
template <int D, class V>
std::vector<double> to_host_rows(const V& v, int n, int& comps) {
  if constexpr (V::rank == 1) {
    comps = 1;
    Kokkos::View<double*, MemSpace> packed("ondine::Snapshot::pack", n);
    Kokkos::parallel_for("ondine::Snapshot::pack", Kokkos::RangePolicy<ExecSpace>(0, n),
                         KOKKOS_LAMBDA(const int i) { packed(i) = static_cast<double>(v(i)); });
    std::vector<double> out(n);
    Kokkos::deep_copy(Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(out.data(), n), packed);
    return out;
  } else {
    comps = 3;
    Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace> packed("ondine::Snapshot::pack", n);
    Kokkos::parallel_for("ondine::Snapshot::pack", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < 3; ++k) packed(i, k) = k < D ? v(i, k) : 0.0;
    });
    std::vector<double> out(3 * static_cast<std::size_t>(n));
    Kokkos::deep_copy(Kokkos::View<double* [3], Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(out.data(), n), packed);
    return out;
  }
}

}  // namespace

SnapshotWriter::SnapshotWriter(std::string dir, std::string case_name, Communicator comm)
    : dir_(std::move(dir)), name_(std::move(case_name)), comm_(comm) {}

std::string SnapshotWriter::index_path() const { return dir_ + "/" + name_ + ".xmf"; }

std::string SnapshotWriter::file_name(std::size_t index) const {
  std::ostringstream fname;
  fname << name_ << "_" << std::setw(6) << std::setfill('0') << index << ".h5";
  return fname.str();
}

template <int D>
void SnapshotWriter::write(const ParticleSet<D>& p, double time, std::int64_t step, std::int64_t owned) {
  const std::string fname = file_name(entries_.size());
  const int n = static_cast<int>(owned < 0 ? static_cast<std::int64_t>(p.size()) : owned);
  H5CollectiveFile file(dir_ + "/" + fname, comm_, n);
  SnapshotEntry entry{fname, time, step, static_cast<std::size_t>(file.global_rows()), {}};
  file.attribute("time", time);
  file.attribute("step", step);
  file.attribute("dimension", D);
  p.for_each_allocated([&](auto tag, const auto& view) {
    if (!decltype(tag)::output) return;
    int comps = 1;
    const std::vector<double> rows = to_host_rows<D>(view, n, comps);
    file.dataset(decltype(tag)::label, rows, comps);
    entry.fields.emplace_back(decltype(tag)::label, comps);
  });
  file.commit();
  entries_.push_back(entry);
  if (comm_.rank() == 0) write_index();
}

void SnapshotWriter::remove_from(std::size_t first) const {
  if (comm_.rank() == 0) remove_numbered_files(dir_, name_ + "_", first);
  comm_.barrier();
}

void SnapshotWriter::resume(std::size_t count) {
  remove_from(count);
  entries_.clear();
  for (std::size_t k = 0; k < count; ++k) {
    const std::string fname = file_name(k);
    const SnapshotData d = read_snapshot(dir_ + "/" + fname, false);
    SnapshotEntry e{fname, d.time, d.step, d.particles, {}};
    for (std::size_t f = 0; f < d.names.size(); ++f) e.fields.emplace_back(d.names[f], d.components[f]);
    entries_.push_back(e);
  }
}

void SnapshotWriter::write_index() const {
  std::vector<XdmfPointSet> sets;
  for (const SnapshotEntry& e : entries_) sets.push_back({e.file, e.time, e.particles, e.fields});
  write_text_atomically(index_path(), xdmf_point_series(name_, "particles", sets));
}

SnapshotData read_snapshot(const std::string& path, bool with_values) {
  SnapshotData d;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become the messages below
  const H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file.id < 0) throw std::runtime_error(path + ": not a readable HDF5 snapshot");
  auto read_attr = [&](const char* name, hid_t type, void* out) {
    const H5Handle a(H5Aopen(file, name, H5P_DEFAULT), H5Aclose);
    if (a.id < 0) throw std::runtime_error(path + ": missing attribute '" + name + "'");
    if (H5Aread(a, type, out) < 0) throw std::runtime_error(path + ": attribute '" + name + "' cannot be read");
  };
  read_attr("time", H5T_NATIVE_DOUBLE, &d.time);
  read_attr("step", H5T_NATIVE_INT64, &d.step);
  read_attr("dimension", H5T_NATIVE_INT, &d.dimension);
  H5G_info_t info;
  if (H5Gget_info(file, &info) < 0) throw std::runtime_error(path + ": its datasets cannot be listed");
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    char name[256];
    if (H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof(name), H5P_DEFAULT) < 0)
      throw std::runtime_error(path + ": the name of dataset " + std::to_string(k) + " cannot be read");
    const H5Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
    if (set.id < 0) throw std::runtime_error(path + ": '" + name + "' is not a dataset");
    const H5Handle space(H5Dget_space(set), H5Sclose);
    hsize_t dims[2] = {0, 1};
    const int rank = space.id < 0 ? -1 : H5Sget_simple_extent_dims(space, dims, nullptr);
    if (rank < 1 || rank > 2) throw std::runtime_error(path + ": dataset '" + name + "' is not a table of rows");
    std::vector<double> v(with_values ? dims[0] * (rank == 2 ? dims[1] : 1) : 0);
    if (!v.empty() && H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      throw std::runtime_error(path + ": dataset '" + name + "' cannot be read (truncated or corrupted file)");
    d.names.emplace_back(name);
    d.components.push_back(rank == 2 ? static_cast<int>(dims[1]) : 1);
    d.particles = dims[0];
    d.values.push_back(std::move(v));
  }
  return d;
}

template void SnapshotWriter::write<2>(const ParticleSet<2>&, double, std::int64_t, std::int64_t);
template void SnapshotWriter::write<3>(const ParticleSet<3>&, double, std::int64_t, std::int64_t);

}  // namespace ondine
