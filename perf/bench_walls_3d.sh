#!/usr/bin/env bash
# A 3D wall-bounded run end to end: cases/hydrostatic_tank_3d.yaml (1 x 1 x 2 m box
# tank, half filled, NFM triangle walls) at about 1e5 particles (dx = 1/46 m, 46^3)
# and 1e6 (dx = 0.01 m, 100^3), a fixed number of steps each, 2 OpenMP threads,
# with --profile. Right before each size it runs the yardstick, the hand-written
# OpenMP pair loop ../shared/perf/pairbench.cpp (300 x 300, R = 4 dx, 20
# evaluations, 3 runs, median), when that file is beside the checkout.
# Per size: particles, steps, step-loop seconds (summary.json loop_seconds),
# particle-steps/s, the share of the loop in wall (NFM) kernels, peak RSS per
# particle (/usr/bin/time -v); and the marginal bytes per particle between sizes.
# Writes perf/results/bench-walls3d-<date>.json and prints a table. Does not build:
# set ONDINE=path to use another binary than build/ondine.
# usage: perf/bench_walls_3d.sh [--steps-1e5 20] [--steps-1e6 10] [--quick] [--out perf/results]
#   --quick: the 1e5 size only
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
steps_small=20; steps_large=10; quick=0; out="$here/perf/results"
while [ $# -gt 0 ]; do
  case $1 in
    --steps-1e5) steps_small=$2; shift 2 ;;
    --steps-1e6) steps_large=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --out) out=$2; shift 2 ;;
    *) echo "perf/bench_walls_3d.sh: unknown option $1 (see the header of the script)" >&2; exit 2 ;;
  esac
done
ondine=${ONDINE:-$here/build/ondine}
[ -x "$ondine" ] || { echo "perf/bench_walls_3d.sh: build first (make build): no $ondine" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "perf/bench_walls_3d.sh: needs GNU time (/usr/bin/time, Debian package 'time')" >&2; exit 2; }
py=${PYTHON:-/usr/bin/python3}
case_file="$here/cases/hydrostatic_tank_3d.yaml"
mkdir -p "$out"
stamp=$(date +%Y%m%d-%H%M%S)
json="$out/bench-walls3d-$stamp.json"
work=$(mktemp -d /tmp/ondine-walls3d.XXXXXX); trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=2 OMP_PROC_BIND=spread OMP_PLACES=threads

pairbench=""
if [ -f "$here/../shared/perf/pairbench.cpp" ]; then
  g++ -O3 -march=native -fopenmp "$here/../shared/perf/pairbench.cpp" -o "$work/pairbench"  # as perf/run_benchmarks.sh
  pairbench="$work/pairbench"
else
  echo "perf/bench_walls_3d.sh: no ../shared/perf/pairbench.cpp beside the checkout: no yardstick" >&2
fi

# run LABEL DX STEPS: yardstick, then the case under /usr/bin/time -v; leaves $work/LABEL.*
run() {
  local label=$1 dx=$2 steps=$3
  cut -d' ' -f1-3 /proc/loadavg > "$work/$label.load_before"
  : > "$work/$label.pairbench"
  if [ -n "$pairbench" ]; then
    for r in 1 2 3; do "$pairbench" 300 20 >> "$work/$label.pairbench"; done
  fi
  echo "  $label: dx = $dx m, $steps steps ..." >&2
  if ! /usr/bin/time -v -o "$work/$label.time" "$ondine" run "$case_file" --out "$work/$label" --quiet --profile \
      --set discretisation.dx="$dx" --set time.max_steps="$steps" --set time.output_interval=1000 \
      > "$work/$label.log" 2>&1; then
    cat "$work/$label.log" >&2
    echo "perf/bench_walls_3d.sh: the $label run failed" >&2
    exit 1
  fi
  cut -d' ' -f1-3 /proc/loadavg > "$work/$label.load_after"
}

run 1e5 "$("$py" -c 'print(1 / 46)')" "$steps_small"
labels="1e5"
if [ "$quick" = 0 ]; then
  # the 1e6 run must fit: extrapolate the 1e5 run's peak RSS linearly in the particle count
  "$py" - "$work" "$steps_small" "$steps_large" <<'PY'
