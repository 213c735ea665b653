#include "io/H5Collective.hpp"
#include "io/H5Handle.hpp"

#include <cerrno>
#include <cstdio>
#include <stdexcept>

#include "io/AtomicFile.hpp"

namespace ondine {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

hid_t access_list(const Communicator& comm) {
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
#ifdef H5_HAVE_PARALLEL
  if (!comm.serial()) check(H5Pset_fapl_mpio(fapl, comm.comm(), MPI_INFO_NULL), "H5Pset_fapl_mpio");
#else
  if (!comm.serial()) throw std::runtime_error("HDF5 is not the parallel build: install libhdf5-openmpi-dev");
#endif
  return fapl;
}

hid_t transfer_list(const Communicator& comm) {
  const hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
#ifdef H5_HAVE_PARALLEL
  if (!comm.serial()) check(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio");
#else
  (void)comm;
#endif
  return dxpl;
}

// Rows [first, first + count) of a (rows x components) file dataspace, selected
// in place, and the memory dataspace that matches them (an empty selection on a
// rank with no rows: collective calls still need every rank).
struct RowSelection {
  hid_t mem;
  RowSelection(hid_t space, std::int64_t first, std::int64_t count, int components) {
    const hsize_t start[2] = {static_cast<hsize_t>(first), 0}, cnt[2] = {static_cast<hsize_t>(count), static_cast<hsize_t>(components)};
    check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, cnt, nullptr), "selecting rows");
    mem = H5Screate_simple(components == 1 ? 1 : 2, cnt, nullptr);
    if (count == 0) {
      H5Sselect_none(mem);
      H5Sselect_none(space);
    }
  }
  ~RowSelection() { H5Sclose(mem); }
  RowSelection(const RowSelection&) = delete;
  RowSelection& operator=(const RowSelection&) = delete;
};

// attribute `name` of `type` over `space` (taken over), from `value` (none for an empty one)
void write_attr(hid_t file, const std::string& path, const char* name, hid_t type, hid_t space_id, const void* value) {
  const H5Handle space(space_id, H5Sclose);
  errno = 0;
  const H5Handle attr(space.id < 0 ? -1 : H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (attr.id < 0 || (value && H5Awrite(attr, type, value) < 0)) {
    const int e = errno;
    throw std::runtime_error("cannot write " + path + " (HDF5 attribute " + name + ")" + system_reason(e));
  }
}

}  // namespace

