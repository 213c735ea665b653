#!/usr/bin/env bash
# A write that fails on one rank only (diagnostics.csv, which rank 0 alone writes, has a folder
# in its place) ends the whole run: a non-zero exit within the time limit (not a hang in the
# next collective), the message naming the file and the system's reason, no temporary left.
# usage: check_rank_write_failure.sh ONDINE CASE OUT
set -uo pipefail
ondine=$1; case_file=$2; out=$3
rm -rf "$out"
mkdir -p "$out/diagnostics.csv"
export OMP_NUM_THREADS=1
timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 "$ondine" run "$case_file" --out "$out" --quiet \
  --set time.duration=0.01 >"$out.log" 2>&1
rc=$?
cat "$out.log"
if [ "$rc" -eq 0 ] || [ "$rc" -eq 124 ]; then echo "FAIL: exit $rc (0: the failure was ignored; 124: the ranks hung)"; exit 1; fi
grep -q "cannot write $out/diagnostics.csv" "$out.log" || { echo "FAIL: the message does not name diagnostics.csv"; exit 1; }
grep -q "Is a directory" "$out.log" || { echo "FAIL: the message does not give the system's reason"; exit 1; }
if find "$out" -name "*.tmp" | grep -q .; then echo "FAIL: temporary files left:"; find "$out" -name "*.tmp"; exit 1; fi
echo "exit $rc, no hang, the file and the reason named, no temporary left"
