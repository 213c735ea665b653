// Instantiates the flux passes of the named schemes for D = 2, kernel CubicSpline.
#include "kernels/SmoothingKernels.hpp"
#include "solver/FluxDispatch.hpp"

namespace ondine {
template PassFunction<2> select_flux<2, CubicSpline<2>>(const Scene&);
}
