#pragma once
// The transport-velocity law of Oger et al. (thesis 2.112-2.115; with NFM walls 4.88-4.89):
// the particles move with u0_i = u_i + du_i, where
//   n^_i = (1/gamma_i) [ sum_P w0_j grad W(x_i - x_j, R_d) R + sum_S s_q W(x_i - x_q, R_d) n_q R ]   (2.114), (4.89)
//   du_i = -U_char n^_i                        if U_char |n^_i| < 0.25 |u_i|
//        = -0.25 |u_i| n^_i / |n^_i|           otherwise                                        (2.113)
// with R_d = 2 dx (the anisotropy measured very locally), w0_j = m_j / rho0, the particle's
// initial volume (robustness, thesis 2.6.2), U_char = Ma c0 and n = n_out. In Vila's form the
// masses change, and m_j / rho0 then weighs the heavier particles more, so the law also evens
// out the masses (quieter than the lattice volume dx^D in its place: docs/validation.md,
// "Design choices in the kernels, measured"). The wall sum is
// empty without walls and gamma_i is then 1. On a regular lattice n^ vanishes by symmetry, so
// u0 = u; the cap keeps the transport within 25 % of Lagrangian, and u0 -> u as R -> 0 (2.115).
//
// Free surface: n^ of a truncated support points into the fluid, so the law would push the
// surface particles out of it. A particle on the free surface (flag of 4.86-4.87, computed at the
// step's first stage) keeps only the tangential part of du, du - (du . n~) n~ with n~ its outward
// normal of (4.87) (walls included), as the shifting of kernels/ShiftingPass.hpp does: the surface
// moves with the fluid (kinematic condition) and the particles along it are still regularised.
// A particle below the surface with surface particles within R_d (the band the original law keeps
// Lagrangian, Fig. 2.5) keeps the part of du across the direction towards them, sum (x_s - x_i):
// its own n~ is noise there, its support being almost whole (not in the seed; measured in
// docs/validation.md, "Design choices in the kernels, measured").
//
// Truncated supports (not in the seed): in Vila's ALE form the mass flux of a pair moves with the
// mean transport velocity, so in a uniform state a particle's density changes at
// 2 rho_i du_i . g_i, g_i = sum_P w_j grad_i W_ij, which vanishes inside the fluid but not where
// the support is cut by a wall or the free surface (g_i ~ 1/R there, pointing into the fluid).
// So du_i loses its part along g_i, smoothly: du - (du . g) g / (|g|^2 + eps^2), eps = 0.1 / R,
// which leaves an interior particle (|g| R of a few hundredths) almost untouched and makes the
// correction tangential to walls and to the surface (before the surface projection above, which
// has the last word: g and n~ differ by some degrees on a disordered surface). Still water,
// bodies at rest and free flights stay exact; the price is in violent flows, where the
// wall-normal part of (4.89) is what keeps the particles off the walls, so
// scheme.ale.cut_supports: free keeps it (both measured in docs/validation.md, "Design choices
// in the kernels, measured").
#include "kernels/NeighbourLoops.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallSet.hpp"

namespace ondine {

template <int D, class Kernel, bool Walls = false, bool Surface = false>
struct OgerVelocityLaw {
  NeighbourList<D> list;
  PeriodicBox<D> box;
  Kernel W;            // radius R: the normal n~ of (4.87)
  Kernel W_d;          // radius R_d = 2 dx: the anisotropy vector (2.114)
  double R, R2, R_d2;  // R, R^2, R_d^2
  double rho0, u_char;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Mass, D> m;
  field_view_t<field::TransportCorrection, D> du0;  // du_i of (2.113), written
  WallPoints<D> wall;                               // read with Walls only
  CellList<D> wall_cells;
  field_view_t<field::ShepardGamma, D> gamma;       // read with Walls only
  field_view_t<field::FreeSurface, D> surface;      // read with Surface only
  double eps2;  // (0.1 / R)^2: below, the truncation vector g is interior noise
  bool project;  // scheme.ale.cut_supports: tangential (true) or free (false)

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<D> xi = load<D>(x, i);
    Vec<D> nhat = Vec<D>::zero();
    Mat<D> M = Mat<D>::zero();   // Surface: the NFM matrix (4.86), up to 1/gamma
    Vec<D> toward = Vec<D>::zero();  // Surface: sum of x_s - x_i over the surface particles s within R_d
    const bool on_surface = Surface && surface(i) > 0.5;
    Vec<D> g = Vec<D>::zero();   // sum_P w_j grad_i W_ij, the truncation vector
    for_each_neighbour_within<D>(list, box, x, i, xi, R2, [&](const int j, const Vec<D>& xij, const double r) {
      const double w = m(j) / rho(j);
      const Vec<D> gradW = (W.derivative(r) / r) * xij;
      g += w * gradW;
      if (r * r < R_d2) {
        nhat += (m(j) / rho0 * W_d.derivative(r) / r) * xij;
        if constexpr (Surface)
          if (surface(j) > 0.5) toward -= xij;
      }
      if constexpr (Surface) {
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) M.a[a][b] -= w * xij[a] * gradW[b];
      }
    });
    Vec<D> v = g;  // Surface: g + sum_S s_q n_q W_iq, the vector of (4.87)
    double inv_gamma = 1.0;
    if constexpr (Walls) {
      inv_gamma = 1.0 / gamma(i);
      for_each_point_within<D>(wall_cells, box, wall.x, xi, R2, [&](const int q, const Vec<D>& xiq, const double r) {
        const Vec<D> nq = load<D>(wall.n_out, q);
        if (r * r < R_d2) nhat += (wall.s(q) * W_d.value(r)) * nq;
        if constexpr (Surface) {
          const double sW = wall.s(q) * W.value(r);
          v += sW * nq;
          for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b) M.a[a][b] -= sW * xiq[a] * nq[b];
        }
      });
    }
    nhat *= inv_gamma * R;
    // (2.113): -U_char n^, capped at a quarter of the particle's speed
    const double speed = kmath::sqrt(norm2(load<D>(u, i)));
    const double len = kmath::sqrt(norm2(nhat));
    Vec<D> d = Vec<D>::zero();
    if (len > 0.0) d = u_char * len < 0.25 * speed ? (-u_char) * nhat : (-0.25 * speed / len) * nhat;
    // consistency at a truncated support: d - (d . g) g / (|g|^2 + eps^2), g = sum_P w_j grad_i W_ij
    if (project) d -= (dot(d, g) / (norm2(g) + eps2)) * g;
    if constexpr (Surface) {
      // on the surface: n~ = -B v / |B v| (4.87), B the inverse of the NFM matrix (gamma cancels);
      // below it: the direction towards the surface particles within R_d (the sign does not matter)
      Vec<D> n = toward;
      if (on_surface) {
        Mat<D> B;
        n = invert(M, B, 1e-12) ? B * v : v;
      }
      const double nl = kmath::sqrt(norm2(n));
      if (nl > 0.0) {
        n *= 1.0 / nl;
        d -= dot(d, n) * n;
      }
    }
    store<D>(du0, i, d);
  }
};

}  // namespace ondine
