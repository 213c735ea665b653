#pragma once
#include <string>
#include <vector>

namespace ondine {
std::string ondine_version();
std::string kokkos_version();
std::vector<std::string> kokkos_backends();  // enabled execution spaces
std::string default_backend();
int backend_threads();
// the GPU's name (CUDA build), else "host": what the run's times were measured on
std::string device_name();
}  // namespace ondine
