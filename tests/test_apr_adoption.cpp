// Adoption (kernels/apr/Adoption.hpp, docs/apr.md "Derefinement"): the daughters a
// derefining mother leaves inside their zone stay, re-parented to the nearest mother guard
// (brute force over all particles), with every mother holding the sum of her daughters'
// masses and the leaves' mass exact. The same scenario runs on 2 and 4 ranks in test_mpi.cpp.
#include <catch2/catch.hpp>

#include "apr_adoption_scenario.hpp"

using namespace ondine;

TEST_CASE("APR adoption: a mother leaving her zone leaves her daughters in it, adopted, mass exact", "[apr]") {
  const test::AprGather local = [](const Simulation<2>& sim) { return test::owned_apr_rows(sim); };
  const test::AdoptionOutcome on = test::mother_leaves(true, local);
  CHECK(on.daughters_kept == 4);
  CHECK(on.adopters_as_brute_force == 4);
  CHECK(on.adopted == 4);
  CHECK(on.orphans_deleted == 0);
  CHECK_FALSE(on.mother_kept);  // her whole mass went with her daughters
  CHECK(on.leaf_drift <= 1e-14);
  CHECK(on.worst_family <= 1e-14);  // every mother holds the sum of her daughters' masses

  // without adoption (refinement.adoption: false) the family goes whole: the zone loses four
  // fine particles deep inside it, and the mother comes back with their mass
  const test::AdoptionOutcome off = test::mother_leaves(false, local);
  CHECK(off.daughters_kept == 0);
  CHECK(off.mother_kept);
  CHECK(off.mother_mass == on.mass0);
  CHECK(off.adopted == 0);
  CHECK(off.leaf_drift <= 1e-14);
  CHECK(off.worst_family <= 1e-14);
}
