#pragma once
// Host-side dispatch of the scene's runtime choices to compiled types: with_kernel calls
// f(kernel) with the smoothing kernel the scene chose, with_eos f(eos) with its equation
// of state. The flux's term pack is chosen once, in FluxDispatch.hpp.
#include "kernels/EquationOfState.hpp"
#include "kernels/SmoothingKernels.hpp"
#include "scene/Scene.hpp"

namespace ondine {

template <int D, class F>
decltype(auto) with_kernel(KernelType k, double R, F&& f) {
  switch (k) {
    case KernelType::QuarticSpline: return f(QuarticSpline<D>(R));
    case KernelType::CubicSpline: return f(CubicSpline<D>(R));
    case KernelType::WendlandC2: break;
  }
  return f(WendlandC2<D>(R));
}

template <int D, class F>
void with_eos(const Scene& s, F&& f) {
  if (s.eos == EosLaw::Tait) f(TaitEos{s.rho0, s.c0, s.tait_gamma, s.eos_background_pressure});
  else f(LinearEos{s.rho0, s.c0, s.eos_background_pressure});
}

}  // namespace ondine
