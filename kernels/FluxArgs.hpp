#pragma once
// Everything a flux pass may read, whatever its terms; the selected term pack
// takes what it needs (see src/solver/FluxDispatch.hpp).
#include "kernels/ConsistentLaplacian.hpp"
#include "kernels/NeighbourList.hpp"
#include "kernels/VelocityGradientSum.hpp"
#include "kernels/WallPressure.hpp"

namespace ondine {

template <int D>
struct FluxArgs {
  int first = 0;  // the pass covers particles [first, first + n) (one APR level; 0 otherwise)
  int n = 0;
  NeighbourList<D> list;
  PeriodicBox<D> box;
  double R = 0;
  Vec<D> body;
  field_view_t<field::Position, D> x;
  field_view_t<field::Velocity, D> u;
  field_view_t<field::Density, D> rho;
  field_view_t<field::Pressure, D> P;
  field_view_t<field::Mass, D> m;
  field_view_t<field::Acceleration, D> du;
  field_view_t<field::DensityRate, D> drho;
  field_view_t<field::DensityGradient, D> grad_rho;  // delta-SPH only
  double nu = 0;             // viscous terms
  LaplacianWeightView<D> laplacian_weights;  // consistent Morris only
  double delta_coeff = 0;    // delta c0 R
  double av_alpha_R_c0 = 0;  // artificial viscosity
  double P_min = 0;          // background pressure
  WallEos eos{1, 1, 1};      // Riemann-SPH: c(rho) (1.9)
  double riemann_eta = 0;    // Riemann-SPH: > 0 the low-dissipation pressure (kernels/terms/RiemannLeduc.hpp)
  VelocityGradientRows<D> grad_u;  // Riemann-SPH with MUSCL (with grad_rho)
  field_view_t<field::TransportCorrection, D> du0;  // scheme.transport: ale (u0 = u + du0)
  field_view_t<field::MassRate, D> dm;               // Vila's ALE form: dm/dt, written by the flux pass
};

template <int D>
using FluxFunction = void (*)(const FluxArgs<D>&);

}  // namespace ondine
