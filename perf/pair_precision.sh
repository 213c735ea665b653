#!/usr/bin/env bash
# What single precision would buy the pair loop on this machine: the yardstick
# ../shared/perf/pairbench.cpp built twice, as written (double) and with every floating type and
# constant in single precision (storage and arithmetic: -DREAL=float -fsingle-precision-constant on
# a copy whose `double`s read `real`), run alternately RUNS times (300 x 300, R = 4 dx, 2 threads,
# EVALS evaluations). The upper bound of a mixed-precision pair loop's gain: a real one keeps
# double positions and sums. Writes perf/results/pair-precision-<date>.json (each run's pair
# rate and checksum, the medians and their ratio).
# usage: perf/pair_precision.sh [--runs 5] [--evals 10] [--out perf/results]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
runs=5; evals=10; out="$here/perf/results"
while [ $# -gt 0 ]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --evals) evals=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "perf/pair_precision.sh: unknown option $1 (see the head of the script)" >&2; exit 2 ;;
  esac
done
src="$here/../shared/perf/pairbench.cpp"
[ -f "$src" ] || { echo "perf/pair_precision.sh: no yardstick at $src" >&2; exit 2; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
sed -e 's/\bdouble\b/real/g' -e 's/1e-300/1e-30/' \
    -e 's/#include <random>/#include <random>\n#ifndef REAL\n#define REAL double\n#endif\nusing real = REAL;/' "$src" > "$work/pb.cpp"
g++ -O3 -march=native -fopenmp "$src" -o "$work/double"
g++ -O3 -march=native -fopenmp -DREAL=float -fsingle-precision-constant "$work/pb.cpp" -o "$work/float"
export OMP_NUM_THREADS=2
for r in $(seq "$runs"); do
  for p in double float; do echo "$p $("$work/$p" 300 "$evals")"; done
done > "$work/runs"
mkdir -p "$out"
/usr/bin/python3 - "$work/runs" "$out/pair-precision-$(date +%Y%m%d-%H%M%S).json" <<'PY'
import json, statistics, sys
runs = [dict(json.loads(l.split(" ", 1)[1]), precision=l.split(" ", 1)[0]) for l in open(sys.argv[1])]
med = {p: statistics.median(r["pair_interactions_per_s"] for r in runs if r["precision"] == p) for p in ("double", "float")}
res = {"runs": runs, "median_pairs_per_second": med, "float_over_double": med["float"] / med["double"]}
json.dump(res, open(sys.argv[2], "w"), indent=1)
print(json.dumps({"median_pairs_per_second": med, "float_over_double": res["float_over_double"]}))
print("wrote " + sys.argv[2])
PY
