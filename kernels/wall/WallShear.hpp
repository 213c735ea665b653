#pragma once
namespace ondine {
// The shear stress the no-slip wall term applies (src/solver/WallFluxDispatch.hpp), which the
// walls' traction reports (kernels/WallForces.hpp): nu (4.85), nu + nu_T,i (kernels/wall/
// NoSlipViscosity.hpp, a turbulence model without wall function), the log law's u_*,i^2
// (kernels/wall/WallFunction.hpp).
enum class WallShear { Molecular, Eddy, LogLaw };
}  // namespace ondine
