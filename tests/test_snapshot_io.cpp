// HDF5 snapshot round trip and the XDMF index.
#include <catch2/catch.hpp>
#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/SnapshotWriter.hpp"

using namespace ondine;
namespace fs = std::filesystem;

TEST_CASE("Snapshots round-trip every allocated field exactly", "[unit][io]") {
  const fs::path dir = fs::temp_directory_path() / ("ondine_test_snapshot_io_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const int n = 37;
  ParticleSet<2> p(n);
  const auto x = p.allocate(field::Position{});
  const auto u = p.allocate(field::Velocity{});
  const auto rho = p.allocate(field::Density{});
  Kokkos::parallel_for(n, KOKKOS_LAMBDA(int i) {
    x(i, 0) = 0.1 * i;
    x(i, 1) = 1.0 / (i + 3);
    u(i, 0) = -i;
    u(i, 1) = 1e-300 * i;
    rho(i) = 1000.0 + 1.0 / 7.0 * i;
  });
  SnapshotWriter w(dir.string(), "rt");
  w.write(p, 0.25, 12);
  w.write(p, 0.5, 24);

  const SnapshotData d = read_snapshot((dir / "rt_000001.h5").string());
  CHECK(d.time == 0.5);
  CHECK(d.step == 24);
  CHECK(d.dimension == 2);
  CHECK(d.particles == static_cast<std::size_t>(n));
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
  auto hu = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), u);
  auto hr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), rho);
  int seen = 0;
  for (std::size_t f = 0; f < d.names.size(); ++f) {
    const auto& v = d.values[f];
    if (d.names[f] == "position" || d.names[f] == "velocity") {
      ++seen;
      REQUIRE(d.components[f] == 3);
      const auto& h = d.names[f] == "position" ? hx : hu;
      for (int i = 0; i < n; ++i) {
        CHECK(v[3 * i] == h(i, 0));
        CHECK(v[3 * i + 1] == h(i, 1));
        CHECK(v[3 * i + 2] == 0.0);
      }
    } else if (d.names[f] == "density") {
      ++seen;
      for (int i = 0; i < n; ++i) CHECK(v[i] == hr(i));
    }
  }
  CHECK(seen == 3);
  CHECK(d.names.size() == 3);  // nothing that was not allocated

  // no temporary left, and the index lists both snapshots with their times
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().extension() != ".tmp");
  std::ifstream in(w.index_path());
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string xmf = ss.str();
  CHECK(xmf.find("rt_000000.h5:/position") != std::string::npos);
  CHECK(xmf.find("rt_000001.h5:/density") != std::string::npos);
  CHECK(xmf.find("<Time Value=\"0.25\"/>") != std::string::npos);
  CHECK(xmf.find("CollectionType=\"Temporal\"") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("Reading a file that is not a snapshot fails with its name", "[unit][io]") {
  const fs::path f = fs::temp_directory_path() / ("ondine_not_a_snapshot_" + std::to_string(getpid()) + ".h5");
  std::ofstream(f) << "garbage";
  try {
    read_snapshot(f.string());
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(e.what(), Catch::Matchers::Contains(f.string()));
  }
  fs::remove(f);
}

TEST_CASE("Reading a snapshot without an attribute names it and leaves no HDF5 id open", "[unit][io]") {
  // an HDF5 file with the time but no step: the reader throws naming the file and the
  // attribute, and closes what it opened (the library's count of open ids is unchanged)
  const fs::path f = fs::temp_directory_path() / ("ondine_no_step_" + std::to_string(getpid()) + ".h5");
  {
    const hid_t file = H5Fcreate(f.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(file, "time", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
    const double t = 0.5;
    H5Awrite(a, H5T_NATIVE_DOUBLE, &t);
    H5Aclose(a);
    H5Sclose(space);
    H5Fclose(file);
  }
  const ssize_t open_before = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  try {
    read_snapshot(f.string());
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(e.what(), Catch::Matchers::Contains(f.string()) && Catch::Matchers::Contains("'step'"));
  }
  CHECK(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) == open_before);
  fs::remove(f);
}
