#include "solver/SimulationImpl.hpp"
namespace ondine {
template class Simulation<2>;
template class OutputFrame<2>;
template void update_free_surface<2>(Simulation<2>&, bool, int);
}
