#!/usr/bin/env bash
# 1-, 2- and 4-rank runs of the same case give the same particles: after N steps
# every field of the last snapshot agrees within TOL relative (matched by id).
# usage: check_mpi_equivalence.sh ONDINE COMPARE CASE OUT STEPS TOL [--set ...]
# COMPARE_FIELDS (environment, optional): the snapshot fields compared (default: ondine_compare's)
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
done
