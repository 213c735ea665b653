#!/usr/bin/env bash
# The flux pass's pair rate against the yardstick pair loop ../shared/perf/pairbench.cpp, in one
# sitting: the pairs the flux pass evaluates per second of its own kernel time (particles x mean
# neighbours within R, both ways, x evaluations, over the seconds of the ondine::Flux kernel in
# `ondine run --profile`), with the full and the half neighbour list (scheme.pair_list), on
#   2D: the dam break as shipped (cases/dam_break_2d.yaml, a/50, 5 000 particles), and
#   3D: SPHERIC Test 2 at dx = 0.04 m to t = 0.6 s (cases/spheric_test2_3d.yaml, 10 500 particles),
# RUNS runs each, alternating (full, half), the yardstick 3 times before and once after; medians.
# Also each run's whole-loop time, so the saving on the whole run is read in the same sitting.
# Writes perf/results/flux-pair-rate-<date>.json.
# usage: perf/flux_pair_rate.sh [--runs 3] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
runs=3; out="$here/perf/results"
while [ $# -gt 0 ]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "perf/flux_pair_rate.sh: unknown option $1 (see the header of the script)" >&2; exit 2 ;;
  esac
done
ondine=${ONDINE:-$here/build/ondine}
[ -x "$ondine" ] || { echo "perf/flux_pair_rate.sh: build first (make build): no $ondine" >&2; exit 2; }
yard_src="$here/../shared/perf/pairbench.cpp"
[ -f "$yard_src" ] || { echo "perf/flux_pair_rate.sh: the yardstick $yard_src is not beside the checkout" >&2; exit 2; }
mkdir -p "$out"
stamp=$(date +%Y%m%d-%H%M%S)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=2
g++ -O3 -march=native -fopenmp "$yard_src" -o "$work/pb"
for r in 1 2 3; do "$work/pb" 300 20 >> "$work/pairbench"; done
for r in $(seq 1 "$runs"); do
  for list in full half; do
    "$ondine" run "$here/cases/dam_break_2d.yaml" --set scheme.pair_list=$list --profile --quiet --out "$work/2d_${list}_$r" > /dev/null 2>&1
    "$ondine" run "$here/cases/spheric_test2_3d.yaml" --set discretisation.dx=0.04 --set time.duration=0.6 \
      --set scheme.pair_list=$list --profile --quiet --out "$work/3d_${list}_$r" > /dev/null 2>&1
  done
done
"$work/pb" 300 20 >> "$work/pairbench"
/usr/bin/python3 - "$work" "$runs" "$out/flux-pair-rate-$stamp.json" <<'PY'
import json, statistics, sys
work, runs, dest = sys.argv[1], int(sys.argv[2]), sys.argv[3]
yard = [json.loads(l)["pair_interactions_per_s"] for l in open(work + "/pairbench") if l.strip().startswith("{")]
rows, summary = [], {}
for case in ("2d", "3d"):
    for lst in ("full", "half"):
        rs = []
        for r in range(1, runs + 1):
            d = "%s/%s_%s_%d" % (work, case, lst, r)
            s = json.load(open(d + "/summary.json"))
            k = json.load(open(d + "/profile_kernels.json"))
            flux = [x for x in k["kernels"] if x["name"].startswith("ondine::Flux[")]
            fs = sum(x["seconds"] for x in flux)
            calls = flux[0]["calls"]
            pairs = s["particles"] * s["mean_neighbours"] * calls
            rs.append({"case": case, "pair_list": lst, "run": r, "particles": s["particles"], "mean_neighbours": s["mean_neighbours"],
                       "steps": s["total_steps"], "flux_evaluations": calls, "flux_seconds": fs, "loop_seconds": s["loop_seconds"],
                       "flux_pairs_per_second": pairs / fs, "flux_share_of_kernels": fs / k["kernel_seconds"]})
        rows += rs
        summary["%s_%s" % (case, lst)] = {
            "flux_pairs_per_second_median": statistics.median(x["flux_pairs_per_second"] for x in rs),
            "flux_seconds_median": statistics.median(x["flux_seconds"] for x in rs),
            "loop_seconds_median": statistics.median(x["loop_seconds"] for x in rs),
            "over_yardstick": statistics.median(x["flux_pairs_per_second"] for x in rs) / statistics.median(yard)}
    summary[case + "_half_over_full_loop_seconds"] = summary[case + "_half"]["loop_seconds_median"] / summary[case + "_full"]["loop_seconds_median"]
res = {"yardstick_pairs_per_second": yard, "yardstick_median": statistics.median(yard), "threads": 2, "summary": summary, "runs": rows}
json.dump(res, open(dest, "w"), indent=1)
print("yardstick (pairbench 300 x 300, R = 4 dx): median %.3g pairs/s of %s" % (res["yardstick_median"], ", ".join("%.3g" % y for y in yard)))
for key, v in summary.items():
    if isinstance(v, dict):
        print("%-8s flux %.3g pairs/s (%.2f of the yardstick), flux pass %.2f s, loop %.2f s (medians)" %
              (key, v["flux_pairs_per_second_median"], v["over_yardstick"], v["flux_seconds_median"], v["loop_seconds_median"]))
    else:
        print("%s %.3f" % (key, v))
print("->", dest)
PY
