#pragma once
// The passes of a compiled scheme (solver/Scheme.hpp), each a function template over the
// smoothing kernel K and the scene's options, and make_scheme, which picks them once.
// Included by SimulationImpl.hpp only.
#include "kernels/DensityGradientPass.hpp"
#include "kernels/FreeSurfacePass.hpp"
#include "kernels/MorrisLatticeFactor.hpp"
#include "kernels/OgerVelocityLaw.hpp"
#include "kernels/ProbeSum.hpp"
#include "kernels/RenormalisedContinuity.hpp"
#include "kernels/ShiftingPass.hpp"
#include "kernels/ShiftingStability.hpp"
#include "kernels/WallForces.hpp"
#include "solver/WallFluxDispatch.hpp"
#include "kernels/WaveGauge.hpp"
#include "kernels/apr/GuardSpacing.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "solver/FluxSelect.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/Scheme.hpp"
#include "solver/WallFluxDispatch.hpp"

namespace ondine {

namespace pass {

template <class Context>
auto range(const Context& c) {
  return Kokkos::RangePolicy<ExecSpace>(c.first, c.end);
}

// the density gradient; next to no-slip walls also the consistent Laplacian's weights
// (and with Riemann-SPH's MUSCL reconstruction the velocity gradient in the same loop)
template <int D, class K, bool Consistent, bool Velocity>
void density_gradient(const PassContext<D>& c) {
  const K W(c.R);
  if constexpr (Consistent)
    Kokkos::parallel_for(Velocity ? "ondine::DensityGradient+velocity+consistent_laplacian" : "ondine::DensityGradient+consistent_laplacian",
                         range(c),
                         DensityGradientPass<D, K, true, Velocity>{c.list, c.box, W, c.R * c.R, c.x, c.rho, c.m, c.grad_rho,
                                                                   {c.wall, c.wall_cells, 0.05 * c.R, c.morris_factor, c.gamma, c.weights},
                                                                   c.u, c.grad_u});
  else
    Kokkos::parallel_for(Velocity ? "ondine::DensityGradient+velocity" : "ondine::DensityGradient", range(c),
                         DensityGradientPass<D, K, false, Velocity>{c.list, c.box, W, c.R * c.R, c.x, c.rho, c.m, c.grad_rho, {}, c.u, c.grad_u});
}

// the continuity's renormalised divergence (kernels/RenormalisedContinuity.hpp)
template <int D, class K, bool Walls>
void renormalised_continuity(const PassContext<D>& c) {
  const K W(c.R);
  if constexpr (Walls)
    Kokkos::parallel_for("ondine::RenormalisedContinuity", range(c),
                         RenormalisedContinuity<D, K, true>{c.list, c.box, W, c.R * c.R, c.wall, c.wall_cells, c.x, c.u, c.rho, c.m,
                                                            c.gamma, c.drho});
  else
    Kokkos::parallel_for("ondine::RenormalisedContinuity", range(c),
                         RenormalisedContinuity<D, K, false>{c.list, c.box, W, c.R * c.R, {}, {}, c.x, c.u, c.rho, c.m, {}, c.drho});
}

// the free-surface flag (4.86)-(4.87)
template <int D, class K, bool Walls>
void free_surface(const PassContext<D>& c) {
  const K W(c.R);
  Kokkos::parallel_for("ondine::FreeSurface", range(c),
                       FreeSurfacePass<D, K, Walls>{c.list, c.box, W, c.R, c.R * c.R, c.wall, c.wall_cells, c.x, c.rho, c.m,
                                                    Walls ? c.gamma : field_view_t<field::ShepardGamma, D>(), c.free_surface});
}

// the transport-velocity correction of Oger et al. (kernels/OgerVelocityLaw.hpp), R_d = 2 dx
// (at most R); with a free surface possible its flags must be fresh, halos included
template <int D, class K, bool Walls>
void transport_velocity(const PassContext<D>& c) {
  const double R_d = c.R < 2.0 * c.dx ? c.R : 2.0 * c.dx;
  const K W(c.R), W_d(R_d);
  const auto gamma = Walls ? c.gamma : field_view_t<field::ShepardGamma, D>();
  const double eps2 = (0.1 / c.R) * (0.1 / c.R);
  auto launch = [&](auto pass) { Kokkos::parallel_for("ondine::TransportVelocity", range(c), pass); };
  if (c.free_surface.is_allocated())
    launch(OgerVelocityLaw<D, K, Walls, true>{c.list, c.box, W, W_d, c.R, c.R * c.R, R_d * R_d, c.rho0, c.u_char, c.x, c.u, c.rho, c.m,
                                              c.du0, c.wall, c.wall_cells, gamma, c.free_surface, eps2,
                                              c.ale_project});
  else
    launch(OgerVelocityLaw<D, K, Walls>{c.list, c.box, W, W_d, c.R, c.R * c.R, R_d * R_d, c.rho0, c.u_char, c.x, c.u, c.rho, c.m, c.du0,
                                        c.wall, c.wall_cells, gamma, {}, eps2, c.ale_project});
}

// the turbulence model's nu_T (V&I §4.1.1) and, with the log-law wall function (Walls), u_* and y+
// (kernels/turbulence/EddyViscosityPass.hpp)
template <int D, class K, bool Walls, bool KEps>
void eddy_viscosity(const PassContext<D>& c) {
  const K W(c.R);
  Kokkos::parallel_for(Walls ? "ondine::EddyViscosity+wall_function" : "ondine::EddyViscosity", range(c),
                       EddyViscosityPass<D, K, Walls, KEps>{c.list, c.box, W, c.R * c.R, c.x, c.u, c.rho, c.m, c.mixing_length, c.nu_T,
                                                            c.wall, c.wall_cells, c.log_law, 0.05 * c.R, c.u_star, c.y_plus, c.k,
                                                            c.eps, c.k_eps.c_mu});
}

// k-epsilon: k and epsilon advanced over c.k_eps.dt into the scratch fields (kernels/turbulence/KEpsilon.hpp)
template <int D, class K>
void k_epsilon_step(const PassContext<D>& c) {
  Kokkos::parallel_for("ondine::KEpsilon::step", range(c),
                       KEpsilonStep<D, K>{c.list, c.box, K(c.R), c.R * c.R, c.x, c.u, c.rho, c.m, c.k, c.eps, c.nu_T, c.nu, c.k_eps,
                                          c.k_next, c.eps_next});
}

// the Langevin model (kernels/turbulence/Langevin.hpp): the kernel-filtered means u~ into c.mean_u
// and the supports' centroid offsets into c.langevin_offset
template <int D, class K>
void langevin_mean(const PassContext<D>& c) {
  Kokkos::parallel_for("ondine::Langevin::mean", range(c), LangevinMean<D, K>{c.list, c.box, K(c.R), c.R * c.R, c.x, c.u, c.rho, c.m, c.mean_u,
                                                                                  c.langevin_offset});
}

// ... then, from the means' gradient, the velocity after the step's increment over c.langevin.dt
// into c.u_langevin, with nu_T, k and epsilon
template <int D, class K>
void langevin_step(const PassContext<D>& c) {
  Kokkos::parallel_for("ondine::Langevin::step", range(c),
                       LangevinStep<D, K>{c.list, c.box, K(c.R), c.R * c.R, c.x, c.u, c.rho, c.m, c.id, c.mixing_length, c.langevin,
                                          c.mean_u, c.langevin_offset, c.nu_T, c.k, c.eps, c.u_langevin,
                                          c.langevin_gradient, c.langevin_drift});
}

// ... and with drift_mean: removed the kernel mean of the deterministic increments taken from it
template <int D, class K>
void langevin_drift_mean(const PassContext<D>& c) {
  Kokkos::parallel_for("ondine::Langevin::drift_mean", range(c),
                       LangevinDriftMean<D, K>{c.list, c.box, K(c.R), c.R * c.R, c.x, c.rho, c.m, c.langevin_drift, c.u_langevin});
}

// max_i kappa_i of the no-slip wall term (4.85) (kernels/WallFluxPass.hpp)
template <int D, class K>
double wall_stiffness(const PassContext<D>& c) {
  double kmax = 0;
  Kokkos::parallel_reduce("ondine::TimeStep::wall_viscous", range(c),
                          WallViscousStiffness<D, K>{c.wall, c.wall_cells, K(c.R), c.R * c.R, c.nu, 0.05 * c.R, c.box, c.x, c.gamma},
                          Kokkos::Max<double>(kmax));
  return kmax;
}

// particle shifting (kernels/ShiftingPass.hpp); c.wrap_box wraps the shifted positions; with a
// free surface possible (c.free_surface allocated) its flags must be fresh, halos included
template <int D, class K, bool Walls>
void shifting(const PassContext<D>& c, const field_view_t<field::Position, D>& x_out, const field_view_t<field::Velocity, D>& u_out,
              const field_view_t<field::Density, D>& rho_out, double max_shift) {
  const K W(c.R);
  auto launch = [&](auto pass) { Kokkos::parallel_for("ondine::Shifting", range(c), pass); };
  if (c.free_surface.is_allocated())
    launch(ShiftingPass<D, K, Walls, true>{c.list, c.box, c.wrap_box, W, c.R * c.R, c.shift_coefficient * c.R * c.R, W.value(c.dx), max_shift, c.x, c.u,
                                           c.rho, c.m, x_out, u_out, rho_out, c.wall, c.wall_cells, c.free_surface});
  else
    launch(ShiftingPass<D, K, Walls>{c.list, c.box, c.wrap_box, W, c.R * c.R, c.shift_coefficient * c.R * c.R, W.value(c.dx), max_shift, c.x, c.u, c.rho,
                                     c.m, x_out, u_out, rho_out, c.wall, c.wall_cells, {}});
}

// Shepard sums at a point (2.40-2.41): at radius c.R, or with zones each SPH particle
// with its level's radius (apr::ProbeSum)
template <int D, class K, bool Levels>
double probe_sum(const PassContext<D>& c, const Vec<D>& xp, int what) {
  double acc = 0;
  const auto policy = Kokkos::RangePolicy<ExecSpace>(0, c.end);
  if constexpr (Levels) {
    apr::ProbeSum<D, K> f{c.zones, K(1.0), xp, c.x, c.u, c.rho, c.P, c.m, c.birth, c.guard, what};
    Kokkos::parallel_reduce("ondine::Probe", policy, f, acc);
  } else {
    const K W(c.R);
    auto reduce = [&](auto value) {
      Kokkos::parallel_reduce("ondine::Probe", policy, ProbeSum<D, K, decltype(value)>{c.box, W, xp, c.x, c.rho, c.m, value}, acc);
    };
    using Scalar = probe_value::Scalar<field_view_t<field::Density, D>>;
    using Component = probe_value::Component<field_view_t<field::Velocity, D>>;
    if (what == 0) reduce(probe_value::One{});
    else if (what == 1) reduce(Scalar{c.P});
    else if (what == 2) reduce(Scalar{c.rho});
    else reduce(Component{c.u, what - 3});
  }
  return acc;
}

// the Shepard sum at each wave-gauge sample point (kernels/WaveGauge.hpp)
template <int D, class K, bool Levels>
void gauge_sums(const PassContext<D>& c, const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& points,
                const Kokkos::View<double*, MemSpace>& sums) {
  const auto policy = Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(points.extent(0)));
  if constexpr (Levels)
    Kokkos::parallel_for("ondine::WaveGauge", policy,
                         GaugeShepardSum<D, K, true>{c.cells, c.box, K(1.0), c.R * c.R, c.end, c.x, c.rho, c.m, points, sums, c.zones,
                                                     c.birth, c.guard});
  else
    Kokkos::parallel_for("ondine::WaveGauge", policy,
                         GaugeShepardSum<D, K>{c.cells, c.box, K(c.R), c.R * c.R, c.end, c.x, c.rho, c.m, points, sums});
}

// the fluid's Shepard sums at the open boundaries' facet points (kernels/OpenBoundary.hpp)
template <int D, class K>
void open_samples(const PassContext<D>& c, const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& points,
                  const field_view_t<field::OpenRole, D>& role, const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& sums) {
  Kokkos::parallel_for("ondine::Open::facet_sample", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(points.extent(0))),
                       FacetSample<D, K>{c.cells, c.box, K(c.R), c.R * c.R, c.end, points, c.x, c.u, c.rho, c.P, c.m, role, sums});
}

