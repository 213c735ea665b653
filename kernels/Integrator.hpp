#pragma once
// Explicit Runge-Kutta updates of the particle state (classical RK4 and the
// explicit midpoint predictor-corrector; driven by Simulation<D>::step).
// Positions are wrapped into the periodic box after every update.
#include "kernels/Fields.hpp"
#include "kernels/PeriodicBox.hpp"

namespace ondine {

// The fields an explicit Runge-Kutta update reads and writes: the state y, its
// derivatives k (du/dt, drho/dt, and u for dx/dt), the state y0 at the start of
// the step and the RK4 weighted sums (unused by the midpoint scheme). With the transport
// velocity of Oger et al. (scheme.transport: ale) the positions move with u0 = u + du0 (2.112);
// with Vila's ALE fluxes (2.86) the masses are part of the state.
template <int D>
struct RungeKuttaViews {
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  field_view_t<field::Position, D> x0, xa;
  field_view_t<field::Velocity, D> u0, ua;
  field_view_t<field::Density, D> r0, ra;
  field_view_t<field::TransportCorrection, D> du0 = {};  // allocated with scheme.transport: ale
  field_view_t<field::Mass, D> m = {}, m0 = {}, ma = {};  // allocated with Vila's mass fluxes
  field_view_t<field::MassRate, D> dm = {};
  bool transport = false, masses = false;

  // dx/dt: u, or u0 = u + du0 (2.112)
  KOKKOS_INLINE_FUNCTION double position_rate(const int i, const int k) const { return transport ? u(i, k) + du0(i, k) : u(i, k); }
};

// One stage: y = y0 + c_dt k, and, when accumulate is set, the RK4 weighted sum
// acc += w k (acc = w k on the first stage).
template <int D>
struct RungeKuttaStage {
  PeriodicBox<D> box;
  RungeKuttaViews<D> v;
  double c_dt, w;
  bool accumulate, first;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) {
      const double uk = v.position_rate(i, k);
      if (accumulate) {
        v.xa(i, k) = (first ? 0.0 : v.xa(i, k)) + w * uk;
        v.ua(i, k) = (first ? 0.0 : v.ua(i, k)) + w * v.du(i, k);
      }
      v.x(i, k) = box.wrap(v.x0(i, k) + c_dt * uk, k);
      v.u(i, k) = v.u0(i, k) + c_dt * v.du(i, k);
    }
    if (accumulate) v.ra(i) = (first ? 0.0 : v.ra(i)) + w * v.drho(i);
    v.rho(i) = v.r0(i) + c_dt * v.drho(i);
    if (v.masses) {
      if (accumulate) v.ma(i) = (first ? 0.0 : v.ma(i)) + w * v.dm(i);
      v.m(i) = v.m0(i) + c_dt * v.dm(i);
    }
  }

  void run(int n) const { run(0, n); }
  void run(int first, int end) const {
    Kokkos::parallel_for("ondine::Integrator::stage", Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

// Final classical RK4 update: y1 = y0 + dt (acc + k4/6), acc = (k1 + 2 k2 + 2 k3)/6.
template <int D>
struct RungeKutta4Final {
  PeriodicBox<D> box;
  RungeKuttaViews<D> v;
  double dt;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) {
      const double uk = v.position_rate(i, k);
      v.x(i, k) = box.wrap(v.x0(i, k) + dt * (v.xa(i, k) + uk / 6.0), k);
      v.u(i, k) = v.u0(i, k) + dt * (v.ua(i, k) + v.du(i, k) / 6.0);
    }
    v.rho(i) = v.r0(i) + dt * (v.ra(i) + v.drho(i) / 6.0);
    if (v.masses) v.m(i) = v.m0(i) + dt * (v.ma(i) + v.dm(i) / 6.0);
  }

  void run(int n) const { run(0, n); }
  void run(int first, int end) const {
    Kokkos::parallel_for("ondine::Integrator::rk4_final", Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

// A step's start over [first, end): y0 = y (the whole set's is a deep copy; with local time
// stepping each level starts its own steps).
template <int D>
struct RungeKuttaStart {
  RungeKuttaViews<D> v;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) {
      v.x0(i, k) = v.x(i, k);
      v.u0(i, k) = v.u(i, k);
    }
    v.r0(i) = v.rho(i);
    if (v.masses) v.m0(i) = v.m(i);
  }
  void run(int first, int end) const {
    Kokkos::parallel_for("ondine::Integrator::start", Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

// Initial relaxation of a scene that starts out of discrete equilibrium (time.damping;
// not in the seeds): u *= factor, once per step while t < damping time.
template <int D>
struct VelocityDamping {
  field_view_t<field::Velocity, D> u;
  double factor;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) u(i, k) *= factor;
  }
  void run(int n) const { Kokkos::parallel_for("ondine::Damping", Kokkos::RangePolicy<ExecSpace>(0, n), *this); }
};

}  // namespace ondine
