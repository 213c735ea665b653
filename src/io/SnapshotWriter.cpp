#include "io/SnapshotWriter.hpp"

#include <hdf5.h>

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "io/AtomicFile.hpp"

namespace ondine {

namespace {

// Packs a field into a host row-major N x 3 (vectors) or N (scalars) double array;
// the transposition runs on the device.
template <int D, class V>
std::vector<double> to_host_rows(const V& v, int& comps) {
  const int n = static_cast<int>(v.extent(0));
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

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

void write_attribute(hid_t file, const char* name, hid_t type, const void* value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (attr < 0) throw std::runtime_error(std::string("HDF5: cannot create attribute ") + name);
  check(H5Awrite(attr, type, value), std::string("writing attribute ") + name);
  H5Aclose(attr);
  H5Sclose(space);
}

}  // namespace

SnapshotWriter::SnapshotWriter(std::string dir, std::string case_name) : dir_(std::move(dir)), name_(std::move(case_name)) {}

std::string SnapshotWriter::index_path() const { return dir_ + "/" + name_ + ".xmf"; }

template <int D>
void SnapshotWriter::write(const ParticleSet<D>& p, double time, std::int64_t step) {
  std::ostringstream fname;
  fname << name_ << "_" << std::setw(6) << std::setfill('0') << entries_.size() << ".h5";
  const std::string path = dir_ + "/" + fname.str();
  const std::string tmp = temporary_name(path);
  SnapshotEntry entry{fname.str(), time, step, p.size(), {}};

  const hid_t file = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("HDF5: cannot create " + tmp);
  try {
    write_attribute(file, "time", H5T_NATIVE_DOUBLE, &time);
    write_attribute(file, "step", H5T_NATIVE_INT64, &step);
    const int dim = D;
    write_attribute(file, "dimension", H5T_NATIVE_INT, &dim);
    p.for_each_allocated([&](auto tag, const auto& view) {
      int comps = 1;
      const std::vector<double> rows = to_host_rows<D>(view, comps);
      const hsize_t dims[2] = {static_cast<hsize_t>(p.size()), static_cast<hsize_t>(comps)};
      const hid_t space = H5Screate_simple(comps == 1 ? 1 : 2, dims, nullptr);
      const hid_t set = H5Dcreate2(file, decltype(tag)::label, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      if (set < 0) throw std::runtime_error(std::string("HDF5: cannot create dataset ") + decltype(tag)::label);
      if (!rows.empty()) check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data()), "writing a dataset");
      H5Dclose(set);
      H5Sclose(space);
      entry.fields.emplace_back(decltype(tag)::label, comps);
    });
  } catch (...) {
    H5Fclose(file);
    std::remove(tmp.c_str());
    throw;
  }
  check(H5Fclose(file), "closing " + tmp);
  commit_file(tmp, path);
  entries_.push_back(entry);
  write_index();
}

void SnapshotWriter::write_index() const {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << name_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  x << std::setprecision(17);
  for (const SnapshotEntry& e : entries_) {
    x << "   <Grid Name=\"particles\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << e.time << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.particles << "\"/>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n"
      << "     <DataItem Dimensions=\"" << e.particles << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << e.file << ":/position</DataItem>\n    </Geometry>\n";
    for (const auto& [name, comps] : e.fields) {
      if (name == "position") continue;
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << (comps == 3 ? "Vector" : "Scalar")
        << "\" Center=\"Node\">\n     <DataItem Dimensions=\"" << e.particles << (comps == 3 ? " 3" : "")
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << e.file << ":/" << name
        << "</DataItem>\n    </Attribute>\n";
    }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  write_text_atomically(index_path(), x.str());
}

SnapshotData read_snapshot(const std::string& path) {
  SnapshotData d;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error(path + ": not a readable HDF5 snapshot");
  auto read_attr = [&](const char* name, hid_t type, void* out) {
    const hid_t a = H5Aopen(file, name, H5P_DEFAULT);
    if (a < 0) throw std::runtime_error(path + ": missing attribute '" + name + "'");
    check(H5Aread(a, type, out), std::string("reading attribute ") + name);
    H5Aclose(a);
  };
  read_attr("time", H5T_NATIVE_DOUBLE, &d.time);
  read_attr("step", H5T_NATIVE_INT64, &d.step);
  read_attr("dimension", H5T_NATIVE_INT, &d.dimension);
  H5G_info_t info;
  check(H5Gget_info(file, &info), "listing " + path);
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    char name[256];
    H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof(name), H5P_DEFAULT);
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 1};
    const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
    std::vector<double> v(dims[0] * (rank == 2 ? dims[1] : 1));
    if (!v.empty()) check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), "reading " + std::string(name));
    d.names.emplace_back(name);
    d.components.push_back(rank == 2 ? static_cast<int>(dims[1]) : 1);
    d.particles = dims[0];
    d.values.push_back(std::move(v));
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(file);
  return d;
}

template void SnapshotWriter::write<2>(const ParticleSet<2>&, double, std::int64_t);
template void SnapshotWriter::write<3>(const ParticleSet<3>&, double, std::int64_t);

}  // namespace ondine
