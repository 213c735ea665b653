#!/usr/bin/env bash
# Time to solution on the 2D dam break (cases/dam_break_2d.yaml, Martin & Moyce): the front's
# RMS relative error over the 13 measured points with T <= 3 against wall time, for each
# scheme choice and resolution, beside the yardstick pair loop ../shared/perf/pairbench.cpp
# (300 x 300, R = 4 dx, 2 threads, median of 3) and, where ../shared/peer/ is present, the
# peer DualSPHysics 5.4 CPU on its own 2D dam break at the same resolution, alternating
# runs (peer, then each scheme, RUNS times) and quoting the ratio of the medians.
# Schemes (all RK4): "defaults" (the solver's defaults: acoustic CFL 0.375, the density gradient
# at every stage), "cfl0.75" (twice the acoustic step; skipped at widths of 100 and more) and
# "case" (the case file as shipped: CFL 0.75 and scheme.density_gradient: step) and "riemann"
# (Riemann-SPH of Leduc et al. with MUSCL, scheme.flux: riemann, at acoustic CFL 0.5 with the
# gradients at every stage; the case's artificial viscosity kept). --schemes picks a subset.
# With --dx3d, the 3D dam break (SPHERIC Test 2, cases/spheric_test2_3d.yaml, 2 s) at each
# spacing, alternating with the peer on the same geometry (../shared/peer/run_test2_3d.sh OUT DP,
# its sensors by sensors_test2_3d.sh), RUNS3D times: peer, then each of --schemes3d ("defaults":
# the case as shipped; "fast": CFL 0.75 with the density gradient once per step; "fast_exact": the
# same with time.output_at: exact, every step cut to land on the 2 ms sensor instants). Both codes'
# H2, H4 RMS errors, P1/P3 first-impact peaks and the P1 impulse over 0.35-0.60 s against the
# measured series by one rule (perf/test2_metrics.py), the ratio of the medians of the wall times
# (the peer's includes GenCase, Ondine's its set-up), particle-steps/s and pair interactions/s.
# Widths "" skips the 2D part.
# Writes perf/results/time-to-solution-<date>.json and .png.
# usage: perf/time_to_solution.sh [--widths "25 50 100"] [--runs 3] [--schemes "defaults cfl0.75 case riemann"]
#                                 [--dx3d "0.04 0.03"] [--runs3d 1] [--schemes3d "fast"] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
widths="25 50 100"; runs=3; dx3d=""; out="$here/perf/results"; schemes_asked="defaults cfl0.75 case riemann"
runs3d=1; schemes3d="fast"
while [ $# -gt 0 ]; do
  case $1 in
    --widths) widths=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --dx3d) dx3d=$2; shift 2 ;;
    --schemes) schemes_asked=$2; shift 2 ;;
    --runs3d) runs3d=$2; shift 2 ;;
    --schemes3d) schemes3d=$2; shift 2 ;;
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
declare -A sets=([defaults]="--set scheme.cfl.acoustic=0.375 --set scheme.density_gradient=stage"
                 [cfl0.75]="--set scheme.cfl.acoustic=0.75 --set scheme.density_gradient=stage"
                 [case]=""
                 [riemann]="--set scheme.flux=riemann --set scheme.delta_sph=0 --set scheme.density_gradient=stage --set scheme.cfl.acoustic=0.5")
for s in $schemes_asked; do
  [ -n "${sets[$s]+x}" ] || { echo "perf/time_to_solution.sh: unknown scheme '$s' in --schemes (expected some of: ${!sets[*]})" >&2; exit 2; }
