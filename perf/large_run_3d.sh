#!/usr/bin/env bash
# A large 3D run on this machine, end to end: the 3D dam break on a box of SPHERIC Test 2
# (cases/spheric_test2_3d.yaml, its walls and sensors) at about PARTICLES particles, STEPS
# steps on 2 OpenMP threads, with the run's own memory estimate and refusal (its second
# line), its progress and ETA on stderr (kept in the JSON's folder as run.log), and
# /usr/bin/time -v for the peak memory. Right before, the yardstick pair loop
# ../shared/perf/pairbench.cpp (300 x 300, R = 4 dx, 3 runs, median). Writes
# perf/results/large-run-3d-<date>.json: particles, steps, seconds per step,
# particle-steps/s, peak resident memory, bytes per particle, the estimate, the yardstick.
# --set KEY=VALUE (repeatable) passes an override to the run (e.g. scheme.pair_list=full).
# usage: perf/large_run_3d.sh [--particles 1000000] [--steps 20] [--set KEY=VALUE ...] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
particles=1000000; steps=20; out="$here/perf/results"; sets=()
while [ $# -gt 0 ]; do
  case $1 in
    --particles) particles=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    *) echo "perf/large_run_3d.sh: unknown option $1 (see the header of the script)" >&2; exit 2 ;;
  esac
done
ondine=${ONDINE:-$here/build/ondine}
[ -x "$ondine" ] || { echo "perf/large_run_3d.sh: build first (make build): no $ondine" >&2; exit 2; }
py=/usr/bin/python3
mkdir -p "$out"
stamp=$(date +%Y%m%d-%H%M%S)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
: > "$work/pairbench"
if [ -f "$here/../shared/perf/pairbench.cpp" ]; then
  g++ -O3 -march=native -fopenmp "$here/../shared/perf/pairbench.cpp" -o "$work/pb"
  for r in 1 2 3; do OMP_NUM_THREADS=2 "$work/pb" 300 20 >> "$work/pairbench"; done
fi
dx=$("$py" -c "print((1.228 * 1.0 * 0.55 / $particles) ** (1.0 / 3.0))")  # the column is 1.228 x 1 x 0.55 m
load_before=$(cut -d' ' -f1 /proc/loadavg)
OMP_NUM_THREADS=2 /usr/bin/time -v -o "$work/time" "$ondine" run "$here/cases/spheric_test2_3d.yaml" --out "$work/run" \
  --set discretisation.dx="$dx" --set time.max_steps="$steps" --set time.output_interval=1000 "${sets[@]}" 2> "$work/run.log"
load_after=$(cut -d' ' -f1 /proc/loadavg)
cp "$work/run.log" "$out/large-run-3d-$stamp.log"
"$py" - "$work" "$dx" "$load_before" "$load_after" > "$out/large-run-3d-$stamp.json" <<'PY'
import json, re, statistics, sys
work, dx, lb, la = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
s = json.load(open(f"{work}/run/summary.json"))
rss_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(f"{work}/time").read()).group(1))
log = open(f"{work}/run.log").read()
estimate = next((l[len("ondine: "):] for l in log.splitlines() if l.startswith("ondine: memory:")), "")
yard = [json.loads(l) for l in open(f"{work}/pairbench") if l.strip().startswith("{")]
rates = [y["pair_interactions_per_s"] for y in yard]
print(json.dumps({
    "case": "spheric_test2_3d", "dx": dx, "pair_list": s.get("scheme", {}).get("pair_list", "full"), "particles": s["particles"], "steps": s["total_steps"], "threads": s.get("threads"),
    "loop_seconds": s["loop_seconds"], "seconds_per_step": s["loop_seconds"] / s["total_steps"],
    "particle_steps_per_second": s["particle_steps_per_second"], "peak_rss_bytes": rss_kb * 1024,
    "bytes_per_particle_including_fixed_overhead": rss_kb * 1024 / s["particles"], "memory_estimate": estimate,
    "wall_seconds": s["wall_seconds"], "yardstick_pairs_per_second_median": statistics.median(rates) if rates else None,
    "load_before": float(lb), "load_after": float(la)}, indent=1))
PY
cat "$out/large-run-3d-$stamp.json"
