// One Catch2 main: MPI and Kokkos are initialised once; the session runs in an
// inner scope so every View dies before Kokkos::finalize.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <Kokkos_Core.hpp>
#include <mpi.h>

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  Kokkos::initialize(argc, argv);
  int rc = 0;
  {
    rc = Catch::Session().run(argc, argv);
  }
  Kokkos::finalize();
  MPI_Finalize();
  return rc;
}
