#pragma once
// turbulence: the eddy viscosity nu_T of the model (V&I §4.1.1) before the flux, from the stage's
// state (kernels/turbulence/EddyViscosityPass.hpp): at every stage, or with scheme.density_gradient:
// step at a step's first stage only and held through the others, as the density gradient is
// (the owned particles carry it through a migration); read by the Morris term with
// nu + nu_T (kernels/terms/EddyMorrisViscosity.hpp); with the log-law wall function also u_* and y+
// next to no-slip walls (kernels/wall/WallFunction.hpp). The halo copies get nu_T, which the pair
// term reads on both sides. With k-epsilon, k and epsilon are particle fields (in checkpoints),
// set to the case's initial values at the start and advanced at each step's end over the step
// (kernels/turbulence/KEpsilon.hpp: from the end state, the destruction and the diffusion's
// diagonal implicit), split from the Runge-Kutta step of the flow. The Langevin model moves the
// owned particles' velocities at each step's end by its increment over the step
// (kernels/turbulence/Langevin.hpp), split likewise; <u>, nu_T, k and epsilon are its by-products.
// The increments' momentum, sum_i m_i (u_1 - u)_i, is summed over the steps since t = 0 (carried
// by checkpoints) for the momentum budget (observers/LangevinMomentumSeries.hpp).
#include <array>

#include "kernels/turbulence/KEpsilon.hpp"
#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"

namespace ondine {

template <int D>
class EddyViscosity final : public StepHook<D> {
 public:
  explicit EddyViscosity(const Scene& s)
      : k_eps_(s.turbulence.model == TurbulenceModel::KEpsilon),
        langevin_(s.turbulence.model == TurbulenceModel::Langevin),
        averaged_(langevin_ && s.turbulence.langevin_averaged),
        drift_mean_removed_(langevin_ && s.turbulence.langevin_drift_mean_removed) {}
  const char* name() const override { return "eddy_viscosity"; }
  void allocate(ParticleSet<D>& p) override {
    p.allocate(field::EddyViscosity{});
    p.allocate(field::FrictionVelocity{});
    p.allocate(field::YPlus{});
    if (langevin_) {
      p.allocate(field::TurbulentKineticEnergy{});
      p.allocate(field::DissipationRate{});
      p.allocate(field::MeanVelocity{});
      p.allocate(field::LangevinVelocity{});
      p.allocate(field::LangevinOffset{});
      if (drift_mean_removed_) p.allocate(field::LangevinDrift{});
    }
    if (averaged_) {  // the path-averaged gradient: a state field (zero until the first step sets it)
      p.allocate(field::LangevinGradientX{});
      p.allocate(field::LangevinGradientY{});
      if (D == 3) p.allocate(field::LangevinGradientZ{});
    }
    if (!k_eps_) return;
    p.allocate(field::TurbulentKineticEnergy{});
    p.allocate(field::DissipationRate{});
    p.allocate(field::TurbulentKineticEnergyNext{});
    p.allocate(field::DissipationRateNext{});
  }
  void start(StepState<D>& s, const CheckpointSlice* restart) override {
    if (langevin_ && restart && s.comm().rank() == 0)  // a global sum, carried by rank 0
      for (int k = 0; k < 3; ++k) impulse_[k] = restart->header.langevin_impulse[k];
    if (!k_eps_ || restart) return;  // a restart reads k and epsilon from its checkpoint
    ParticleSet<D>& p = s.particles();
    Kokkos::deep_copy(p.get(field::TurbulentKineticEnergy{}), s.scene().turbulence.initial_k);
    Kokkos::deep_copy(p.get(field::DissipationRate{}), s.scene().turbulence.initial_epsilon);
  }
  void before_flux(StepState<D>& s, bool later_stage) override {
    if (!(later_stage && s.scene().density_gradient_once_per_step))
      for (const LevelSpan<D>& L : s.levels())
        if (L.active_end > L.first) s.scheme().eddy_viscosity(s.context(L));
    s.domain().refresh(s.particles(), field::EddyViscosity{});  // a list rebuilt since may have made new halo copies
  }
  void step_end(StepState<D>& s, double dt) override {
    if (langevin_) langevin_step(s, dt);
    if (!k_eps_) return;
    ParticleSet<D>& p = s.particles();
    s.ensure_lists();
    s.domain().refresh_state_halos(p);
    s.domain().refresh(p, field::TurbulentKineticEnergy{}, field::DissipationRate{}, field::EddyViscosity{});
    for (const LevelSpan<D>& L : s.levels())
      if (L.active_end > L.first) {
        PassContext<D> c = s.context(L);
        c.k_eps.dt = dt;
        s.scheme().k_epsilon_step(c);
      }
    const PassContext<D> c = s.context();
    const bool rough = c.log_law.rough;
    KEpsilonUpdate<D> update{c.k_eps, c.log_law.kappa, c.log_law.nu, rough ? 0.0 : c.log_law.yc, rough ? c.log_law.ks : 0.0,
                             c.k, c.eps, c.k_next, c.eps_next};
    if (s.scene().turbulence.wall_function != WallLaw::None) {
      update.u_star = c.u_star;
      update.y_plus = c.y_plus;
    }
    Kokkos::parallel_for("ondine::KEpsilon::update", Kokkos::RangePolicy<ExecSpace>(0, s.owned()), update);
  }

