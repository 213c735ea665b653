#pragma once
// Simulation<D>: one derivative evaluation (du/dt, drho/dt, P), the same passes for a
// uniform run (one level) and a run with refinement zones (each level with its radius,
// list and wall cells; the guards interpolated first, 5.24; with local time stepping one
// level at a time, eval_level_):
//   pressure from the EOS; P_min of the background pressure (2.105);
//   per level: the Shepard factor gamma of the walls (4.55), the density gradient (and the
//   consistent Laplacian's weights next to no-slip walls);
//   per level: the fluid flux (FluxDispatch: one compiled term pack), the wall flux
//   (WallFluxDispatch: the wall terms 4.22, 4.25, 4.85 folded by the generic wall loop),
//   the renormalised continuity (4.86).
// Included by SimulationImpl.hpp only.
#include "kernels/EquationOfState.hpp"
#include "kernels/apr/LevelSums.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/StepState.hpp"
#include "solver/hooks/Refinement.hpp"

namespace ondine {

template <int D>
void Simulation<D>::update_walls(double t) {
  if (walls_.moving()) {
    walls_.move_to(t);
    if (refinement_) refinement_->move_walls(t);
  }
}

// (2.105): P_min = max(0, -min_k P_k) over the owned particles of every rank
template <int D>
double background_pressure_min(const field_view_t<field::Pressure, D>& P, int n, const Communicator& comm) {
  double pmin = 0;
  Kokkos::parallel_reduce("ondine::BackgroundPressure::min", Kokkos::RangePolicy<ExecSpace>(0, n), apr::MinOf{P},
                          Kokkos::Min<double>(pmin));
  pmin = comm.min(pmin);
  return pmin < 0 ? -pmin : 0.0;
}

template <int D>
PassContext<D> Simulation<D>::context(const LevelSpan<D>& L) const {
  PassContext<D> c;
  c.first = L.first;
  c.end = L.active_end;
  c.R = L.R;
  c.dx = L.dx;
  c.list = L.list;
  if (scene_.half_pair_list) {
    c.half_list = L.half_list;
    c.scatter = &pair_scatter_;
  }
  c.cells = domain_.cells();
  c.wall_cells = L.wall_cells;
  c.box = domain_.box();
  c.wrap_box = domain_.local_box();
  auto take = [&](auto& view, auto tag) {
    if (p_.has(tag)) view = p_.get(tag);
  };
  take(c.x, field::Position{});
  take(c.u, field::Velocity{});
  take(c.rho, field::Density{});
  take(c.P, field::Pressure{});
  take(c.m, field::Mass{});
  take(c.grad_rho, field::DensityGradient{});
  take(c.grad_u.g0, field::VelocityGradientX{});
  take(c.grad_u.g1, field::VelocityGradientY{});
  take(c.grad_u.g2, field::VelocityGradientZ{});
  take(c.gamma, field::ShepardGamma{});
  take(c.du, field::Acceleration{});
  take(c.drho, field::DensityRate{});
  take(c.dm, field::MassRate{});
  take(c.free_surface, field::FreeSurface{});
  take(c.du0, field::TransportCorrection{});
  take(c.nu_T, field::EddyViscosity{});
  take(c.u_star, field::FrictionVelocity{});
  take(c.y_plus, field::YPlus{});
  take(c.k, field::TurbulentKineticEnergy{});
  take(c.eps, field::DissipationRate{});
  take(c.k_next, field::TurbulentKineticEnergyNext{});
  take(c.eps_next, field::DissipationRateNext{});
  take(c.id, field::GlobalId{});
  take(c.mean_u, field::MeanVelocity{});
  take(c.u_langevin, field::LangevinVelocity{});
  take(c.langevin_offset, field::LangevinOffset{});
  take(c.langevin_drift, field::LangevinDrift{});
  take(c.langevin_gradient.g0, field::LangevinGradientX{});
  take(c.langevin_gradient.g1, field::LangevinGradientY{});
  take(c.langevin_gradient.g2, field::LangevinGradientZ{});
  for (int k = 0; k < D; ++k) c.body[k] = scene_.gravity[k] + scene_.body_force[k];
  // the pair terms' coefficients at the level's radius; the lattice factor scales the plain
  // Morris term, the consistent one has its own weights
  c.nu_pair = scene_.viscous_term == ViscousTerm::Morris && !uses_consistent_laplacian(scene_) ? scene_.nu * scheme_.morris_factor : scene_.nu;
  c.delta_coeff = scene_.delta_sph * scene_.c0 * L.R;
  c.delta_hydrostatic = scene_.delta_sph_hydrostatic;
  for (int k = 0; k < D; ++k) c.rho_hydrostatic[k] = scene_.rho0 * scene_.gravity[k] / (scene_.c0 * scene_.c0);
  c.av_alpha_R_c0 = scene_.artificial_viscosity * L.R * scene_.c0;
  c.riemann_eta = scene_.riemann_low_dissipation ? 3.0 : 0.0;  // eta of Zhang et al. (2017)
  c.u_char = scene_.ale_mach * scene_.c0;
  c.ale_project = scene_.ale_tangential_cut;
  c.wall = L.wall;
  c.facets = walls_.facets();
  c.facet_cells = walls_.facet_cells();
  c.weights = laplacian_weights_;
  c.eos = WallEos{scene_.rho0, scene_.c0, scene_.eos == EosLaw::Tait ? scene_.tait_gamma : 1.0};  // (4.14)
  c.nu = scene_.nu;
  c.rho0 = scene_.rho0;
  c.morris_factor = scheme_.morris_factor;
  c.shift_coefficient = scheme_.shift_coefficient;
  if (scene_.turbulence.on()) {
    const Turbulence& tu = scene_.turbulence;
    c.mixing_length = MixingLength<D>{tu.model == TurbulenceModel::Smagorinsky ? tu.smagorinsky_constant * L.dx : tu.length, tu.axis,
                                      tu.kappa, tu.bed, tu.depth, tu.plane};
    c.k_eps = KEpsilonConstants{tu.c_mu, tu.c1, tu.c2, tu.sigma_k, tu.sigma_e, 1e-10 * tu.initial_k, 1e-10 * tu.initial_epsilon};
    c.langevin = LangevinConstants{tu.langevin_c1, tu.langevin_c2, tu.langevin_c0, tu.c_mu, tu.seed};
    c.langevin.averaged = tu.langevin_averaged;
    c.langevin.drift_mean_removed = tu.langevin_drift_mean_removed;
    c.langevin.solenoidal = tu.langevin_solenoidal;
    c.log_law = LogLaw::make(tu.kappa, scene_.nu, tu.smooth_constant, tu.wall_function == WallLaw::Rough ? tu.roughness : 0.0,
                             tu.rough_constant);
  }
  c.clearance = 0.5 * L.dx;
  c.velocity_muscl = scene_.wall_velocity_reconstruction;
  c.wall_contact = scene_.wall_contact;
  c.wall_shear = scene_.turbulence.wall_function != WallLaw::None ? WallShear::LogLaw
                 : scene_.turbulence.eddy_viscous()                ? WallShear::Eddy
                                                                  : WallShear::Molecular;
  if (refinement_) {
    c.zones = refinement_->apr().zones();
    take(c.birth, field::AprBirthLevel{});
    take(c.guard, field::AprGuard{});
    take(c.mother, field::AprMother{});
  }
  return c;
}

template <int D>
void Simulation<D>::evaluate(const bool later_stage) {
  ensure_neighbours();                 // with zones: lists only; roles change at a step start
  domain_.refresh_state_halos(p_);     // several ranks: this stage's halos (with zones: the guards' sources)
  if (p_.has(field::MassRate{})) domain_.refresh(p_, field::Mass{});  // Vila's ALE fluxes change the masses
  const int n = n_own_, n_all = static_cast<int>(p_.size());
  const bool walls = !walls_.empty();
  if (walls) update_walls(stage_time_);
  StepState<D> state(*this);
  if (refinement_) refinement_->interpolate_guards(state, eval_level_);  // guards from this stage's SPH particles (5.24)
  // next to no-slip walls: the consistent Laplacian's weights (grown with some slack)
  if (walls && uses_consistent_laplacian(scene_) && static_cast<int>(laplacian_weights_.extent(0)) < n)
    laplacian_weights_ = LaplacianWeightView<D>("ondine::NFM::laplacian_weights", n + n / 8 + 16);
  const auto rho = p_.get(field::Density{}), P = p_.get(field::Pressure{});
  with_eos<D>(scene_, [&](auto eos) { update_pressure<D>(eos, rho, P, n_all); });
  const double P_min = scene_.background_pressure ? background_pressure_min<D>(P, n, comm()) : 0.0;
  const auto x = p_.get(field::Position{});
  const auto gamma = walls ? p_.get(field::ShepardGamma{}) : field_view_t<field::ShepardGamma, D>();
  // the density gradient feeds delta-SPH, the MUSCL wall state (4.30) and Riemann-SPH's MUSCL
  // (2.78, with the velocity gradient); next to no-slip walls its pass also solves the
  // consistent Laplacian's weights
  const bool gradient = uses_density_gradient(scene_), velocity_gradient = uses_velocity_gradient(scene_);
  // scheme.density_gradient: step holds the first stage's gradient through the step (the owned
  // particles carry it through a migration; the halos are refreshed below all the same)
  const bool gradient_pass = gradient && !(later_stage && scene_.density_gradient_once_per_step);
  std::vector<LevelSpan<D>> levels = this->levels();
  if (eval_level_ >= 0) levels = {levels[eval_level_]};  // local time stepping: one level's step
  for (const LevelSpan<D>& L : levels) {
    if (L.active_end == L.first) continue;
    const auto range = Kokkos::RangePolicy<ExecSpace>(L.first, L.active_end);
    if (walls)
      Kokkos::parallel_for("ondine::NFM::shepard_gamma", range, ShepardGammaPass<D>{walls_.facets(), walls_.facet_cells(), L.R, domain_.box(), x, gamma});
    if (gradient_pass) scheme_.density_gradient(context(L));
  }
  // the hooks' point before the flux (scheme.transport: ale: the transport velocity, 2.113)
  for (auto& h : hooks_) h->before_flux(state, later_stage);
  // with zones the guards' density gradient came with their interpolation (GuardInterpolation.hpp)
  if (gradient) domain_.refresh(p_, field::DensityGradient{});
  if (velocity_gradient) {
    domain_.refresh(p_, field::VelocityGradientX{}, field::VelocityGradientY{});
    if constexpr (D == 3) domain_.refresh(p_, field::VelocityGradientZ{});
  }
  for (const LevelSpan<D>& L : levels) {
    if (L.active_end == L.first) continue;
    PassContext<D> c = context(L);
    c.P_min = P_min;
    scheme_.flux(c);
    if (walls) scheme_.wall_flux(c);
    // replaces the plain divergence of (4.23)/(4.25) by the renormalised one (kernels/RenormalisedContinuity.hpp)
    if (scene_.renormalised_continuity) scheme_.renormalised_continuity(c);
  }
  for (auto& h : hooks_) h->after_evaluation(state);
}

}  // namespace ondine
