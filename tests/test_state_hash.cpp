// Results unchanged through refactoring: the state hashes of six cases after a fixed number
// of steps (tests/state_hash_cases.hpp), recorded before the one-pipeline redesign (poiseuille's and
// lid_driven_cavity's again when the consistent Laplacian's moment matrix was summed as its upper
// triangle and mirrored: its lower triangle had differed from the upper in the last bit), on one
// rank (the 2- and 4-rank values are in test_mpi.cpp). Thread-count independent: every
// per-particle sum runs in neighbour-list order, and the reductions that feed the state
// (time step, P_min) are min/max.
#include <catch2/catch.hpp>

#include <cinttypes>

#include "state_hash_cases.hpp"

using namespace ondine;

TEST_CASE("state hashes of the regression cases are unchanged (one rank)", "[unit][hash]") {
  // name -> (state, APR) hashes
  const std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> recorded = {
      {"dam_break", {0xeb07e8b014d5f194ULL, 0x0000000000000000ULL}},
      {"dam_break_apr", {0xd0e0c777b0d4703cULL, 0x7ffcbc4512de54deULL}},
      {"taylor_green", {0xdca9283d18533a60ULL, 0x0000000000000000ULL}},
      {"poiseuille", {0x1bb0d339292f04e9ULL, 0x0000000000000000ULL}},
      {"lid_driven_cavity", {0xed55b0f41516511dULL, 0x0000000000000000ULL}},
      {"wave_paddle", {0x6ddfece01de411b2ULL, 0x0000000000000000ULL}},
  };
  for (const auto& c : test::hash_cases()) {
    const auto h = test::run_and_hash(c);
    std::printf("state hash 1 rank %-18s {0x%016" PRIx64 "ULL, 0x%016" PRIx64 "ULL}\n", c.name, h.first, h.second);
    INFO(c.name);
    CHECK(h.first == recorded.at(c.name).first);
    CHECK(h.second == recorded.at(c.name).second);
  }
}
