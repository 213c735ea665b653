#!/usr/bin/env bash
# Time to solution on the 2D dam break (cases/dam_break_2d.yaml, Martin & Moyce): the front's
# RMS relative error over the 13 measured points with T <= 3 against wall time, for each
# scheme choice and resolution, beside the yardstick pair loop ../shared/perf/pairbench.cpp
# (300 x 300, R = 4 dx, 2 threads, median of 3) and, where ../shared/peer/ is present, the
# peer DualSPHysics 5.4 CPU on its own 2D dam break at the same resolution, alternating
# runs (peer, then each scheme, RUNS times) and quoting the ratio of the medians.
# Schemes: "rk4" (the default, acoustic CFL 0.375) and "rk4_cfl0.75" (the same, twice the
# acoustic step). Writes perf/results/time-to-solution-<date>.json and .png.
# usage: perf/time_to_solution.sh [--widths "25 50"] [--runs 3] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
widths="25 50"; runs=3; out="$here/perf/results"
while [ $# -gt 0 ]; do
  case $1 in
    --widths) widths=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "perf/time_to_solution.sh: unknown option $1 (see the header of the script)" >&2; exit 2 ;;
  esac
done
ondine=${ONDINE:-$here/build/ondine}
[ -x "$ondine" ] || { echo "perf/time_to_solution.sh: build first (make build): no $ondine" >&2; exit 2; }
py=/usr/bin/python3
peer="$here/../shared/peer"
mkdir -p "$out"
stamp=$(date +%Y%m%d-%H%M%S)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=2
: > "$work/pairbench"
if [ -f "$here/../shared/perf/pairbench.cpp" ]; then
  g++ -O3 -march=native -fopenmp "$here/../shared/perf/pairbench.cpp" -o "$work/pb"
  for r in 1 2 3; do "$work/pb" 300 20 >> "$work/pairbench"; done
fi
declare -A sets=([rk4]="" [rk4_cfl0.75]="--set scheme.cfl.acoustic=0.75")
: > "$work/runs"
for w in $widths; do
  dx=$("$py" -c "print(0.05715 / $w)")
  for r in $(seq "$runs"); do
    if [ -x "$peer/run_dambreak2d.sh" ]; then
      t0=$(date +%s.%N)
      "$peer/run_dambreak2d.sh" "$work/peer" "$("$py" -c "print(1.0 / $w)")" > /dev/null
      t1=$(date +%s.%N)
      echo "{\"code\": \"peer\", \"scheme\": \"DualSPHysics 5.4 CPU\", \"width\": $w, \"run\": $r, \"wall_seconds\": $("$py" -c "print($t1 - $t0)")}" >> "$work/runs"
    fi
    for s in rk4 rk4_cfl0.75; do
      # shellcheck disable=SC2086
      "$ondine" run "$here/cases/dam_break_2d.yaml" --out "$work/$s" --quiet --set discretisation.dx="$dx" ${sets[$s]} > /dev/null 2>&1
      "$py" - "$work/$s" "$s" "$w" "$r" "$here/cases/reference/martin_moyce1952_front_n2_2.csv" >> "$work/runs" <<'PY'
import csv, json, sys
d, scheme, w, r, ref = sys.argv[1:6]
pts = [l.strip().split(",") for l in open(ref) if l[0].isdigit()]
pts = [(float(a), float(b)) for a, b in pts if float(a) <= 3.0]
rows = list(csv.DictReader(open(d + "/front.csv")))
t = [float(x["T"]) for x in rows]; z = [float(x["Z"]) for x in rows]
def interp(T):
    for k in range(1, len(t)):
        if t[k] >= T:
            return z[k - 1] + (z[k] - z[k - 1]) * (T - t[k - 1]) / (t[k] - t[k - 1])
    return z[-1]
rms = (sum(((interp(T) - Z) / Z) ** 2 for T, Z in pts) / len(pts)) ** 0.5
s = json.load(open(d + "/summary.json"))
# pair interactions per second of the flux pass alone: particles x mean neighbours (both ways)
# x 4 evaluations per RK4 step x steps over the loop's time (the density-gradient and wall
# passes read the same pairs again and are not counted)
pairs = s["particles"] * s.get("mean_neighbours", 0.0) * 4 * s["total_steps"] / s["loop_seconds"]
print(json.dumps({"code": "ondine", "scheme": scheme, "width": int(w), "run": int(r), "wall_seconds": s["wall_seconds"],
                  "loop_seconds": s["loop_seconds"], "steps": s["total_steps"], "particles": s["particles"],
                  "mean_neighbours": s.get("mean_neighbours", 0.0), "flux_pairs_per_second": pairs,
                  "front_rms_error": rms, "points": len(pts)}))
PY
    done
  done
done
"$py" - "$work/runs" "$work/pairbench" "$out/time-to-solution-$stamp" <<'PY'
import json, statistics, sys
runs = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
yard = [json.loads(l)["pair_interactions_per_s"] for l in open(sys.argv[2]) if l.strip().startswith("{")]
stem = sys.argv[3]
groups = {}
for r in runs:
    groups.setdefault((r["width"], r["code"], r["scheme"]), []).append(r)
table = []
for (w, code, scheme), rs in sorted(groups.items()):
    row = {"width": w, "code": code, "scheme": scheme, "runs": len(rs),
           "wall_seconds_median": statistics.median(x["wall_seconds"] for x in rs)}
    if code == "ondine":
        row.update(front_rms_error=rs[0]["front_rms_error"], steps=rs[0]["steps"], particles=rs[0]["particles"],
                   flux_pairs_per_second_median=statistics.median(x["flux_pairs_per_second"] for x in rs))
        if yard:
            row["flux_pair_rate_over_yardstick"] = row["flux_pairs_per_second_median"] / statistics.median(yard)
    table.append(row)
for row in table:
    peer = [p for p in table if p["width"] == row["width"] and p["code"] == "peer"]
    if peer and row["code"] == "ondine":
        row["time_over_peer"] = row["wall_seconds_median"] / peer[0]["wall_seconds_median"]
json.dump({"yardstick_pairs_per_second_median": statistics.median(yard) if yard else None, "summary": table, "runs": runs},
          open(stem + ".json", "w"), indent=1)
for row in table:
    print(json.dumps(row))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for scheme in sorted({r["scheme"] for r in table if r["code"] == "ondine"}):
        pts = sorted((r["wall_seconds_median"], r["front_rms_error"]) for r in table if r["scheme"] == scheme)
        ax.loglog(*zip(*pts), "o-", label="Ondine " + scheme)
    # the peer's front error at a/50, a/100 (its README; its output is not read here)
    peer_err = {50: 0.120, 100: 0.132, 200: 0.138}
    pts = sorted((r["wall_seconds_median"], peer_err[r["width"]]) for r in table if r["code"] == "peer" and r["width"] in peer_err)
    if pts:
        ax.loglog(*zip(*pts), "s--", label="DualSPHysics 5.4 CPU (error from its README)")
    ax.set_xlabel("wall time (s), median, 2 threads")
    ax.set_ylabel("front RMS error vs Martin & Moyce")
    ax.set_title("2D dam break: error against time" + (" (pairbench %.3g pairs/s)" % statistics.median(yard) if yard else ""), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(stem + ".png", dpi=90)
except ImportError:
    print("python3-matplotlib is missing: no plot", file=sys.stderr)
PY
echo "wrote $out/time-to-solution-$stamp.json and .png"
