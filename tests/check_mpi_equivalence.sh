#!/usr/bin/env bash
# 1-, 2- and 4-rank runs of the same case give the same particles: after N steps
# every field of the last snapshot agrees within TOL relative (matched by id).
# usage: check_mpi_equivalence.sh ONDINE COMPARE CASE OUT STEPS TOL [--set ...]
# COMPARE_FIELDS (environment, optional): the snapshot fields compared (default: ondine_compare's)
# COMPARE_WALLS=1 (environment, optional): the last rows of walls.csv (pressure and viscous parts,
# moments) and, where the case has wall sensors, of wall_sensors.csv agree too, each within TOL (at
# least 1e-11: the files' 12 digits) of its row's largest value
set -euo pipefail
ondine=$1; compare=$2; case_file=$3; out=$4; steps=$5; tol=$6; shift 6
mpirun=(mpirun --allow-run-as-root --oversubscribe)
export OMP_NUM_THREADS=1
rm -rf "$out"
for np in 1 2 4; do
  "${mpirun[@]}" -np $np "$ondine" run "$case_file" --out "$out/np$np" --quiet --set time.max_steps=$steps "$@"
done
last=$(ls "$out/np1"/*_0*.h5 | sort | tail -1); last=$(basename "$last")
for np in 2 4; do
  echo "1 rank vs $np ranks ($last):"
  "$compare" "$out/np1/$last" "$out/np$np/$last" "$tol" ${COMPARE_FIELDS:-}
  if [ "${COMPARE_WALLS:-0}" = 1 ]; then
    /usr/bin/python3 - "$out/np1" "$out/np$np" "$tol" <<'PY'
import math, os, sys
if not os.path.exists(os.path.join(sys.argv[1], "walls.csv")):
    sys.exit("COMPARE_WALLS=1: no walls.csv in " + sys.argv[1])
bad = 0
for name in ("walls.csv", "wall_sensors.csv"):
    if not os.path.exists(os.path.join(sys.argv[1], name)):
        continue
    rows = [open(os.path.join(d, name)).read().split("\n") for d in sys.argv[1:3]]
    names = rows[0][0].split(",")
    cols = range(2, len(names))  # after time, step
    a, b = ([float(v) for v in r[-2].split(",")] for r in rows)
    # the files hold 12 significant digits: a last-digit flip is 1e-12 of a value
    tol, scale = max(float(sys.argv[3]), 1e-11), max(abs(a[k]) for k in cols)
    diffs = [abs(a[k] - b[k]) for k in cols]
    worst = float("nan") if any(math.isnan(d) for d in diffs) else max(diffs)  # a NaN fails
    print("%s, last row: largest difference %.3g against the largest value %.3g" % (name, worst, scale))
    bad |= not (a[1] == b[1] and abs(a[0] - b[0]) <= tol * abs(a[0]) and worst <= tol * scale)  # same step, time; NaN fails
sys.exit(bad)
PY
  fi
done
