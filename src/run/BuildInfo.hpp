#pragma once
#include <string>
#include <vector>

namespace ondine {
std::string ondine_version();
std::string kokkos_version();
std::vector<std::string> kokkos_backends();  // enabled execution spaces
std::string default_backend();
int backend_threads();
}  // namespace ondine
