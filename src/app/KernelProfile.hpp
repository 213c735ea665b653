#pragma once
// `ondine run --profile`: wall time and call count of every Kokkos kernel (parallel_for,
// parallel_reduce, parallel_scan) by name, from Kokkos' tool callbacks, written to
// OUT/profile_kernels.json. Hand-written because Kokkos' own kernel timer lives in the
// separate kokkos-tools project, which Debian does not package (docs/output.md).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ondine {

// Installs the kernel callbacks (once, before the run; perf/bench_flux.cpp also uses them). Each kernel is fenced at its end so
// that device backends report the kernel's time, not its launch's.
void install_kernel_profile();

// {"kernel_seconds": total, "kernels": [{name, calls, seconds, share}] by decreasing time,
//  "groups": {group: {seconds, share}}}: share is over the total kernel time; a group is
// the name up to its second "::" (e.g. ondine::APR), plus "guard_interpolation"
// (ondine::APR::GuardWeights and ::GuardInterpolation, thesis 5.24).
nlohmann::json kernel_profile_report();

// Forgets the times measured so far; the seconds spent in kernels whose name starts with
// one of `prefixes` since then.
void reset_kernel_profile();
double kernel_seconds(const std::vector<std::string>& prefixes);

}  // namespace ondine
