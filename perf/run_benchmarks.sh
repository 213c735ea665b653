#!/usr/bin/env bash
# Runs the solver-core benchmark and, in the same session, the hand-written
# OpenMP pair loop used as the yardstick (shared/perf/pairbench.cpp, if present
# beside the checkout), and writes perf/results/<date>.json. Usage:
#   perf/run_benchmarks.sh [--quick]
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-$(nproc)} OMP_PROC_BIND=spread OMP_PLACES=threads
mkdir -p perf/results
stamp=$(date +%Y%m%d-%H%M%S)
out=perf/results/bench-$stamp.json
build/perf/ondine_bench "$@" --out "$out.ondine"
yard=""
if [ -f ../shared/perf/pairbench.cpp ]; then
  g++ -O3 -march=native -fopenmp ../shared/perf/pairbench.cpp -o build/perf/pairbench
  # same particle count and R/dx as the pairbench_like_2d_R4dx run
  side=300; [ "${1:-}" = "--quick" ] && side=100
  yard=$(for r in 1 2 3; do build/perf/pairbench $side 20; done | python3 -c '
import json, sys
runs = [json.loads(l) for l in sys.stdin if l.strip().startswith("{")]
print(json.dumps(runs))')
fi
python3 - "$out.ondine" "$out" "$yard" <<'PY'
import json, statistics, sys
res = json.load(open(sys.argv[1]))
if sys.argv[3]:
    yard = json.loads(sys.argv[3])
    res["pairbench"] = yard
    key = next((k for k in yard[0] if "pair" in k and "per_s" in k), None)
    if key:
        med = statistics.median(r[key] for r in yard)
        ours = next(r for r in res["runs"] if r["case"].startswith("pairbench_like"))
        res["ratios"]["ondine_over_pairbench_pairs_per_second"] = ours["pair_interactions_per_second"] / med
json.dump(res, open(sys.argv[2], "w"), indent=2)
print(json.dumps(res["ratios"], indent=2))
PY
rm -f "$out.ondine"
echo "wrote $out"
