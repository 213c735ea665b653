// Step hooks (solver/StepHook.hpp): a toy hook written in this file alone and added with
// one line reaches every named point of a step in order, and changes the state the way it
// says: a uniform acceleration a applied at each step's end moves a lattice at rest in a
// periodic box (where every pair force cancels) at exactly u = a t.
#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

#include "solver/StepState.hpp"
#include "solver/StepHook.hpp"
#include "test_helpers.hpp"

using namespace ondine;
using namespace ondine::test;

// u_x += du on each particle (a functor: nvcc takes no device lambda in a class of an unnamed namespace)
template <int D>
struct KickVelocity {
  ondine::field_view_t<ondine::field::Velocity, D> u;
  double du;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { u(i, 0) += du; }
};

namespace {

// the toy hook: u += a dt on the owned particles at each step's end; it logs the points it sees
template <int D>
class UniformKick final : public StepHook<D> {
 public:
  explicit UniformKick(double a, std::vector<std::string>& log) : a_(a), log_(log) {}
  const char* name() const override { return "uniform_kick"; }
  void step_start(StepState<D>&) override { log_.push_back("step_start"); }
  void after_lists(StepState<D>&) override { log_.push_back("after_lists"); }
  void before_flux(StepState<D>&, bool later) override { log_.push_back(later ? "before_flux" : "before_flux(first)"); }
  void after_evaluation(StepState<D>&) override { log_.push_back("after_evaluation"); }
  void shifted(StepState<D>&, const ShiftedState<D>&) override { log_.push_back("shifted"); }
  void step_end(StepState<D>& s, double dt) override {
    log_.push_back("step_end");
    Kokkos::parallel_for("test::UniformKick", Kokkos::RangePolicy<ExecSpace>(0, s.owned()),
                         KickVelocity<D>{s.particles().get(field::Velocity{}), a_ * dt});
    s.domain().halos_stale();
  }

 private:
  double a_;
  std::vector<std::string>& log_;
};

template <int D>
void check_kick(const std::string& scheme, int evaluations, bool shifting) {
  const Scene scene = periodic_box(D, 0.2, 0.02, scheme);
  Simulation<D> sim(scene);
  std::vector<std::string> log;
  const double a = 0.5;  // m/s^2
  sim.add_hook(std::make_unique<UniformKick<D>>(a, log));  // the one registration line
  const int steps = 5;
  for (int k = 0; k < steps; ++k) sim.step(1.0);
  // the points in the order of a step: its start, its lists, each stage's evaluation (before
  // the flux, after it), the
  // shifted state (with shifting), its end
  std::vector<std::string> one{"step_start", "after_lists"};
  for (int e = 0; e < evaluations; ++e) {
    one.push_back(e == 0 ? "before_flux(first)" : "before_flux");
    one.push_back("after_evaluation");
  }
  if (shifting) one.push_back("shifted");
  one.push_back("step_end");
  std::vector<std::string> expected;
  for (int k = 0; k < steps; ++k) expected.insert(expected.end(), one.begin(), one.end());
  CHECK(log == expected);
  // every pair force of a lattice in uniform motion cancels: momentum = M a t to round-off
  const Diagnostics d = diagnostics(sim);
  CHECK(d.momentum[0] == Approx(d.mass * a * sim.time()).epsilon(1e-10));
  for (int k = 1; k < D; ++k) CHECK(std::abs(d.momentum[k]) < 1e-10 * d.mass * a * sim.time());
}

}  // namespace

TEST_CASE("A toy step hook in one file sees every point of the step in order and changes the state as it says", "[hooks]") {
  SECTION("2D, explicit midpoint") { check_kick<2>("{time_integrator: predictor_corrector}", 2, false); }
  SECTION("2D, RK4 with shifting") { check_kick<2>("{time_integrator: rk4, shifting: true}", 4, true); }
  SECTION("3D, explicit midpoint") { check_kick<3>("{time_integrator: predictor_corrector}", 2, false); }
}
