#include "solver/SimulationImpl.hpp"
namespace ondine {
template class Simulation<2>;
}
