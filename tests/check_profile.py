#!/usr/bin/env python3
"""Checks OUT/profile_kernels.json of `ondine run --profile` (an APR run): every kernel
listed with its calls and seconds, shares summing to 1, the kernel time within the run's
wall time, and the guard interpolation (thesis 5.24) measured."""
import json
import sys

j = json.load(open(sys.argv[1] + "/profile_kernels.json"))
k = j["kernels"]
assert len(k) > 10, f"only {len(k)} kernels profiled"
assert all(e["calls"] > 0 and e["seconds"] >= 0 for e in k)
assert all(k[i]["seconds"] >= k[i + 1]["seconds"] for i in range(len(k) - 1)), "not sorted by time"
total = sum(e["seconds"] for e in k)
assert abs(total - j["kernel_seconds"]) <= 1e-9 * total
assert abs(sum(e["share"] for e in k) - 1) < 1e-9
assert 0 < j["kernel_seconds"] <= j["wall_seconds"], (j["kernel_seconds"], j["wall_seconds"])
g = j["groups"]["guard_interpolation"]
names = {e["name"]: e for e in k}
# GuardInterpolation once per RK4 stage of each step, GuardWeights once per step (and at bookkeepings)
assert names["ondine::APR::GuardInterpolation"]["calls"] >= 4 * j["steps"]
assert names["ondine::APR::GuardWeights"]["calls"] >= j["steps"]
assert 0 < g["share"] < 1
print(f"profile OK: {len(k)} kernels, {j['kernel_seconds']:.3g} s of {j['wall_seconds']:.3g} s wall, "
      f"guard interpolation {100 * g['share']:.1f} %")
