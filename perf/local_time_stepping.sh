#!/usr/bin/env bash
# Local time stepping by level against one global step (refinement.local_time_stepping;
# docs/apr.md): a refined case run both ways, alternating, RUNS times each, 2 threads, beside the
# yardstick pair loop ../shared/perf/pairbench.cpp (300 x 300, R = 4 dx, median of 3). For each
# run: wall and CPU seconds, steps, each level's steps and SPH particle-steps
# (summary.json level_particle_steps), list builds, and the case's error figures; the medians'
# ratios (local over global). Writes perf/results/local-time-stepping-<date>.json.
# (a case with a time-averaged reference needs --set reference.from=T, T < the duration)
# usage: perf/local_time_stepping.sh [--case cases/cylinder_re100_apr_2d.yaml] [--duration 0.01]
#                                    [--runs 1] [--set KEY=VALUE ...] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
case_file="$here/cases/cylinder_re100_apr_2d.yaml"; duration=0.01; runs=1; out="$here/perf/results"; sets=()
while [ $# -gt 0 ]; do
  case $1 in
    --case) case_file=$2; shift 2 ;;
    --duration) duration=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "perf/local_time_stepping.sh: unknown option $1 (see the header of the script)" >&2; exit 2 ;;
  esac
done
ondine=${ONDINE:-$here/build/ondine}
[ -x "$ondine" ] || { echo "perf/local_time_stepping.sh: build first (make build): no $ondine" >&2; exit 2; }
mkdir -p "$out"
stamp=$(date +%Y%m%d-%H%M%S)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=2
: > "$work/pairbench"
if [ -f "$here/../shared/perf/pairbench.cpp" ]; then
  g++ -O3 -march=native -fopenmp "$here/../shared/perf/pairbench.cpp" -o "$work/pb"
  for r in 1 2 3; do "$work/pb" 300 20 >> "$work/pairbench"; done
fi
for r in $(seq 1 "$runs"); do
  for mode in false true; do
    "$ondine" run "$case_file" --quiet --out "$work/${mode}_$r" --set time.duration="$duration" \
      --set refinement.local_time_stepping=$mode "${sets[@]}" > "$work/${mode}_$r.log" 2>&1 ||
      { echo "perf/local_time_stepping.sh: the run failed (local_time_stepping=$mode): $work/${mode}_$r.log" >&2; cat "$work/${mode}_$r.log" >&2; exit 1; }
  done
done
/usr/bin/python3 - "$work" "$runs" "$case_file" "$duration" "$out/local-time-stepping-$stamp.json" "${sets[@]}" <<'EOF'
import json, os, statistics, sys
work, runs, case, duration, dest = sys.argv[1], int(sys.argv[2]), sys.argv[3], float(sys.argv[4]), sys.argv[5]
def summary(mode, r):
    s = json.load(open(os.path.join(work, f"{mode}_{r}", "summary.json")))
    ref = s.get("refinement", {})
    return {"wall_seconds": s["wall_seconds"], "cpu_seconds": s.get("cpu_seconds"), "loop_seconds": s["loop_seconds"],
            "steps": s["steps"], "level_steps": ref.get("level_steps"), "level_particle_steps": s.get("level_particle_steps"),
            "neighbour_list_builds": s["neighbour_list_builds"], "particles": ref.get("particles"), "errors": s["errors"]}
result = {"case": os.path.relpath(case), "duration": duration, "sets": sys.argv[6:], "threads": 2, "runs": runs,
          "global": [summary("false", r) for r in range(1, runs + 1)], "local": [summary("true", r) for r in range(1, runs + 1)]}
med = lambda xs: statistics.median(xs)
for key in ("wall_seconds", "cpu_seconds", "loop_seconds"):
    g, l = med([x[key] for x in result["global"]]), med([x[key] for x in result["local"]])
    result[f"median_{key}"] = {"global": g, "local": l, "local_over_global": l / g}
work_g = sum(result["global"][0]["level_particle_steps"]); work_l = sum(result["local"][0]["level_particle_steps"])
result["particle_steps"] = {"global": work_g, "local": work_l, "local_over_global": work_l / work_g}
yard = [json.loads(line) for line in open(os.path.join(work, "pairbench")) if line.startswith("{")]
result["yardstick"] = {"source": "../shared/perf/pairbench.cpp 300 20, 2 threads",
                       "median_pair_interactions_per_s": statistics.median([y["pair_interactions_per_s"] for y in yard]) if yard else None,
                       "runs": yard}
json.dump(result, open(dest, "w"), indent=1)
print(f"{dest}: CPU s global {result['median_cpu_seconds']['global']:.1f}, local {result['median_cpu_seconds']['local']:.1f} "
      f"(ratio {result['median_cpu_seconds']['local_over_global']:.3f}); particle-steps ratio {result['particle_steps']['local_over_global']:.3f}")
EOF
