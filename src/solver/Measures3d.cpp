#include "solver/measures/MeasuresImpl.hpp"

namespace ondine {
ONDINE_INSTANTIATE_MEASURES(3)
}  // namespace ondine
