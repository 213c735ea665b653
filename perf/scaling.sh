#!/usr/bin/env bash
# Strong and weak scaling of distributed runs on a dam break, the resolution set by
# the particle count: the 2D dam break (cases/dam_break_2d.yaml) or, with --dim 3, the
# 3D dam break on a box of SPHERIC Test 2 (cases/spheric_test2_3d.yaml, its walls):
#   strong: a fixed problem of PARTICLES particles on each rank count;
#   weak:   PER_RANK particles per rank.
# Each rank runs one OpenMP thread, so that ranks are the only parallelism
# measured; a rank count above the machine's cores is run oversubscribed and
# labelled so. Writes OUT/scaling-<date>.json (one object per run: time per step,
# the shares of the loop in halo exchange, migration and rebalancing, the balance),
# a markdown table and a PNG of the efficiencies (python3-matplotlib).
# usage: perf/scaling.sh [--dim 2|3] [--ranks "1 2"] [--particles 200000] [--per-rank 100000]
#                        [--steps 60] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
ranks="1 2"; particles=200000; per_rank=100000; steps=60; out="$here/perf/results"; dim=2
while [ $# -gt 0 ]; do
  case $1 in
    --dim) dim=$2; shift 2 ;;
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
cores=$(getconf _NPROCESSORS_ONLN)  # not nproc, which reads OMP_NUM_THREADS
if [ "$dim" = 3 ]; then
  case_file="$here/cases/spheric_test2_3d.yaml"
  dx_for() { "$py" -c "print((1.228 * 1.0 * 0.55 / $1) ** (1.0 / 3.0))"; }  # the column is 1.228 x 1 x 0.55 m
else
  case_file="$here/cases/dam_break_2d.yaml"
  a=0.05715  # water column width (m); the column is a x 2a, so N = 2 (a/dx)^2
  dx_for() { "$py" -c "import math; print($a / math.sqrt($1 / 2.0))"; }
fi
run() {  # run KIND NP N
  local kind=$1 np=$2 n=$3 dx dir
  dx=$(dx_for "$n"); dir="$work/$kind-$np"
  mpirun --allow-run-as-root --oversubscribe -np "$np" "$ondine" run "$case_file" --out "$dir" --quiet \
    --set discretisation.dx="$dx" --set time.max_steps="$steps" --set time.output_interval=10 > /dev/null 2>&1
  "$py" - "$dir/summary.json" "$kind" "$np" "$dim" "$cores" >> "$json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
c = s["checkpoints"]
p = s["parallel"]
print(json.dumps({"kind": sys.argv[2], "ranks": int(sys.argv[3]), "dimension": int(sys.argv[4]),
                  "oversubscribed": int(sys.argv[3]) > int(sys.argv[5]), "particles": s["particles"], "steps": s["steps"],
                  "loop_seconds": s["loop_seconds"], "seconds_per_step": s["loop_seconds"] / s["steps"],
                  "particle_steps_per_second": s["particle_steps_per_second"],
                  "exchange_share": p["exchange_share_of_loop"], "halo_share": p.get("halo_share_of_loop", 0.0),
                  "migration_share": p.get("migration_share_of_loop", 0.0), "rebalance_share": p.get("rebalance_share_of_loop", 0.0),
                  "balance_tau": p["balance_tau"],
                  "checkpoint_seconds_per_million": c["seconds"] / max(c["count"], 1) / s["particles"] * 1e6}))
PY
  tail -1 "$json"
}
for np in $ranks; do run strong "$np" "$particles"; done
for np in $ranks; do run weak "$np" $((per_rank * np)); done
"$py" "$here/perf/plot_scaling.py" "$json" "$out/scaling-$stamp"
echo "wrote $json, $out/scaling-$stamp.md and .png"
