#!/usr/bin/env bash
# Strong and weak scaling of distributed runs on the 2D dam break
# (cases/dam_break_2d.yaml, the resolution set by the particle count):
#   strong: a fixed problem of PARTICLES particles on each rank count;
#   weak:   PER_RANK particles per rank.
# Each rank runs one OpenMP thread, so that ranks are the only parallelism
# measured. Writes OUT/scaling-<date>.json (one object per run), a markdown
# table and a PNG of the efficiencies (python3-matplotlib).
# usage: perf/scaling.sh [--ranks "1 2"] [--particles 200000] [--per-rank 100000]
#                        [--steps 60] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
ranks="1 2"; particles=200000; per_rank=100000; steps=60; out="$here/perf/results"
while [ $# -gt 0 ]; do
  case $1 in
    --ranks) ranks=$2; shift 2 ;;
    --particles) particles=$2; shift 2 ;;
    --per-rank) per_rank=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "perf/scaling.sh: unknown option $1 (see the header of the script)" >&2; exit 2 ;;
  esac
done
ondine=${ONDINE:-$here/build/ondine}
[ -x "$ondine" ] || { echo "perf/scaling.sh: build first (make build): no $ondine" >&2; exit 2; }
mkdir -p "$out"
stamp=$(date +%Y%m%d-%H%M%S)
json="$out/scaling-$stamp.json"; work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_PROC_BIND=spread OMP_PLACES=threads
py=${PYTHON:-/usr/bin/python3}  # Debian's, with python3-matplotlib
a=0.05715  # water column width (m); the column is a x 2a, so N = 2 (a/dx)^2
dx_for() { "$py" -c "import math; print($a / math.sqrt($1 / 2.0))"; }
run() {  # run KIND NP N
  local kind=$1 np=$2 n=$3 dx dir
  dx=$(dx_for "$n"); dir="$work/$kind-$np"
  mpirun --allow-run-as-root --oversubscribe -np "$np" "$ondine" run "$here/cases/dam_break_2d.yaml" --out "$dir" --quiet \
    --set discretisation.dx="$dx" --set time.max_steps="$steps" --set time.output_interval=10 > /dev/null 2>&1
  "$py" - "$dir/summary.json" "$kind" "$np" >> "$json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
c = s["checkpoints"]
print(json.dumps({"kind": sys.argv[2], "ranks": int(sys.argv[3]), "particles": s["particles"], "steps": s["steps"],
                  "loop_seconds": s["loop_seconds"], "seconds_per_step": s["loop_seconds"] / s["steps"],
                  "particle_steps_per_second": s["particle_steps_per_second"],
                  "exchange_share": s["parallel"]["exchange_share_of_loop"], "balance_tau": s["parallel"]["balance_tau"],
                  "checkpoint_seconds_per_million": c["seconds"] / max(c["count"], 1) / s["particles"] * 1e6}))
PY
  tail -1 "$json"
}
for np in $ranks; do run strong "$np" "$particles"; done
for np in $ranks; do run weak "$np" $((per_rank * np)); done
"$py" "$here/perf/plot_scaling.py" "$json" "$out/scaling-$stamp"
echo "wrote $json, $out/scaling-$stamp.md and .png"
