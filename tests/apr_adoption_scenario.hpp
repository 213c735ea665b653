#pragma once
// The adoption scenario (kernels/apr/Adoption.hpp), shared by the one-rank test
// (test_apr_adoption.cpp) and the MPI one (test_mpi.cpp): in fluid at rest, the mother guard
// nearest the zone's centre jumps 0.15 m out of the zone, to the middle of a cell of the
// coarse lattice; one step, whose bookkeeping derefines her far from her four daughters.
// Everything is read from the particles of every rank (`gather`), so that the same checks
// hold on any rank count; each daughter's adopter is also found by brute force over them.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

namespace ondine::test {

// fluid at rest in a periodic 0.6 x 0.4 m box (dx 0.02 m, R 0.06 m), one static zone
// [0.2, 0.4] x [0.12, 0.28]: its transition layer is R = 0.06 m wide, a mother derefines
// beyond 0.07 m from it
inline Scene adoption_resting_box(bool adoption) {
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

struct AprRow {
  std::int64_t id, parent;
  double x[2], m;
  int birth, mother;
};

// the owned particles of this rank
inline std::vector<AprRow> owned_apr_rows(const Simulation<2>& sim) {
  const auto& p = sim.particles();
  auto host = [](const auto& v) { return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v); };
  auto x = host(p.get(field::Position{}));
  auto m = host(p.get(field::Mass{}));
  auto id = host(p.get(field::GlobalId{}));
  auto parent = host(p.get(field::AprParent{}));
  auto birth = host(p.get(field::AprBirthLevel{}));
  auto mother = host(p.get(field::AprMother{}));
  std::vector<AprRow> rows(sim.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = {id(i), parent(i), {x(i, 0), x(i, 1)}, m(i), birth(i), mother(i)};
  return rows;
}

struct AdoptionOutcome {
  int daughters_kept = 0, adopters_as_brute_force = 0;
  bool mother_kept = false;
  double mother_mass = 0, mass0 = 0, leaf_drift = 0, worst_family = 0;
  std::int64_t adopted = 0, orphans_deleted = 0;
};

using AprGather = std::function<std::vector<AprRow>(const Simulation<2>&)>;

inline AdoptionOutcome mother_leaves(bool adoption, const AprGather& gather) {
  Simulation<2> sim(adoption_resting_box(adoption));
  std::vector<AprRow> all = gather(sim);
  const auto nearest = [&](double x, double y, int mother) {
    const AprRow* best = nullptr;
    double d = 1e300;
    for (const AprRow& r : all) {
      if (r.birth != 0 || r.mother != mother) continue;
      const double e = std::hypot(r.x[0] - x, r.x[1] - y);
      if (e < d || (e == d && r.id < best->id)) d = e, best = &r;
    }
    return *best;
  };
  const AprRow M = nearest(0.3, 0.2, 1), C = nearest(0.05, 0.2, 0);
  const double to[2] = {C.x[0] + 0.01, C.x[1] + 0.01};
  // each daughter's adopter by brute force: the nearest other mother of level 0 inside the zone
  // within R_0 = 0.06 m (ties by the smaller id); all of them were mothers before the step
  const auto inside = [](const AprRow& r) { return r.x[0] > 0.2 && r.x[0] < 0.4 && r.x[1] > 0.12 && r.x[1] < 0.28; };
  std::map<std::int64_t, std::int64_t> expected;
  double leaf0 = 0;
  AdoptionOutcome o;
  o.mass0 = M.m;
  for (const AprRow& d : all) {
    if (d.mother != 1) leaf0 += d.m;
    if (d.parent != M.id) continue;
    std::int64_t best = -1;
    double e = 0.06 * 0.06;
    for (const AprRow& a : all) {
      if (a.birth != 0 || a.mother != 1 || a.id == M.id || !inside(a)) continue;
      const double r2 = std::pow(a.x[0] - d.x[0], 2) + std::pow(a.x[1] - d.x[1], 2);
      if (r2 < e || (r2 == e && a.id < best)) e = r2, best = a.id;
    }
    expected[d.id] = best;
  }
  // the jump, on the rank that owns her
  auto& p = sim.particles();
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::Position{}));
  auto hid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.get(field::GlobalId{}));
  for (std::size_t i = 0; i < sim.size(); ++i)
    if (hid(i) == M.id)
      for (int k = 0; k < 2; ++k) hx(i, k) = to[k];
  Kokkos::deep_copy(p.get(field::Position{}), hx);
  sim.invalidate_neighbours();
  sim.step(1.0);

  all = gather(sim);
  std::map<std::int64_t, const AprRow*> by_id;
  std::map<std::int64_t, double> daughters_mass;
  double leaf = 0;
  for (const AprRow& r : all) {
    by_id[r.id] = &r;
    if (r.birth > 0) daughters_mass[r.parent] += r.m;
    if (r.mother != 1) leaf += r.m;
  }
  for (const AprRow& r : all)
    if (r.mother == 1) o.worst_family = std::max(o.worst_family, std::abs(daughters_mass[r.id] - r.m) / r.m);
  for (const auto& [d, adopter] : expected) {
    const auto it = by_id.find(d);
    if (it == by_id.end()) continue;
    ++o.daughters_kept;
    if (adopter >= 0 && it->second->parent == adopter) ++o.adopters_as_brute_force;
  }
  const auto m = by_id.find(M.id);
  o.mother_kept = m != by_id.end();
  if (o.mother_kept) o.mother_mass = m->second->m;
  o.leaf_drift = std::abs(leaf - leaf0) / leaf0;
  o.adopted = sim.refinement().adopted();
  o.orphans_deleted = sim.refinement().orphans_deleted();
  std::printf("APR adoption %s (%d rank(s)): %d of %zu daughters kept (%d by the brute-force adopter), mother %s (mass %.3g of "
              "%.3g), %lld adopted, %lld deleted for want of an adopter; leaf-mass drift %.2e, worst family %.2e\n",
              adoption ? "on" : "off", sim.comm().size(), o.daughters_kept, expected.size(), o.adopters_as_brute_force,
              o.mother_kept ? "kept" : "gone", o.mother_mass, o.mass0, static_cast<long long>(o.adopted),
              static_cast<long long>(o.orphans_deleted), o.leaf_drift, o.worst_family);
  return o;
}

}  // namespace ondine::test
