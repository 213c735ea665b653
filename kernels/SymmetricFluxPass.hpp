#pragma once
// The pair loop on the half neighbour list (scheme.pair_list: half): each pair (i, j) of the
// level evaluated once, both particles updated from the same PairData through the terms'
// pair_both (each term's antisymmetry: grad_j W_ji = -grad_i W_ij); a partner outside the level
// (a halo) only from i's side, as FluxPass does. The scattered sums go through Kokkos'
// ScatterView: per-thread copies summed at the end on a host backend, atomics on a GPU (the
// backend's default). Same results as FluxPass to round-off; the order of the sums depends on
// the thread count.
#include <Kokkos_ScatterView.hpp>

#include <string>

#include "kernels/FluxPass.hpp"

namespace ondine {

// The scattered du/dt and drho/dt, kept between evaluations (sized to the particle views).
template <int D>
struct PairScatter {
  using Device = Kokkos::Device<ExecSpace, MemSpace>;
  using VectorScatter = Kokkos::Experimental::ScatterView<double* [D], Kokkos::LayoutLeft, Device>;
  // the layout of the fields it adds into (a scalar field's is the backend's default)
  using ScalarScatter = Kokkos::Experimental::ScatterView<double*, typename field_view_t<field::DensityRate, D>::array_layout, Device>;
  VectorScatter du;
  ScalarScatter drho;
  std::size_t n = 0;
  void ensure(std::size_t extent) {
    if (n == extent && du.is_allocated()) return;
    du = VectorScatter(field_view_t<field::Acceleration, D>("ondine::Flux::scatter_du", extent));
    drho = ScalarScatter(field_view_t<field::DensityRate, D>("ondine::Flux::scatter_drho", extent));
    n = extent;
  }
};

template <int D, class Kernel, class TermPack>
struct SymmetricFluxPass {
  FluxPass<D, Kernel, TermPack> f;  // the fields, kernel and terms of the full-list pass (its list unused)
  NeighbourList<D> half;
  PairScatter<D>* scatter;
  int first = 0, end = 0;

  struct Pairs {
    SymmetricFluxPass p;
    typename PairScatter<D>::VectorScatter du_s;
    typename PairScatter<D>::ScalarScatter drho_s;
    KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
      auto a_du = du_s.access();
      auto a_drho = drho_s.access();
      PairData<D> q;
      q.i = i;
      q.rho_i = p.f.rho(i);
      q.inv_rho_i = 1.0 / q.rho_i;
      q.omega_i = p.f.m(i) * q.inv_rho_i;
      q.P_i = p.f.P(i);
      q.u_i = load<D>(p.f.u, i);
      const Vec<D> xi = load<D>(p.f.x, i);
      FluxSum<D> si{Vec<D>::zero(), 0.0};
      for_each_neighbour_within<D>(p.half, p.f.box, p.f.x, i, xi, p.f.R2, [&](const int j, const Vec<D>& xij, const double r) {
        q.xij = xij;
        q.j = j;
        q.r = r;
        q.dWdr = p.f.W.derivative(r);
        q.gradW = (q.dWdr / r) * xij;
        q.rho_j = p.f.rho(j);
        q.inv_rho_j = 1.0 / q.rho_j;
        q.P_j = p.f.P(j);
        q.omega_j = p.f.m(j) * q.inv_rho_j;
        q.u_j = load<D>(p.f.u, j);
        FluxSum<D> sj{Vec<D>::zero(), 0.0};
        p.f.terms.pair_both(q, si, sj);
        if (j >= p.first && j < p.end) {  // a partner of the level: its side of the pair
          for (int k = 0; k < D; ++k) a_du(j, k) += sj.du[k];
          a_drho(j) += sj.drho;
        }
      });
      for (int k = 0; k < D; ++k) a_du(i, k) += si.du[k];
      a_drho(i) += si.drho;
    }
  };

  void run() const {
    const std::string label = "ondine::Flux[" + TermPack::names() + "]";
    const auto dv = f.du;
    const auto dr = f.drho;
    scatter->ensure(dv.extent(0));
    scatter->du.reset();
    scatter->drho.reset();
    Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecSpace>(first, end), Pairs{*this, scatter->du, scatter->drho});
    // du = g + the scattered sums, drho = the scattered sums, over the level (contribute_into adds)
    const Vec<D> g = f.body;
    Kokkos::parallel_for("ondine::Flux::body", Kokkos::RangePolicy<ExecSpace>(first, end), KOKKOS_LAMBDA(const int i) {
      for (int k = 0; k < D; ++k) dv(i, k) = g[k];
      dr(i) = 0.0;
    });
    scatter->du.contribute_into(dv);
    scatter->drho.contribute_into(dr);
  }
};

}  // namespace ondine
