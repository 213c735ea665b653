#pragma once
// Local time stepping by level (refinement.local_time_stepping; docs/apr.md): the SPH
// particles of the other levels, which a level's guards are interpolated from (5.24), at the
// time of that level's stage. A coarser level has already taken its step: its state is
// interpolated linearly in time between the step's start y0 (the integrator's stage storage)
// and its end y1 (LevelEnd*), y0 + theta (y1 - y0), positions by their minimum-image
// displacement. A finer level has not started: its velocity and density at the step's start
// (kept in LevelEnd*) are extrapolated by their rates there, u + s du/dt, rho + s drho/dt; its
// positions stay (the guards' shape functions are those of the step's start, and a position
// moved ahead by a coarse step would overrun the fine level's Verlet skin). Not in the seeds.
#include "kernels/Fields.hpp"
#include "kernels/PeriodicBox.hpp"

namespace ondine::apr {

// y1 <- y (the level's end state, kept) or y <- y1 (put back), over [first, end)
template <int D>
struct LevelEndCopy {
  field_view_t<field::Position, D> x, x1;
  field_view_t<field::Velocity, D> u, u1;
  field_view_t<field::Density, D> rho, rho1;
  bool keep;  // true: y1 <- y; false: y <- y1

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) {
      if (keep) {
        x1(i, k) = x(i, k);
        u1(i, k) = u(i, k);
      } else {
        x(i, k) = x1(i, k);
        u(i, k) = u1(i, k);
      }
    }
    if (keep) rho1(i) = rho(i);
    else rho(i) = rho1(i);
  }
  void run(int first, int end) const {
    Kokkos::parallel_for("ondine::APR::level_end_copy", Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

// y <- y0 + theta (y1 - y0) over [first, end)
template <int D>
struct LevelTimeInterpolation {
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x, x0, x1;
  field_view_t<field::Velocity, D> u, u0, u1;
  field_view_t<field::Density, D> rho, r0, r1;
  double theta;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> dx = box.delta(load<D>(x1, i), load<D>(x0, i));
    for (int k = 0; k < D; ++k) {
      x(i, k) = box.wrap(x0(i, k) + theta * dx[k], k);
      u(i, k) = u0(i, k) + theta * (u1(i, k) - u0(i, k));
    }
    rho(i) = r0(i) + theta * (r1(i) - r0(i));
  }
  void run(int first, int end) const {
    Kokkos::parallel_for("ondine::APR::level_time_interpolation", Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

// u <- u1 + s du/dt, rho <- rho1 + s drho/dt over [first, end)
template <int D>
struct LevelTimeExtrapolation {
  field_view_t<field::Velocity, D> u, u1;
  field_view_t<field::Density, D> rho, r1;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  double s;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) u(i, k) = u1(i, k) + s * du(i, k);
    rho(i) = r1(i) + s * drho(i);
  }
  void run(int first, int end) const {
    Kokkos::parallel_for("ondine::APR::level_time_extrapolation", Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

}  // namespace ondine::apr
