#pragma once
// One HDF5 file written by all ranks together (parallel HDF5, MPI-IO driver):
// rank r writes rows [offset_r, offset_r + n_r) of every dataset, offsets by an
// exclusive scan of the row counts. On one rank the plain (sec2) driver is used.
// The file is created under a temporary name and renamed into place by commit();
// a file never committed (an exception, a kill) is never found under its name.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "parallel/Communicator.hpp"

namespace ondine {

class H5CollectiveFile {
 public:
  H5CollectiveFile(std::string path, const Communicator& comm, std::int64_t local_rows);
  ~H5CollectiveFile();
  H5CollectiveFile(const H5CollectiveFile&) = delete;
  H5CollectiveFile& operator=(const H5CollectiveFile&) = delete;

  std::int64_t global_rows() const { return global_; }
  // file attributes: every rank passes the same value
  void attribute(const char* name, double v);
  void attribute(const char* name, std::int64_t v);
  void attribute(const char* name, int v);
  void attribute(const char* name, std::uint64_t v);
  void attribute(const char* name, const std::string& v);
  void attribute(const char* name, const std::vector<double>& v);  // a 1-D array attribute
  // this rank's rows, row-major local_rows x components (components 1: a 1-D dataset)
  void dataset(const std::string& name, const std::vector<double>& rows, int components);
  void commit();

 private:
  std::string path_, tmp_;
  const Communicator& comm_;
  hid_t file_ = -1;
  std::int64_t local_, offset_, global_;
  bool committed_ = false;
};

// Reading one file by all ranks together: rank r reads its share [N r/p, N (r+1)/p)
// of the rows. Throws std::runtime_error naming the file and what is missing.
class H5CollectiveReader {
 public:
  H5CollectiveReader(std::string path, const Communicator& comm);
  ~H5CollectiveReader();
  H5CollectiveReader(const H5CollectiveReader&) = delete;
  H5CollectiveReader& operator=(const H5CollectiveReader&) = delete;

  bool has(const char* name) const;  // attribute or dataset
  double attribute_double(const char* name) const;
  std::int64_t attribute_int(const char* name) const;
  std::uint64_t attribute_u64(const char* name) const;
  std::string attribute_string(const char* name) const;
  std::vector<double> attribute_doubles(const char* name) const;  // a 1-D array attribute (a scalar: one value)
  // rows of a dataset: total count and component count
  void shape(const std::string& name, std::int64_t& rows, int& components) const;
  // rows [first, first + count) of a dataset, row-major
  std::vector<double> rows(const std::string& name, std::int64_t first, std::int64_t count) const;

 private:
  std::string path_;
  const Communicator& comm_;
  hid_t file_ = -1;
};

}  // namespace ondine