done
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
    schemes=$schemes_asked
    [ "$w" -ge 100 ] && schemes=${schemes/cfl0.75/}
    for s in $schemes; do
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
# the flux pass's pair interactions (particles x mean neighbours, both ways, x 4 evaluations per
# RK4 step x steps) over the whole loop's time, every other pass included (the density-gradient
# and wall passes read the same pairs again and are not counted); the flux pass's own rate, over
# its kernel time alone: perf/flux_pair_rate.sh
pairs = s["particles"] * s.get("mean_neighbours", 0.0) * 4 * s["total_steps"] / s["loop_seconds"]
gradient_passes = 1 if scheme == "case" else 4  # (with riemann the pass also gathers grad u)
print(json.dumps({"code": "ondine", "scheme": scheme, "width": int(w), "run": int(r), "wall_seconds": s["wall_seconds"],
                  "loop_seconds": s["loop_seconds"], "steps": s["total_steps"], "particles": s["particles"],
                  "mean_neighbours": s.get("mean_neighbours", 0.0), "flux_pairs_per_second": pairs,
                  "neighbour_pair_passes_per_step": 4 + gradient_passes,
                  "particle_steps_per_second": s["particles"] * s["total_steps"] / s["loop_seconds"],
                  "front_rms_error": rms, "points": len(pts)}))
PY
    done
  done
done
declare -A sets3=([defaults]="" [fast]="--set scheme.cfl.acoustic=0.75 --set scheme.density_gradient=step"
                  [fast_exact]="--set scheme.cfl.acoustic=0.75 --set scheme.density_gradient=step --set time.output_at=exact")
for s in $schemes3d; do
  [ -n "${sets3[$s]+x}" ] || { echo "perf/time_to_solution.sh: unknown scheme '$s' in --schemes3d (expected some of: ${!sets3[*]})" >&2; exit 2; }
done
measured="$here/cases/reference/spheric_test2_kleefsman2005.csv"
for d3 in $dx3d; do
  for r in $(seq "$runs3d"); do
    if [ -x "$peer/run_test2_3d.sh" ]; then
      t0=$(date +%s.%N)
      "$peer/run_test2_3d.sh" "$work/peer3d" "$d3" > /dev/null
      t1=$(date +%s.%N)
      "$peer/sensors_test2_3d.sh" "$work/peer3d" > /dev/null
      "$py" - "$work/peer3d" "$d3" "$r" "$("$py" -c "print($t1 - $t0)")" "$measured" "$here/perf/test2_metrics.py" >> "$work/runs" <<'PY'
import json, re, subprocess, sys
d, dx, r, wall, ref, metrics = sys.argv[1:7]
f = json.loads(subprocess.run([sys.executable, metrics, "peer", d, ref], check=True, capture_output=True, text=True).stdout)
log = open(d + "/gencase.log").read()
total = int(re.search(r"Total particles: (\d+)", log).group(1))
bound = int(re.search(r"bound=(\d+)", log).group(1))
steps = re.search(r"Steps per second[. :]*([0-9.eE+-]+)", open(d + "/run.log").read())
print(json.dumps({"code": "peer", "case": "spheric_test2_3d", "scheme": "DualSPHysics 5.4 CPU", "dx": float(dx), "run": int(r),
                  "wall_seconds": float(wall), "particles": total, "wall_particles": bound, **f}))
PY
    fi
    for s in $schemes3d; do
      # shellcheck disable=SC2086
      "$ondine" run "$here/cases/spheric_test2_3d.yaml" --out "$work/3d_$s" --quiet --set discretisation.dx="$d3" ${sets3[$s]} > /dev/null 2>&1
      "$py" - "$work/3d_$s" "$s" "$d3" "$r" "$measured" "$here/perf/test2_metrics.py" >> "$work/runs" <<'PY'
