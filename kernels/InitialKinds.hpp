#pragma once
// The initial velocity and pressure a fluid block may start with (kernels/InitialFill.hpp;
// case-file keys fluid_blocks[].velocity and .pressure).
namespace ondine {

enum class InitialVelocity { Uniform, TaylorGreen };
enum class InitialPressure { Zero, Hydrostatic, TaylorGreen };

}  // namespace ondine
