#!/usr/bin/env bash
# A distributed run killed with SIGKILL goes on from its last checkpoint on another rank
# count and ends where the uninterrupted run ends: the run on NP ranks writes a checkpoint
# every EVERY steps and is killed (SIGKILL, every rank) once KEEP checkpoints are written;
# the checkpoint left under its name is restarted on NP_RESTART ranks for MORE steps, and
# its last snapshot is compared, field by field and particle by particle (matched by id),
# with that of an uninterrupted run on NP ranks stopped at the same step, within TOL relative.
# Both write their checkpoints at the same steps (a checkpoint, like a restart, starts the
# step after it with a bookkeeping of the refinement).
# usage: check_kill_restart_ranks.sh ONDINE COMPARE CASE OUT NP NP_RESTART EVERY KEEP MORE TOL [--set ...]
set -uo pipefail
ondine=$1; compare=$2; case_file=$3; out=$4; np=$5; np2=$6; every=$7; keep=$8; more=$9; tol=${10}; shift 10
mpirun=(mpirun --allow-run-as-root --oversubscribe)
export OMP_NUM_THREADS=1
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
"${mpirun[@]}" -np "$np" "$ondine" run "$case_file" --out "$out/killed" --set checkpoint.every_steps="$every" \
  --set time.max_steps=1000000 "$@" 2> "$out/killed.log" > /dev/null &
pid=$!
for _ in $(seq 3000); do  # at most 300 s
  [ "$(grep -c '^  checkpoint:' "$out/killed.log" 2>/dev/null)" -ge "$keep" ] && break
  kill -0 $pid 2>/dev/null || fail "the run ended before $keep checkpoints: $(tail -3 "$out/killed.log")"
  sleep 0.1
done
[ "$(grep -c '^  checkpoint:' "$out/killed.log")" -ge "$keep" ] || fail "no $keep checkpoints after 300 s"
# SIGKILL: the ranks first (no handler runs), then mpirun
pkill -9 -P $pid 2>/dev/null; kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
step=$(h5dump -a step "$out/killed/checkpoint.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
[ -n "$step" ] || fail "no readable checkpoint after SIGKILL"
last=$(grep '^  checkpoint:' "$out/killed.log" | tail -1 | sed 's/.*step \([0-9]*\),.*/\1/')
echo "killed on $np ranks after the checkpoint of step $last; checkpoint.h5 holds step $step"
[ "$step" -eq "$last" ] || [ "$step" -eq $((last + every)) ] || fail "checkpoint.h5 holds step $step, the last written was $last"
end=$((step + more))
"${mpirun[@]}" -np "$np2" "$ondine" run "$case_file" --out "$out/killed" --quiet --restart "$out/killed/checkpoint.h5" \
  --set checkpoint.every_steps="$every" --set time.max_steps=$end "$@" || fail "restart on $np2 ranks"
grep -q "\"total_steps\": $end" "$out/killed/summary.json" || fail "the restart did not go on to step $end"
"${mpirun[@]}" -np "$np" "$ondine" run "$case_file" --out "$out/whole" --quiet --set checkpoint.every_steps="$every" \
  --set time.max_steps=$end "$@" || fail "uninterrupted run"
a=$(ls "$out/whole"/*_0*.h5 | sort | tail -1); b=$(ls "$out/killed"/*_0*.h5 | sort | tail -1)
echo "uninterrupted ($np ranks) vs killed at step $step and restarted on $np2 ranks, at step $end:"
"$compare" "$a" "$b" "$tol" all || fail "the fields differ"