// the traction of the fluid at each wall point (kernels/WallForces.hpp)
template <int D, class K, bool Levels>
void wall_traction(const PassContext<D>& c, const Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace>& traction) {
  const auto policy = Kokkos::RangePolicy<ExecSpace>(0, c.wall.count);
  // every particle the cell list can hold, halos included
  const int n = static_cast<int>(c.rho.extent(0));
  Kokkos::View<double*, MemSpace> c2(Kokkos::view_alloc(Kokkos::WithoutInitializing, "ondine::NFM::c2"), n);
  Kokkos::parallel_for("ondine::NFM::sound_speed", Kokkos::RangePolicy<ExecSpace>(0, n), ParticleSoundSpeed2<D>{c.eos, c.rho, c2});
  const Kokkos::View<double*, MemSpace> contact =
      (c.wall_contact && !c.wall_state_only) ? wall_contact<D, K>(c) : Kokkos::View<double*, MemSpace>();
  if constexpr (Levels) {
    WallTraction<D, K, true> pass{c.wall, c.cells, K(1.0), c.R * c.R, c.nu, c.rho0, 0.05 * c.R, c.box, c.x, c.u,
                                  c.rho, c.P, c.m, c.grad_rho, traction, c.zones, c.birth, c.guard, c.velocity_muscl, c2,
                                  c.wall_state_only, c.grad_u};
    pass.contact = contact;
    pass.shear = c.wall_shear;
    pass.nu_T = c.nu_T;
    pass.u_star = c.u_star;
    Kokkos::parallel_for("ondine::NFM::wall_traction", policy, pass);
  } else {
    WallTraction<D, K> pass{c.wall, c.cells, K(c.R), c.R * c.R, c.nu, c.rho0, 0.05 * c.R, c.box, c.x, c.u, c.rho,
                            c.P, c.m, c.grad_rho, traction, {}, {}, {}, c.velocity_muscl, c2, c.wall_state_only, c.grad_u};
    pass.contact = contact;
    pass.shear = c.wall_shear;
    pass.nu_T = c.nu_T;
    pass.u_star = c.u_star;
    Kokkos::parallel_for("ondine::NFM::wall_traction", policy, pass);
  }
}

