#pragma once
// The state hashes of issue-independent regression runs: six cases, each run a fixed number
// of steps with one output in the middle (an OutputFrame and the observers), then
// hashed (kernels/StateHash.hpp). The recorded values pin the numerics bitwise: a change that
// only moves code must keep them; a change of numerics must say why and record new ones.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/CaseFile.hpp"
#include "solver/Simulation.hpp"

namespace ondine::test {

struct HashCase {
  const char* name;
  const char* file;
  std::vector<std::string> sets;
  int steps;
};

inline const std::vector<HashCase>& hash_cases() {
  static const std::vector<HashCase> cases = {
      // the solver's defaults, not the case file's fast setting (CFL 0.75, gradient once per step)
      {"dam_break", "dam_break_2d.yaml", {"discretisation.dx=0.002286", "scheme.cfl.acoustic=0.375", "scheme.density_gradient=stage", "scheme.pair_list=full"}, 100},
      {"dam_break_apr", "dam_break_apr_2d.yaml", {}, 100},
      {"taylor_green", "taylor_green_2d.yaml", {"discretisation.dx=0.05"}, 100},
      {"poiseuille", "poiseuille_2d.yaml", {}, 100},
      {"lid_driven_cavity", "lid_driven_cavity_2d.yaml", {"discretisation.dx=0.05"}, 100},
      {"wave_paddle", "wave_paddle_2d.yaml", {"discretisation.dx=0.025"}, 100},
  };
  return cases;
}

// state checksum and (with refinement zones) APR checksum after `steps` steps, with one
// output's worth of observers at half-way, as the runner does it
inline std::pair<std::uint64_t, std::uint64_t> run_and_hash(const HashCase& c) {
  Simulation<2> sim(load_case(std::string(ONDINE_SOURCE_DIR) + "/cases/" + c.file, c.sets));
  for (int s = 0; s < c.steps; ++s) {
    sim.step(1e30);
    if (s == c.steps / 2) {
      const OutputFrame<2> frame(sim);
      if (!sim.walls().empty()) wall_forces(sim);
      diagnostics(sim);
      sample_probes(sim);
      wave_elevations(sim);
      front_position(sim);
    }
  }
  return {state_checksum(sim), sim.refinement_on() ? refinement_checksum(sim) : 0};
}

}  // namespace ondine::test
