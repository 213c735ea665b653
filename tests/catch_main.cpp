// One Catch2 main: MPI and Kokkos are initialised once; the session runs in an
// inner scope so every View dies before Kokkos::finalize.
// Listing the tests (CTest's discovery, run at build time) needs no device, so
// Kokkos is not initialised for it: a CUDA build compiles, and its tests are
// discovered, on a machine without a GPU.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <Kokkos_Core.hpp>
#include <mpi.h>

#include <cstring>

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  bool listing = false;
  for (int i = 1; i < argc; ++i)
    listing = listing || std::strncmp(argv[i], "--list", 6) == 0 || std::strcmp(argv[i], "-l") == 0 ||
              std::strcmp(argv[i], "-t") == 0;
  if (!listing) Kokkos::initialize(argc, argv);
  int rc = 0;
  {
    rc = Catch::Session().run(argc, argv);
  }
  if (!listing) Kokkos::finalize();
  MPI_Finalize();
  return rc;
}