import json, re, sys
work, s_small, s_large = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(f"{work}/1e5.time").read()).group(1)) * 1024
s = json.load(open(f"{work}/1e5/summary.json"))
scale = 1e6 / s["particles"]
avail = next(int(l.split()[1]) * 1024 for l in open("/proc/meminfo") if l.startswith("MemAvailable:"))
need = rss * scale  # an upper bound: the fixed overhead is scaled too
eta = s["loop_seconds"] / s["steps"] * scale * s_large + s["wall_seconds"] - s["loop_seconds"]
print(f"  1e6: predicted peak RSS <= {need / 2**30:.2f} GiB of {avail / 2**30:.1f} GiB available, about {eta:.0f} s", file=sys.stderr)
if need > 0.8 * avail:
    sys.exit("perf/bench_walls_3d.sh: the 1e6 run would not fit in memory; use --quick")
PY
  run 1e6 0.01 "$steps_large"
  labels="1e5 1e6"
fi

"$py" - "$work" "$json" "$ondine" "$case_file" "$labels" <<'PY'
import datetime, json, os, re, statistics, sys
work, out, ondine, case_file, labels = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5].split()
# NFM kernels that run inside every step (evaluation passes and the impermeability correction);
# the other kernels whose names contain "NFM" are setup (View fills of the wall geometry) or
# output-time figures (wall_traction, wall_force, wall_moment, wall_point_owner, leaks,
# wall_side_count), counted in the "all" figure only.
OUTPUT_OR_SETUP = ("wall_traction", "wall_force", "wall_moment", "wall_point_owner", "leaks", "wall_side_count")
def is_step_nfm(name):
    return name.startswith("ondine::NFM::") and name.split("::")[2] not in OUTPUT_OR_SETUP

def load(path):
    return [float(x) for x in open(path).read().split()]

runs = []
for label in labels:
    s = json.load(open(f"{work}/{label}/summary.json"))
    prof = json.load(open(f"{work}/{label}/profile_kernels.json"))
    tv = open(f"{work}/{label}.time").read()
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", tv).group(1)) * 1024
    el = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", tv).group(1).split(":")
    elapsed = sum(float(v) * 60 ** i for i, v in enumerate(reversed(el)))
    kernels = prof["kernels"]
    nfm = [k for k in kernels if "NFM" in k["name"]]
    step_nfm = [k for k in nfm if is_step_nfm(k["name"])]
    loop = s["loop_seconds"]
    yard = [json.loads(l) for l in open(f"{work}/{label}.pairbench") if l.strip().startswith("{")]
    runs.append({
        "size": label,
        "dx": s["scheme"]["dx"],
        "particles": s["particles"],
        "steps": s["steps"],
        "status": s["status"],
        "simulated_time": s["simulated_time"],
        "neighbour_list_builds": s["neighbour_list_builds"],
        "loop_seconds": loop,
        "seconds_per_step": loop / s["steps"],
        "particle_steps_per_second": s["particles"] * s["steps"] / loop,
        "run_wall_seconds": s["wall_seconds"],
        "process_elapsed_seconds": elapsed,
        "wall_work": {
            "step_kernels_seconds": sum(k["seconds"] for k in step_nfm),
            "share_of_loop": sum(k["seconds"] for k in step_nfm) / loop,
            "step_kernels": [{"name": k["name"], "calls": k["calls"], "seconds": k["seconds"]} for k in step_nfm],
            "all_nfm_seconds": sum(k["seconds"] for k in nfm),
            "all_nfm_share_of_kernel_time": sum(k["seconds"] for k in nfm) / prof["kernel_seconds"],
            "other_nfm_kernels": [{"name": k["name"], "calls": k["calls"], "seconds": k["seconds"]}
                                  for k in nfm if not is_step_nfm(k["name"]) and k["seconds"] >= 1e-3],
        },
        "kernel_seconds": prof["kernel_seconds"],
        "top_kernels": [{"name": k["name"], "calls": k["calls"], "seconds": k["seconds"],
                         "share_of_loop": k["seconds"] / loop} for k in kernels[:8]],
        "max_rss_bytes": rss,
        "bytes_per_particle_including_fixed_overhead": rss / s["particles"],
        "pairbench": {
            "config": "2D 300 x 300, R = 4 dx, 20 evaluations, 3 runs, right before this size",
            "pair_interactions_per_s_median": statistics.median(r["pair_interactions_per_s"] for r in yard) if yard else None,
            "runs": yard,
        },
        "load_average_before": load(f"{work}/{label}.load_before"),
        "load_average_after": load(f"{work}/{label}.load_after"),
    })
