#include "solver/measures/MeasuresImpl.hpp"

namespace ondine {
ONDINE_INSTANTIATE_MEASURES(2)
}  // namespace ondine
