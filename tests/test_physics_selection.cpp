// "A scene pays only for what it uses": the kernels launched and the Views
// allocated are recorded through Kokkos' tool callbacks, for a minimal scene
// and for one with every term of the solver core.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>

#include "test_helpers.hpp"

using namespace ondine;
using namespace ondine::test;

namespace {

std::set<std::string> kernels_launched, views_allocated;

void on_kernel(const char* name, const uint32_t, uint64_t* id) {
  kernels_launched.insert(name);
  *id = 0;
}
void on_alloc(const Kokkos::Tools::SpaceHandle, const char* label, const void*, const uint64_t) {
  views_allocated.insert(label);
}

struct Recording {
  Recording() {
    kernels_launched.clear();
    views_allocated.clear();
    namespace KT = Kokkos::Tools::Experimental;
    KT::set_begin_parallel_for_callback(on_kernel);
    KT::set_begin_parallel_reduce_callback(on_kernel);
    KT::set_begin_parallel_scan_callback(on_kernel);
    KT::set_allocate_data_callback(on_alloc);
  }
  ~Recording() {
    namespace KT = Kokkos::Tools::Experimental;
    KT::set_begin_parallel_for_callback(nullptr);
    KT::set_begin_parallel_reduce_callback(nullptr);
    KT::set_begin_parallel_scan_callback(nullptr);
    KT::set_allocate_data_callback(nullptr);
  }
};

bool any_contains(const std::set<std::string>& s, const std::string& word) {
  return std::any_of(s.begin(), s.end(), [&](const std::string& x) { return x.find(word) != std::string::npos; });
}

std::string listing(const std::set<std::string>& s) {
  std::string out;
  for (const auto& x : s) out += "  " + x + "\n";
  return out;
}

}  // namespace

TEST_CASE("A minimal scene launches no kernel and allocates no field it does not need", "[physics]") {
  const Scene s = periodic_box(2, 0.3, 0.02, "{time_integrator: predictor_corrector}");
  Recording rec;
  Simulation<2> sim(s);
  sim.step(1.0);
  sim.step(1.0);
  INFO("kernels:\n" << listing(kernels_launched) << "views:\n" << listing(views_allocated));
  CHECK(kernels_launched.count("ondine::Flux[pressure_gradient+continuity]") == 1);
  CHECK_FALSE(any_contains(kernels_launched, "viscosity"));
  CHECK_FALSE(any_contains(kernels_launched, "delta"));
  CHECK_FALSE(any_contains(kernels_launched, "DensityGradient"));
  CHECK_FALSE(any_contains(kernels_launched, "BackgroundPressure"));
  CHECK_FALSE(any_contains(views_allocated, "density_gradient"));
  CHECK_FALSE(any_contains(views_allocated, "stage_position_sum"));  // RK4 sums: not with the midpoint scheme
  // one rank: no decomposition, migration or halo exchange
  CHECK_FALSE(any_contains(kernels_launched, "ondine::Halo"));
  CHECK_FALSE(any_contains(kernels_launched, "ondine::Migrate"));
  CHECK_FALSE(any_contains(kernels_launched, "ondine::Decomposition"));
  CHECK(views_allocated.count("ondine::particles::position") == 1);
  // no refinement zone: the uniform code path (no APR kernel, field or list)
  CHECK_FALSE(any_contains(kernels_launched, "APR"));
  CHECK_FALSE(any_contains(views_allocated, "APR"));
  CHECK_FALSE(any_contains(views_allocated, "ondine::particles::level"));
  CHECK_FALSE(any_contains(views_allocated, "ondine::particles::birth_level"));
  CHECK_FALSE(any_contains(views_allocated, "ondine::particles::guard"));
  CHECK_FALSE(any_contains(views_allocated, "ondine::particles::mother"));
}

TEST_CASE("The full scheme launches and allocates what its terms need", "[physics]") {
  const Scene s = periodic_box(2, 0.3, 0.02,
                               "{viscous_term: morris, delta_sph: 0.1, artificial_viscosity: 0.02, background_pressure: true}",
                               ", viscosity: 1.0e-3");
  Recording rec;
  Simulation<2> sim(s);
  sim.step(1.0);
  INFO("kernels:\n" << listing(kernels_launched) << "views:\n" << listing(views_allocated));
  CHECK(kernels_launched.count(
            "ondine::Flux[pressure_gradient+continuity+delta_sph+morris_viscosity+artificial_viscosity+background_pressure]") == 1);
  CHECK(kernels_launched.count("ondine::DensityGradient") == 1);
  CHECK(kernels_launched.count("ondine::BackgroundPressure::min") == 1);
  CHECK(views_allocated.count("ondine::particles::density_gradient") == 1);
  CHECK(views_allocated.count("ondine::particles::stage_position_sum") == 1);
  CHECK_FALSE(any_contains(kernels_launched, "APR"));
  CHECK_FALSE(any_contains(views_allocated, "APR"));
  CHECK_FALSE(any_contains(views_allocated, "ondine::particles::level"));
  CHECK_FALSE(any_contains(views_allocated, "ondine::particles::guard"));
}

TEST_CASE("Refinement zones bring the APR kernels, fields and lists", "[physics][apr]") {
  Scene s = periodic_box(2, 0.4, 0.02, "{viscous_term: morris, delta_sph: 0.1}", ", viscosity: 1.0e-3");
  RefinementZone z;
  z.name = "box";
  z.box.min = {0.12, 0.12, 0};
  z.box.max = {0.28, 0.28, 0};
  s.refinement_zones.push_back(z);
  Recording rec;
  Simulation<2> sim(s);
  sim.step(1.0);
  INFO("kernels:\n" << listing(kernels_launched) << "views:\n" << listing(views_allocated));
  CHECK(kernels_launched.count("ondine::APR::GuardInterpolation") == 1);
  CHECK(kernels_launched.count("ondine::APR::SymmetricList::fill") == 1);
  CHECK(kernels_launched.count("ondine::APR::GuardList::fill") == 1);
  CHECK(kernels_launched.count("ondine::APR::daughters") == 1);
  CHECK(views_allocated.count("ondine::particles::birth_level") == 1);
  CHECK(views_allocated.count("ondine::particles::guard") == 1);
  // the pair loop is the uniform one, run per level (no APR term in the pack)
  CHECK(kernels_launched.count("ondine::Flux[pressure_gradient+continuity+delta_sph+morris_viscosity]") == 1);
}
