#pragma once
// Calls f(kernel) with the smoothing kernel the scene chose (host-side dispatch).
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

}  // namespace ondine
