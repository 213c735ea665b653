// Particle storage: fields allocated on demand, SoA layout, resize keeps data.
#include <catch2/catch.hpp>

#include "particles/ParticleSet.hpp"

using namespace ondine;

TEST_CASE("ParticleSet allocates only the fields asked for", "[unit][storage]") {
  ParticleSet<2> p(10);
  CHECK(p.allocated_labels().empty());
  CHECK_FALSE(p.has(field::Velocity{}));
  CHECK_THROWS_AS(p.get(field::Velocity{}), std::logic_error);
  p.allocate(field::Position{});
  p.allocate(field::Density{});
  CHECK(p.allocated_labels() == std::vector<std::string>{"position", "density"});
  CHECK(p.get(field::Position{}).extent(0) == 10);
  CHECK(p.get(field::Position{}).extent(1) == 2);
  // structure of arrays: component k of all particles is contiguous
  const auto x = p.get(field::Position{});
  CHECK(&x(1, 0) - &x(0, 0) == 1);
  CHECK(&x(0, 1) - &x(0, 0) == 10);
}

TEST_CASE("ParticleSet::resize keeps the first entries of every field", "[unit][storage]") {
  ParticleSet<3> p(4);
  const auto x = p.allocate(field::Position{});
  const auto id = p.allocate(field::GlobalId{});
  Kokkos::parallel_for(4, KOKKOS_LAMBDA(int i) {
    id(i) = 100 + i;
    for (int k = 0; k < 3; ++k) x(i, k) = 10 * i + k;
  });
  p.resize(7);
  CHECK(p.size() == 7);
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::GlobalId{}));
  REQUIRE(hx.extent(0) == 7);
  for (int i = 0; i < 4; ++i) {
    CHECK(hid(i) == 100 + i);
    for (int k = 0; k < 3; ++k) CHECK(hx(i, k) == 10 * i + k);
  }
}
