#pragma once
// What the generic wall loop (kernels/WallFluxPass.hpp) hands to each wall term: the
// particle i, one wall quadrature point q within R, and the sums the terms add to.
#include "kernels/Vec.hpp"

namespace ondine {

// particle i, read once per particle
template <int D>
struct WallParticle {
  int i;
  Vec<D> xi, ui;
  double rho_i, P_i;
  double c2, c_i;  // the sound speed of the EOS at rho_i, squared and not
  Vec<D> grad_rho;  // <grad rho>_i of the MUSCL state (4.30)
};

// wall point q seen from particle i
template <int D>
struct WallPoint {
  int q;
  Vec<D> xiq;  // x_i - x_q (minimum image)
  double Wq;   // s_q W(|x_iq|): the element length (2D) or area (3D) times the kernel
  Vec<D> n;    // n_out, out of the fluid
  Vec<D> uq;   // the wall's velocity at q
  double un;   // (u_f - u_q).n_out, u_f the fluid velocity at q (u_i, or its MUSCL state)
};

// the wall sums of particle i, divided by gamma_i at the end of the loop
template <int D>
struct WallSum {
  Vec<D> du;
  double drho;
};

// Compile-time composition of wall terms, as Terms<T...> is for the fluid pairs: a term
// the scene does not use is absent from the loop.
template <class... T>
struct WallTerms : T... {
  WallTerms() = default;
  explicit WallTerms(const T&... t) : T(t)... {}
  template <int D>
  KOKKOS_INLINE_FUNCTION void point(const WallParticle<D>& p, const WallPoint<D>& w, WallSum<D>& s) const {
    (T::point(p, w, s), ...);
  }
};

}  // namespace ondine
