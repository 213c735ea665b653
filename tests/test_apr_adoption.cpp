// Adoption (kernels/apr/Adoption.hpp, docs/apr.md "Derefinement"): the daughters a
// derefining mother leaves inside their zone stay, re-parented to a mother guard, with
// every mother holding the sum of her daughters' masses and the leaves' mass exact.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <map>

#include "test_helpers.hpp"

using namespace ondine;

namespace {

// fluid at rest in a periodic 0.6 x 0.4 m box (dx 0.02 m, R 0.06 m), one static zone
// [0.2, 0.4] x [0.12, 0.28]: its transition layer is R = 0.06 m wide, a mother derefines
// beyond 0.07 m from it
Scene resting_box(bool adoption) {
  return parse_case(std::string("dimension: 2\n"
                                "domain: {min: [0, 0], max: [0.6, 0.4], periodic: [true, true]}\n"
                                "fluid: {rho0: 1000, sound_speed: 10}\n"
                                "discretisation: {dx: 0.02, R_over_dx: 3}\n"
                                "fluid_blocks: [{min: [0, 0], max: [0.6, 0.4]}]\n"
                                "scheme: {time_integrator: rk4}\n"
                                "time: {duration: 1, output_interval: 1}\n"
                                "refinement: {adoption: ") +
                        (adoption ? "true" : "false") + ", zones: [{name: box, min: [0.2, 0.12], max: [0.4, 0.28]}]}\n",
                    "adoption.yaml");
}

struct Families {
  std::map<std::int64_t, std::size_t> index;  // by id
  double leaf_mass = 0, worst_family = 0;     // the mothers' |m - sum of daughters| / m
  int mothers = 0;
};

Families families(const Simulation<2>& sim, const test::AprHostState<2>& h,
                  const Kokkos::View<std::int64_t*, Kokkos::HostSpace>& id) {
  Families f;
  std::map<std::int64_t, double> daughters;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) {
    f.index[id(i)] = i;
    if (h.birth(i) > 0) daughters[h.parent(i)] += h.m(i);
    if (h.mother(i) != 1) f.leaf_mass += h.m(i);
  }
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (h.mother(i) == 1) {
      ++f.mothers;
      f.worst_family = std::max(f.worst_family, std::abs(daughters[id(i)] - h.m(i)) / h.m(i));
    }
  return f;
}

struct Outcome {
  int daughters_kept = 0, adopted_by_guards = 0;
  bool mother_kept = false;
  double mother_mass = 0, mass0 = 0, leaf_drift = 0, worst_family = 0;
  std::int64_t adopted = 0, orphans_deleted = 0;
};

// The mother guard nearest the zone's centre jumps 0.15 m out of the zone, to the middle of a
// cell of the coarse lattice; one step (its bookkeeping derefines her, far from her daughters).
Outcome mother_leaves(bool adoption) {
  Simulation<2> sim(resting_box(adoption));
  auto& p = sim.particles();
  test::AprHostState<2> h = test::apr_host_state(sim);
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::GlobalId{}));
  const Families before = families(sim, h, id);
  const auto nearest = [&](double x, double y, int mother) {
    std::size_t best = 0;
    double d = 1e300;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (h.birth(i) != 0 || h.mother(i) != mother) continue;
      const double e = std::hypot(h.x(i, 0) - x, h.x(i, 1) - y);
      if (e < d) d = e, best = i;
    }
    return best;
  };
  const std::size_t M = nearest(0.3, 0.2, 1), C = nearest(0.05, 0.2, 0);
  const std::int64_t mid = id(M);
  Outcome o;
  o.mass0 = h.m(M);
  std::vector<std::int64_t> daughters;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (h.parent(i) == mid) daughters.push_back(id(i));
  REQUIRE(daughters.size() == 4);
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  for (int k = 0; k < 2; ++k) hx(M, k) = hx(C, k) + 0.01;
  Kokkos::deep_copy(p.get(field::Position{}), hx);
  sim.invalidate_neighbours();
  sim.step(1.0);

  h = test::apr_host_state(sim);
  id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::GlobalId{}));
  const Families after = families(sim, h, id);
  const auto& z = sim.refinement().zones();
  for (const std::int64_t d : daughters) {
    const auto it = after.index.find(d);
    if (it == after.index.end()) continue;
    ++o.daughters_kept;
    const auto adopter = after.index.find(h.parent(it->second));
    if (adopter == after.index.end()) continue;
    const std::size_t a = adopter->second;
    const double ax = h.x(a, 0), ay = h.x(a, 1);
    if (h.parent(it->second) != mid && h.birth(a) == 0 && h.mother(a) == 1 && ax > z.lo[0][0] && ax < z.hi[0][0] && ay > z.lo[0][1] &&
        ay < z.hi[0][1])
      ++o.adopted_by_guards;
  }
  const auto m = after.index.find(mid);
  o.mother_kept = m != after.index.end();
  if (o.mother_kept) o.mother_mass = h.m(m->second);
  o.leaf_drift = std::abs(after.leaf_mass - before.leaf_mass) / before.leaf_mass;
  o.worst_family = std::max(before.worst_family, after.worst_family);
  o.adopted = sim.refinement().adopted();
  o.orphans_deleted = sim.refinement().orphans_deleted();
  std::printf("APR adoption %s: %d of 4 daughters kept (%d by a mother guard of the zone), mother %s (mass %.3g of %.3g), "
              "%lld adopted, %lld deleted for want of an adopter; leaf-mass drift %.2e, worst family %.2e (%d mothers)\n",
              adoption ? "on" : "off", o.daughters_kept, o.adopted_by_guards, o.mother_kept ? "kept" : "gone", o.mother_mass,
              o.mass0, static_cast<long long>(o.adopted), static_cast<long long>(o.orphans_deleted), o.leaf_drift, o.worst_family,
              after.mothers);
  return o;
}

}  // namespace

TEST_CASE("APR adoption: a mother leaving her zone leaves her daughters in it, adopted, mass exact", "[apr]") {
  const Outcome on = mother_leaves(true);
  CHECK(on.daughters_kept == 4);
  CHECK(on.adopted_by_guards == 4);
  CHECK(on.adopted == 4);
  CHECK(on.orphans_deleted == 0);
  CHECK_FALSE(on.mother_kept);  // her whole mass went with her daughters
  CHECK(on.leaf_drift <= 1e-14);
  CHECK(on.worst_family <= 1e-14);  // every mother holds the sum of her daughters' masses

  // without adoption (refinement.adoption: false) the family goes whole: the zone loses four
  // fine particles deep inside it, and the mother comes back with their mass
  const Outcome off = mother_leaves(false);
  CHECK(off.daughters_kept == 0);
  CHECK(off.mother_kept);
  CHECK(off.mother_mass == on.mass0);
  CHECK(off.adopted == 0);
  CHECK(off.leaf_drift <= 1e-14);
  CHECK(off.worst_family <= 1e-14);
}
