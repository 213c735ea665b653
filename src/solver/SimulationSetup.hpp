#pragma once
// Simulation<D>: the set-up of a run (the lattice fill, the fluid region of the walls, a
// checkpoint's state) and the state rows and checksums a checkpoint carries. Included by
// SimulationImpl.hpp only.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/CaseFile.hpp"
#include "solver/KernelDispatch.hpp"
#include "solver/FluidRegionBuild.hpp"
#include "solver/InitialState.hpp"
#include "solver/SchemePasses.hpp"
#include "solver/StepState.hpp"
#include "solver/hooks/StepHooks.hpp"

namespace ondine {

template <int D>
Simulation<D>::Simulation(const Scene& scene, const CheckpointSlice* restart) : scene_(scene) {
  if (scene.dimension != D) throw std::logic_error("Simulation<D>: scene dimension mismatch");
  R_ = scene.R();
  scheme_ = make_scheme<D>(scene);
  // with refinement zones the skin and the wall quadrature follow the finest spacing
  const bool apr_on = !scene.refinement_zones.empty();
  const double dx_finest = scene.dx / std::ldexp(1.0, scene.max_refinement_level());
  skin_len_ = scene.neighbour_skin * (apr_on ? dx_finest : scene.dx);
  // the wall quadrature's spacing; with zones in 2D every level's walls at the finest level's
  // dx / 4 (3D: each level at its own spacing, hooks/Refinement.hpp)
  wall_spacing_ = wall_quadrature_spacing<D>(scene, apr_on && D == 2 ? dx_finest : scene.dx);
  // with local time stepping each level has its own skin, neighbour_skin dx_l: a level-l particle
  // moves 2^l times as far in a coarse step as a finest one (the cells hold R + the coarse skin)
  const bool level_skins = apr_on && scene.refinement_local_time_stepping;
  domain_ = Domain<D>(scene_, R_ + (level_skins ? scene.neighbour_skin * scene.dx : skin_len_), skin_len_);
  if (level_skins) {
    std::vector<double> skins;
    for (int l = 0; l <= scene.max_refinement_level(); ++l) skins.push_back(scene.neighbour_skin * scene.dx / std::ldexp(1.0, l));
    domain_.set_level_skins(skins);
  }
  // this rank's share of the lattice or of the checkpoint; migrate() then sends
  // every particle to the owner of its cell
  const std::int64_t lattice = count_particles(scene);
  lattice_first_ = lattice * comm().rank() / comm().size();
  const std::int64_t lattice_end = lattice * (comm().rank() + 1) / comm().size();
  p_ = ParticleSet<D>(restart ? static_cast<std::size_t>(restart->rows) : static_cast<std::size_t>(lattice_end - lattice_first_));
  p_.allocate(field::Position{});
  p_.allocate(field::Velocity{});
  p_.allocate(field::Density{});
  p_.allocate(field::Pressure{});
  p_.allocate(field::Mass{});
  p_.allocate(field::GlobalId{});
  p_.allocate(field::Acceleration{});
  p_.allocate(field::DensityRate{});
  const bool walls = !scene.walls.empty();
  // the density gradient feeds delta-SPH, the MUSCL wall state (4.30) and Riemann-SPH's MUSCL (2.78)
  if (uses_density_gradient(scene)) p_.allocate(field::DensityGradient{});
  if (uses_velocity_gradient(scene)) {
    p_.allocate(field::VelocityGradientX{});
    p_.allocate(field::VelocityGradientY{});
    if constexpr (D == 3) p_.allocate(field::VelocityGradientZ{});
  }
  if (walls) p_.allocate(field::ShepardGamma{});
  if (scene.flux == FluxScheme::Riemann && scene.riemann_variant == RiemannVariant::Vila) p_.allocate(field::MassRate{});
  bool free_surface_possible = false;
  for (int k = 0; k < D; ++k) free_surface_possible = free_surface_possible || !scene.periodic[k];
  if (free_surface_possible) p_.allocate(field::FreeSurface{});
  if (walls) {
    walls_ = WallModel<D>(scene_, domain_.box(), R_, wall_spacing_);
  }
  hooks_ = make_step_hooks<D>(scene_, restart);
  for (auto& h : hooks_)
    if (auto* r = dynamic_cast<Refinement<D>*>(h.get())) refinement_ = r;
  for (auto& h : hooks_) h->allocate(p_);
  if (restart) {
    load_checkpoint(p_, *restart, apr_on);
  } else {
    fill_lattice(p_, scene_, lattice_first_, lattice_end);
    bool cuts = false;
    for (const FluidBlock& b : scene_.blocks) cuts = cuts || !b.cuts.empty();
    if (walls) {
      const FluidRegion<D> region = fluid_region<D>(scene_, walls_, domain_.box());
      remove_outside_fluid(p_, scene_, &region, comm());
      check_wall_sides(p_, scene_, walls_, domain_.box(), R_, comm());
    } else if (cuts) {
      remove_outside_fluid<D>(p_, scene_, nullptr, comm());
    }
  }
  n_own_ = static_cast<int>(p_.size());
  if (!comm().serial()) {
    // first decomposition: weighted by the particles in each cell
    domain_.decompose(p_.get(field::Position{}), n_own_, domain_.list(), nullptr, false);
    n_own_ = domain_.migrate(p_, n_own_);
  }
  // the hooks' set-up (the open boundaries' roles, then the refinement's first levels or the
  // checkpoint's APR state)
  StepState<D> state(*this);
  for (auto& h : hooks_) h->start(state, restart);
  with_eos<D>(scene_, [&](auto eos) {
    update_pressure<D>(eos, p_.get(field::Density{}), p_.get(field::Pressure{}), n_own_);
  });
  initial_ = diagnostics(*this);
  if (!restart)
    for (auto& h : hooks_) h->started(initial_);
  if (restart) {
    t_ = restart->header.time;
    steps_ = restart->header.step;
    stage_time_ = t_;
    initial_.mass = restart->header.initial_mass;
    for (int k = 0; k < 3; ++k) initial_.momentum[k] = restart->header.initial_momentum[k];
    if (walls_.moving()) update_walls(t_);
    if (scene_.refinement_local_time_stepping)
      for (const double n : restart->header.refinement.level_steps) level_steps_.push_back(static_cast<std::int64_t>(n));
    // the work before the restart: its all-rank totals on rank 0, so that the sum over ranks goes on from them
    level_particle_steps_ = restart->header.refinement.level_particle_steps;
    if (comm().rank() != 0) std::fill(level_particle_steps_.begin(), level_particle_steps_.end(), 0.0);
  }
}

template <int D>
std::int64_t Simulation<D>::next_id() const {
  if (refinement_) return refinement_->apr().next_id();
  for (const auto& h : hooks_)
    if (h->next_id() >= 0) return h->next_id();
  return 0;
}

template <int D>
const AdaptiveRefinement<D>& Simulation<D>::refinement() const {
  static const AdaptiveRefinement<D> none{};
  return refinement_ ? refinement_->apr() : none;
}

}  // namespace ondine
