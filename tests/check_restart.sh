#!/usr/bin/env bash
# A run stopped after HALF steps and restarted from its checkpoint (on NP_RESTART
# ranks) ends where an uninterrupted run of STEPS steps ends (on NP ranks), within
# TOL relative (0: bitwise), field by field, particles matched by id.
# usage: check_restart.sh ONDINE COMPARE CASE OUT NP NP_RESTART STEPS HALF TOL [--set ...]
# COMPARE_FIELDS (environment, optional): the snapshot fields compared (default: ondine_compare's)
# COMPARE_SUMMARY (environment, optional): summary.json's figures (errors) that must agree too,
# within COMPARE_SUMMARY_TOL absolute (default 1e-8: figures over the whole run, made again from
# the CSV rows read back at the restart, which hold 12 significant digits)
set -euo pipefail
ondine=$1; compare=$2; case_file=$3; out=$4; np=$5; np2=$6; steps=$7; half=$8; tol=$9; shift 9
mpirun=(mpirun --allow-run-as-root --oversubscribe)
export OMP_NUM_THREADS=1
rm -rf "$out"
"${mpirun[@]}" -np "$np" "$ondine" run "$case_file" --out "$out/whole" --quiet --set time.max_steps=$steps \
  --set checkpoint.every_steps=$half "$@"
"${mpirun[@]}" -np "$np" "$ondine" run "$case_file" --out "$out/parts" --quiet --set time.max_steps=$half "$@"
"${mpirun[@]}" -np "$np2" "$ondine" run "$case_file" --out "$out/parts" --quiet --set time.max_steps=$steps \
  --restart "$out/parts/checkpoint.h5" "$@"
grep -q "\"restarted_from\"" "$out/parts/summary.json"
a=$(ls "$out/whole"/*_0*.h5 | sort | tail -1); b=$(ls "$out/parts"/*_0*.h5 | sort | tail -1)
echo "uninterrupted ($np ranks) vs restarted at step $half ($np -> $np2 ranks):"
"$compare" "$a" "$b" "$tol" ${COMPARE_FIELDS:-}
if [ -n "${COMPARE_SUMMARY:-}" ]; then
  /usr/bin/python3 - "$out/whole/summary.json" "$out/parts/summary.json" "${COMPARE_SUMMARY_TOL:-1e-8}" ${COMPARE_SUMMARY} <<'PY'
import json, sys
a, b = (json.load(open(f))["errors"] for f in sys.argv[1:3])
tol = float(sys.argv[3])
bad = 0
for name in sys.argv[4:]:
    if name not in a or name not in b:
        print("summary.json: %s missing (uninterrupted: %s, restarted: %s)" % (name, name in a, name in b)); bad = 1; continue
    d = abs(a[name] - b[name])
    print("summary.json %s: %.12g and %.12g (difference %.3g)" % (name, a[name], b[name], d))
    bad |= not (d <= tol)  # a NaN fails
sys.exit(bad)
PY
fi