H5CollectiveFile::H5CollectiveFile(std::string path, const Communicator& comm, std::int64_t local_rows)
    : path_(std::move(path)), tmp_(temporary_name(path_)), comm_(comm), local_(local_rows) {
  offset_ = comm.exclusive_scan(local_rows);
  global_ = comm.sum(local_rows);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become the messages below, with the system's reason
  const hid_t fapl = access_list(comm);
  errno = 0;
  file_ = H5Fcreate(tmp_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  const int e = errno;
  H5Pclose(fapl);
  if (file_ < 0) {
    if (comm_.rank() == 0) std::remove(tmp_.c_str());
    throw std::runtime_error("cannot write " + path_ + " (HDF5 cannot create " + tmp_ + ")" + system_reason(e));
  }
}

H5CollectiveFile::~H5CollectiveFile() {
  if (committed_) return;
  if (file_ >= 0) H5Fclose(file_);
  if (comm_.rank() == 0) std::remove(tmp_.c_str());
}

void H5CollectiveFile::attribute(const char* name, double v) { write_attr(file_, path_, name, H5T_NATIVE_DOUBLE, H5Screate(H5S_SCALAR), &v); }
void H5CollectiveFile::attribute(const char* name, std::int64_t v) { write_attr(file_, path_, name, H5T_NATIVE_INT64, H5Screate(H5S_SCALAR), &v); }
void H5CollectiveFile::attribute(const char* name, int v) { write_attr(file_, path_, name, H5T_NATIVE_INT, H5Screate(H5S_SCALAR), &v); }
void H5CollectiveFile::attribute(const char* name, std::uint64_t v) { write_attr(file_, path_, name, H5T_NATIVE_UINT64, H5Screate(H5S_SCALAR), &v); }
void H5CollectiveFile::attribute(const char* name, const std::string& v) {
  const H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (type.id < 0 || H5Tset_size(type, v.size() + 1) < 0)
    throw std::runtime_error("cannot write " + path_ + " (HDF5 string type of attribute " + name + ")");
  write_attr(file_, path_, name, type, H5Screate(H5S_SCALAR), v.c_str());
}

void H5CollectiveFile::attribute(const char* name, const std::vector<double>& v) {
  const hsize_t dims[1] = {static_cast<hsize_t>(v.size())};
  write_attr(file_, path_, name, H5T_NATIVE_DOUBLE, v.empty() ? H5Screate(H5S_NULL) : H5Screate_simple(1, dims, nullptr),
             v.empty() ? nullptr : v.data());
}

void H5CollectiveFile::dataset(const std::string& name, const std::vector<double>& rows, int components) {
  const hsize_t dims[2] = {static_cast<hsize_t>(global_), static_cast<hsize_t>(components)};
  const int rank = components == 1 ? 1 : 2;
  const H5Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  errno = 0;
  H5Handle set(space.id < 0 ? -1 : H5Dcreate2(file_, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  if (set.id < 0) {
    const int e = errno;
    throw std::runtime_error("cannot write " + path_ + " (HDF5 dataset " + name + ")" + system_reason(e));
  }
  herr_t st;
  {
    const RowSelection sel(space, offset_, local_, components);
    const H5Handle dxpl(transfer_list(comm_), H5Pclose);
    st = H5Dwrite(set, H5T_NATIVE_DOUBLE, sel.mem, space, dxpl, rows.empty() ? nullptr : rows.data());
  }
  // the data may reach the file only when the dataset is closed (a full disk fails here)
  const hid_t id = set.id;
  set.id = -1;
  if (H5Dclose(id) < 0) st = -1;
  const int e = errno;
  if (st < 0) throw std::runtime_error("cannot write " + path_ + " (HDF5 dataset " + name + ")" + system_reason(e));
}

void H5CollectiveFile::commit() {
  errno = 0;
  const herr_t st = H5Fclose(file_);
  const int e = errno;
  file_ = -1;  // closed or not, never closed again: the destructor removes the temporary
  if (st < 0) throw std::runtime_error("cannot write " + path_ + " (HDF5 closing " + tmp_ + ")" + system_reason(e));
  comm_.barrier();  // every rank's data is in the file
  if (comm_.rank() == 0) commit_file(tmp_, path_);
  comm_.barrier();  // the file is under its name for everyone
  committed_ = true;
}

H5CollectiveReader::H5CollectiveReader(std::string path, const Communicator& comm) : path_(std::move(path)), comm_(comm) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become the messages below
  const hid_t fapl = access_list(comm);
  file_ = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl);
  H5Pclose(fapl);
  if (file_ < 0) throw std::runtime_error(path_ + ": cannot be opened as an HDF5 file (missing, truncated or corrupted)");
}

H5CollectiveReader::~H5CollectiveReader() {
  if (file_ >= 0) H5Fclose(file_);
}

bool H5CollectiveReader::has(const char* name) const {
  return H5Aexists(file_, name) > 0 || H5Lexists(file_, name, H5P_DEFAULT) > 0;
}

namespace {
template <class T>
T read_attr(hid_t file, const std::string& path, const char* name, hid_t type) {
  const hid_t a = H5Aopen(file, name, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(path + ": attribute '" + name + "' is missing");
  T v{};
  const herr_t st = H5Aread(a, type, &v);
  H5Aclose(a);
  if (st < 0) throw std::runtime_error(path + ": attribute '" + name + "' cannot be read");
  return v;
}
}  // namespace

double H5CollectiveReader::attribute_double(const char* name) const { return read_attr<double>(file_, path_, name, H5T_NATIVE_DOUBLE); }
std::int64_t H5CollectiveReader::attribute_int(const char* name) const { return read_attr<std::int64_t>(file_, path_, name, H5T_NATIVE_INT64); }
std::uint64_t H5CollectiveReader::attribute_u64(const char* name) const { return read_attr<std::uint64_t>(file_, path_, name, H5T_NATIVE_UINT64); }
std::string H5CollectiveReader::attribute_string(const char* name) const {
  const hid_t a = H5Aopen(file_, name, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(path_ + ": attribute '" + name + "' is missing");
  const hid_t type = H5Aget_type(a);
  const std::size_t n = H5Tget_size(type);
  std::string v(n, '\0');
  const hid_t mem = H5Tcopy(H5T_C_S1);
  H5Tset_size(mem, n);
  const herr_t st = H5Aread(a, mem, &v[0]);
  H5Tclose(mem);
  H5Tclose(type);
  H5Aclose(a);
  if (st < 0) throw std::runtime_error(path_ + ": attribute '" + name + "' cannot be read");
  return v.substr(0, v.find('\0'));
}

std::vector<double> H5CollectiveReader::attribute_doubles(const char* name) const {
  const hid_t a = H5Aopen(file_, name, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(path_ + ": attribute '" + name + "' is missing");
  const hid_t space = H5Aget_space(a);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  std::vector<double> v(n > 0 ? static_cast<std::size_t>(n) : 0);
  const herr_t st = v.empty() ? 0 : H5Aread(a, H5T_NATIVE_DOUBLE, v.data());
  H5Aclose(a);
  if (n < 0 || st < 0) throw std::runtime_error(path_ + ": attribute '" + name + "' cannot be read");
  return v;
}

void H5CollectiveReader::shape(const std::string& name, std::int64_t& rows, int& components) const {
  const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw std::runtime_error(path_ + ": dataset '" + name + "' is missing");
  const hid_t space = H5Dget_space(set);
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  H5Dclose(set);
  if (rank < 1 || rank > 2) throw std::runtime_error(path_ + ": dataset '" + name + "' is not a table of rows");
  rows = static_cast<std::int64_t>(dims[0]);
  components = rank == 2 ? static_cast<int>(dims[1]) : 1;
}

std::vector<double> H5CollectiveReader::rows(const std::string& name, std::int64_t first, std::int64_t count) const {
  std::int64_t total = 0;
  int comps = 1;
  shape(name, total, comps);
  if (first < 0 || first + count > total) throw std::runtime_error(path_ + ": dataset '" + name + "' has fewer rows than expected");
  const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  std::vector<double> out(static_cast<std::size_t>(count) * comps);
  herr_t st;
  {
    const RowSelection sel(space, first, count, comps);
    const hid_t dxpl = transfer_list(comm_);
    st = H5Dread(set, H5T_NATIVE_DOUBLE, sel.mem, space, dxpl, out.empty() ? nullptr : out.data());
    H5Pclose(dxpl);
  }
  H5Sclose(space);
  H5Dclose(set);
  if (st < 0) throw std::runtime_error(path_ + ": dataset '" + name + "' cannot be read (truncated or corrupted file)");
  return out;
}

}  // namespace ondine