import json, subprocess, sys
d, scheme, dx, r, ref, metrics = sys.argv[1:7]
f = json.loads(subprocess.run([sys.executable, metrics, "ondine", d, ref], check=True, capture_output=True, text=True).stdout)
s = json.load(open(d + "/summary.json"))
evals = 4 * s["total_steps"]
print(json.dumps({"code": "ondine", "case": "spheric_test2_3d", "scheme": scheme, "dx": float(dx), "run": int(r),
                  "wall_seconds": s["wall_seconds"], "loop_seconds": s["loop_seconds"], "steps": s["total_steps"],
                  "particles": s["particles"], "mean_neighbours": s.get("mean_neighbours", 0.0),
                  "particle_steps_per_second": s["particles"] * s["total_steps"] / s["loop_seconds"],
                  "flux_pairs_per_second": s["particles"] * s.get("mean_neighbours", 0.0) * evals / s["loop_seconds"],
                  "neighbour_pair_passes_per_step": 8 if scheme == "defaults" else 5, **f}))
PY
    done
  done
done
"$py" - "$work/runs" "$work/pairbench" "$out/time-to-solution-$stamp" <<'PY'
import json, statistics, sys
runs = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
yard = [json.loads(l)["pair_interactions_per_s"] for l in open(sys.argv[2]) if l.strip().startswith("{")]
stem = sys.argv[3]
runs3 = [r for r in runs if r.get("case") == "spheric_test2_3d"]
runs = [r for r in runs if "case" not in r]
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
for r in runs3:
    if yard and r["code"] == "ondine":
        r["flux_pair_rate_over_yardstick"] = r["flux_pairs_per_second"] / statistics.median(yard)
groups3 = {}
for r in runs3:
    groups3.setdefault((r["dx"], r["code"], r["scheme"]), []).append(r)
table3 = []
figs = ("H2_rms_error", "H4_rms_error", "P1_peak", "P1_peak_time", "P3_peak", "P1_impulse", "P1_impulse_relative_error", "steps", "particles")
for (dx, code, scheme), rs in sorted(groups3.items(), key=lambda g: (-g[0][0], g[0][1] != "peer", g[0][2])):
    row = {"dx": dx, "code": code, "scheme": scheme, "runs": len(rs), "wall_seconds": [x["wall_seconds"] for x in rs],
           "wall_seconds_median": statistics.median(x["wall_seconds"] for x in rs)}
    row.update({k: rs[0][k] for k in figs if k in rs[0]})
    peer = [x["wall_seconds"] for x in runs3 if x["dx"] == dx and x["code"] == "peer"]
    if peer and code == "ondine":
        row["time_over_peer"] = row["wall_seconds_median"] / statistics.median(peer)
    table3.append(row)
json.dump({"yardstick_pairs_per_second_median": statistics.median(yard) if yard else None, "summary": table, "runs": runs,
           "spheric_test2_3d_summary": table3, "spheric_test2_3d": runs3}, open(stem + ".json", "w"), indent=1)
for row in table + table3:
    print(json.dumps(row))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = (1 if table else 0) + (1 if runs3 else 0)
    fig, axes = plt.subplots(1, panels, figsize=(5.5 * panels, 4), squeeze=False)
    if table:
        ax = axes[0][0]
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
    if runs3:
        ax = axes[0][panels - 1]
        for scheme in sorted({r["scheme"] for r in table3}):
            for h, mk in (("H2", "o-"), ("H4", "^:")):
                pts = sorted((r["wall_seconds_median"], r[h + "_rms_error"]) for r in table3 if r["scheme"] == scheme and r.get(h + "_rms_error"))
                if pts:
                    ax.loglog(*zip(*pts), mk, label="%s %s" % ("DualSPHysics" if "Dual" in scheme else "Ondine " + scheme, h))
        ax.set_xlabel("wall time (s), median, 2 threads")
        ax.set_ylabel("RMS error / initial height")
        ax.set_title("SPHERIC Test 2 (3D dam break), dx = " + ", ".join(sorted({"%g" % r["dx"] for r in runs3})) +
                     (" (pairbench %.3g pairs/s)" % statistics.median(yard) if yard else ""), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(stem + ".png", dpi=90)
except ImportError:
    print("python3-matplotlib is missing: no plot", file=sys.stderr)
PY
echo "wrote $out/time-to-solution-$stamp.json and .png"
