#include "observers/ErrorNormsImpl.hpp"

namespace ondine {
template std::map<std::string, double> reference_errors(const Simulation<2>&);
}  // namespace ondine
