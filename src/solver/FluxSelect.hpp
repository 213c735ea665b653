#pragma once
// Declaration of the flux-pass selection (definitions: FluxDispatch.hpp,
// instantiated once per dimension and kernel in FluxDispatch_*.cpp).
#include "kernels/PassContext.hpp"
#include "scene/Scene.hpp"

namespace ondine {
template <int D, class Kernel>
PassFunction<D> select_flux(const Scene& s);
}