// the guard spacing shifts of one level's guards (kernels/apr/GuardSpacing.hpp)
template <int D, class K, bool Walls>
long guard_spacing(const PassContext<D>& c, const Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace>& shift, bool daughters,
                   bool mothers) {
  long moved = 0;
  Kokkos::parallel_reduce("ondine::APR::GuardSpacing", range(c),
                          apr::GuardSpacing<D, K, Walls>{c.cells, c.box, c.zones, K(1.0), c.R, c.dx, NearFacets<D>{c.facets, c.facet_cells}, c.wall, c.wall_cells,
                                                         c.x, c.rho, c.m, c.birth, c.mother,
                                                         Walls ? c.gamma : field_view_t<field::ShepardGamma, D>(), shift, daughters,
                                                         mothers},
                          moved);
  return moved;
}

template <int D, class K>
CompiledScheme<D> compile(const Scene& s) {
  const bool walls = !s.walls.empty(), levels = !s.refinement_zones.empty();
  CompiledScheme<D> c;
  c.flux = select_flux<D, K>(s);
  if (walls) c.wall_flux = select_wall_flux<D, K>(s);
  const bool consistent = walls && uses_consistent_laplacian(s), velocity = uses_velocity_gradient(s);
  if (consistent) c.density_gradient = velocity ? &density_gradient<D, K, true, true> : &density_gradient<D, K, true, false>;
  else c.density_gradient = velocity ? &density_gradient<D, K, false, true> : &density_gradient<D, K, false, false>;
  c.renormalised_continuity = walls ? &renormalised_continuity<D, K, true> : &renormalised_continuity<D, K, false>;
  c.free_surface = walls ? &free_surface<D, K, true> : &free_surface<D, K, false>;
  c.wall_stiffness = &wall_stiffness<D, K>;
  if (s.turbulence.on()) {
    const bool law = walls && s.turbulence.wall_function != WallLaw::None, keps = s.turbulence.model == TurbulenceModel::KEpsilon;
    c.eddy_viscosity = law ? (keps ? &eddy_viscosity<D, K, true, true> : &eddy_viscosity<D, K, true, false>)
                           : (keps ? &eddy_viscosity<D, K, false, true> : &eddy_viscosity<D, K, false, false>);
    if (keps) c.k_epsilon_step = &k_epsilon_step<D, K>;
    if (s.turbulence.model == TurbulenceModel::Langevin) {
      c.langevin_mean = &langevin_mean<D, K>;
      c.langevin_step = &langevin_step<D, K>;
      c.langevin_drift_mean = &langevin_drift_mean<D, K>;
    }
  }
  if (s.ale) c.transport_velocity = walls ? &transport_velocity<D, K, true> : &transport_velocity<D, K, false>;
  c.shifting = walls ? &shifting<D, K, true> : &shifting<D, K, false>;
  c.probe_sum = levels ? &probe_sum<D, K, true> : &probe_sum<D, K, false>;
  c.gauge_sums = levels ? &gauge_sums<D, K, true> : &gauge_sums<D, K, false>;
  if (!s.open_boundaries.empty()) c.open_samples = &open_samples<D, K>;
  c.wall_traction = levels ? &wall_traction<D, K, true> : &wall_traction<D, K, false>;
  c.guard_spacing = walls ? &guard_spacing<D, K, true> : &guard_spacing<D, K, false>;
  if (s.viscous_term == ViscousTerm::Morris) c.morris_factor = morris_lattice_factor<D>(K(s.R()), s.R(), s.dx);
  // the same at every level (R / dx is)
  if (s.shifting) c.shift_coefficient = s.shifting_coefficient_stable ? 1.0 / shifting_mode_rate<D>(K(s.R()), s.R(), s.dx) : s.shifting_coefficient;
  return c;
}

}  // namespace pass

template <int D>
CompiledScheme<D> make_scheme(const Scene& scene) {
  return with_kernel<D>(scene.kernel, scene.R(), [&](auto W) { return pass::compile<D, decltype(W)>(scene); });
}

}  // namespace ondine