s0 = json.load(open(f"{work}/{labels[0]}/summary.json"))
res = {
    "benchmark": "walls_3d",
    "date": datetime.datetime.now().isoformat(timespec="seconds"),
    "case": "cases/hydrostatic_tank_3d.yaml",
    "binary": os.path.relpath(ondine, os.path.dirname(os.path.dirname(case_file))) if ondine.startswith(os.path.dirname(os.path.dirname(case_file)) + "/") else ondine,
    "ondine_version": s0["ondine_version"],
    "kokkos_version": s0["kokkos_version"],
    "backend": s0["backend"],
    "threads": s0["threads"],
    "omp": {k: os.environ.get(k) for k in ("OMP_NUM_THREADS", "OMP_PROC_BIND", "OMP_PLACES")},
    "machine": {"cpus": os.cpu_count(),
                "memory_bytes": next(int(l.split()[1]) * 1024 for l in open("/proc/meminfo") if l.startswith("MemTotal:"))},
    "overrides": "--set discretisation.dx=DX --set time.max_steps=STEPS --set time.output_interval=1000 --profile",
    "definitions": {
        "loop_seconds": "summary.json loop_seconds: the step loop, including the last snapshot and the checkpoint written at max_steps",
        "wall_work.share_of_loop": "kernels named ondine::NFM::* run in the steps (listed in step_kernels) over loop_seconds",
        "wall_work.all_nfm_share_of_kernel_time": "every kernel whose name contains NFM (setup and output-time ones too) over all kernel time of the run",
        "bytes_per_particle_including_fixed_overhead": "peak RSS of the process (/usr/bin/time -v) over the particle count",
        "marginal_bytes_per_particle": "difference of the peak RSS between the two sizes over the difference of the particle counts",
    },
    "runs": runs,
}
if len(runs) == 2:
    a, b = runs
    res["marginal_bytes_per_particle"] = (b["max_rss_bytes"] - a["max_rss_bytes"]) / (b["particles"] - a["particles"])
json.dump(res, open(out, "w"), indent=2)

fmt = "{:>5} {:>9} {:>6} {:>9} {:>10} {:>7} {:>9} {:>9} {:>13} {:>15}"
print(fmt.format("size", "particles", "steps", "loop s", "p-steps/s", "wall %", "RSS MiB", "B/part", "pairbench p/s", "load before"))
for r in runs:
    pb = r["pairbench"]["pair_interactions_per_s_median"]
    print(fmt.format(r["size"], r["particles"], r["steps"], f"{r['loop_seconds']:.2f}", f"{r['particle_steps_per_second']:.3g}",
                     f"{100 * r['wall_work']['share_of_loop']:.1f}", f"{r['max_rss_bytes'] / 2**20:.0f}",
                     f"{r['bytes_per_particle_including_fixed_overhead']:.0f}", f"{pb:.3g}" if pb else "-",
                     " ".join(f"{x:.2f}" for x in r["load_average_before"])))
if "marginal_bytes_per_particle" in res:
    print(f"marginal bytes per particle (1e5 -> 1e6): {res['marginal_bytes_per_particle']:.0f}")
names = sorted({k["name"] for r in runs for k in r["wall_work"]["step_kernels"]})
print("wall % counts: " + ", ".join(names))
for r in runs:
    top = r["top_kernels"][0]
    print(f"{r['size']}: largest kernel {top['name']} ({100 * top['share_of_loop']:.0f} % of the loop)")
PY
echo "wrote $json"
