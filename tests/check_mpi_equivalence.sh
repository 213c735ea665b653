#!/usr/bin/env bash
# 1-, 2- and 4-rank runs of the same case give the same particles: after N steps
# every field of the last snapshot agrees within TOL relative (matched by id).
# usage: check_mpi_equivalence.sh ONDINE COMPARE CASE OUT STEPS TOL [--set ...]
# COMPARE_FIELDS (environment, optional): the snapshot fields compared (default: ondine_compare's)
# COMPARE_WALLS=1 (environment, optional): walls.csv's last rows agree too (pressure and viscous parts,
# moments), within TOL of the row's largest value
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
    /usr/bin/python3 - "$out/np1/walls.csv" "$out/np$np/walls.csv" "$tol" <<'PY'
import sys
rows = [open(f).read().split("\n") for f in sys.argv[1:3]]
names = rows[0][0].split(",")
cols = range(2, len(names))  # after time, step
a, b = ([float(v) for v in r[-2].split(",")] for r in rows)
tol, scale = float(sys.argv[3]), max(abs(a[k]) for k in cols)
worst = max(abs(a[k] - b[k]) for k in cols)
print("walls.csv, last row: largest difference %.3g against the largest value %.3g" % (worst, scale))
sys.exit(0 if a[:2] == b[:2] and worst <= tol * scale else 1)
PY
  fi
done