  // public: nvcc takes no extended lambda in a private member function
  void langevin_step(StepState<D>& s, double dt) {
    ParticleSet<D>& p = s.particles();
    s.ensure_lists();
    s.domain().refresh_state_halos(p);
    for (const LevelSpan<D>& L : s.levels())
      if (L.active_end > L.first) s.scheme().langevin_mean(s.context(L));
    s.domain().refresh(p, field::MeanVelocity{});
    for (const LevelSpan<D>& L : s.levels())
      if (L.active_end > L.first) {
        PassContext<D> c = s.context(L);
        c.langevin.dt = dt;
        c.langevin.step = s.steps();
        c.langevin.time = s.time();
        s.scheme().langevin_step(c);
      }
    if (drift_mean_removed_) {
      s.domain().refresh(p, field::LangevinDrift{});
      for (const LevelSpan<D>& L : s.levels())
        if (L.active_end > L.first) s.scheme().langevin_drift_mean(s.context(L));
    }
    auto u = p.get(field::Velocity{});
    auto u1 = p.get(field::LangevinVelocity{});
    auto mean = p.get(field::MeanVelocity{});
    auto corrected = p.get(field::LangevinOffset{});
    auto m = p.get(field::Mass{});
    for (int a = 0; a < D; ++a) {
      double dp = 0;
      Kokkos::parallel_reduce("ondine::Langevin::momentum", Kokkos::RangePolicy<ExecSpace>(0, s.owned()),
                              KOKKOS_LAMBDA(const int i, double& sum) { sum += m(i) * (u1(i, a) - u(i, a)); }, dp);
      impulse_[a] += dp;
    }
    Kokkos::parallel_for("ondine::Langevin::update", Kokkos::RangePolicy<ExecSpace>(0, s.owned()), KOKKOS_LAMBDA(const int i) {
      for (int a = 0; a < D; ++a) {
        u(i, a) = u1(i, a);
        mean(i, a) = corrected(i, a);
      }
    });
    s.domain().halos_stale();
  }

  void save(const Communicator& comm, CheckpointHeader& h) const override {
    if (!langevin_) return;
    const std::vector<double> v = langevin_impulse(comm);
    for (int k = 0; k < D; ++k) h.langevin_impulse[k] = v[k];
  }
  bool langevin() const { return langevin_; }
  // the Langevin increments' momentum since t = 0 (kg m/s; per metre of span in 2D), all ranks
  std::vector<double> langevin_impulse(const Communicator& comm) const {
    std::vector<double> v(impulse_.begin(), impulse_.begin() + D);
    comm.sum_in_place(v);
    return v;
  }

 private:
  bool k_eps_, langevin_, averaged_, drift_mean_removed_;
  std::array<double, 3> impulse_ = {0, 0, 0};  // this rank's
};

}  // namespace ondine
