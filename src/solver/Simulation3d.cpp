#include "solver/SimulationImpl.hpp"
namespace ondine {
template class Simulation<3>;
template class OutputFrame<3>;
template void update_free_surface<3>(Simulation<3>&, bool, int);
}
