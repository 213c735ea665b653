#pragma once
// The generic pair loop: for each particle i, over its neighbours j within R,
// builds PairData and applies the term pack; writes du/dt (with the body force)
// and drho/dt (and dm/dt with mass fluxes). Full neighbour list, one thread per particle, no atomics.
#include <string>

#include "kernels/NeighbourList.hpp"
#include "kernels/NeighbourLoops.hpp"
#include "kernels/Terms.hpp"

namespace ondine {

template <int D, class Kernel, class TermPack>
struct FluxPass {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;
  double R2;
  Vec<D> body;  // gravity + body force
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  TermPack terms;
  field_view_t<field::MassRate, D> dm = {};  // allocated with mass fluxes (Vila's ALE form) only

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    PairData<D> q;
    q.i = i;
    q.rho_i = rho(i);
    q.inv_rho_i = 1.0 / q.rho_i;
    q.P_i = P(i);
    q.u_i = load<D>(u, i);
    const Vec<D> xi = load<D>(x, i);
    FluxSum<D> s{Vec<D>::zero(), 0.0};
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      q.xij = xij;
      q.j = j;
      q.r = r;
      q.dWdr = W.derivative(q.r);
      q.gradW = (q.dWdr / q.r) * q.xij;
      q.rho_j = rho(j);
      q.P_j = P(j);
      q.omega_j = m(j) / q.rho_j;
      q.u_j = load<D>(u, j);
      terms.pair(q, s);
    });
    store<D>(du, i, s.du + body);
    drho(i) = s.drho;
    if (dm.data() != nullptr) dm(i) = s.dm;
  }

  // particles [first, end): the SPH particles of one APR level (contiguous); built from the
  // pass context by solver/FluxDispatch.hpp
  void run(int first, int end) const {
    const std::string label = "ondine::Flux[" + TermPack::names() + "]";
    Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecSpace>(first, end), *this);
  }
};

}  // namespace ondine
