#include "run/BuildInfo.hpp"

#include <Kokkos_Core.hpp>
#ifdef KOKKOS_ENABLE_CUDA
#include <cuda_runtime.h>
#endif

namespace ondine {

std::string ondine_version() { return "0.1.0"; }

std::string kokkos_version() {
  const int v = KOKKOS_VERSION;
  return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." + std::to_string(v % 100);
}

std::vector<std::string> kokkos_backends() {
  std::vector<std::string> b;
#ifdef KOKKOS_ENABLE_SERIAL
  b.push_back("Serial");
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  b.push_back("OpenMP");
#endif
#ifdef KOKKOS_ENABLE_THREADS
  b.push_back("Threads");
#endif
#ifdef KOKKOS_ENABLE_CUDA
  b.push_back("Cuda");
#endif
#ifdef KOKKOS_ENABLE_HIP
  b.push_back("HIP");
#endif
  return b;
}

std::string default_backend() { return Kokkos::DefaultExecutionSpace::name(); }
int backend_threads() { return Kokkos::DefaultExecutionSpace().concurrency(); }

std::string device_name() {
#ifdef KOKKOS_ENABLE_CUDA
  int device = 0;
  cudaDeviceProp prop;
  if (cudaGetDevice(&device) == cudaSuccess && cudaGetDeviceProperties(&prop, device) == cudaSuccess) return prop.name;
#endif
  return "host";
}

}  // namespace ondine
