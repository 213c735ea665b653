#pragma once
// `ondine run --profile`: wall time and call count of every Kokkos kernel (parallel_for,
// parallel_reduce, parallel_scan) by name, from Kokkos' tool callbacks, written to
// OUT/profile_kernels.json. Hand-written because Kokkos' own kernel timer lives in the
// separate kokkos-tools project, which Debian does not package (docs/output.md).
#include <nlohmann/json.hpp>

namespace ondine {

// Installs the callbacks (once, before the run). Each kernel is fenced at its end so
// that device backends report the kernel's time, not its launch's.
void install_kernel_profile();

// {"kernel_seconds": total, "kernels": [{name, calls, seconds, share}] by decreasing time,
//  "groups": {group: {seconds, share}}}: share is over the total kernel time; a group is
// the name up to its second "::" (e.g. ondine::APR), plus "guard_interpolation"
// (ondine::APR::GuardWeights and ::GuardInterpolation, thesis 5.24).
nlohmann::json kernel_profile_report();

}  // namespace ondine
