// Instantiates the flux passes of the named schemes for D = 3, kernel CubicSpline.
#include "kernels/SmoothingKernels.hpp"
#include "solver/FluxDispatch.hpp"

namespace ondine {
template PassFunction<3> select_flux<3, CubicSpline<3>>(const Scene&);
}
