#!/usr/bin/env bash
# Checkpoints survive the ways a run can end badly:
#  1. SIGKILL mid-run: the checkpoint under its name is the last complete one
#     (at most one interval lost) and the run restarts from it;
#  2. SIGTERM: a clean stop that writes a checkpoint, exit status 128 + 15;
#  3. a truncated, a corrupted and a foreign file, and a checkpoint of another
#     resolution, are refused with a message, exit status 2.
# usage: check_kill_restart.sh ONDINE SRC OUT
set -uo pipefail
ondine=$1; src=$2; out=$3
case_file="$src/cases/dam_break_2d.yaml"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
wait_for() {  # wait_for LOG COUNT: until LOG has COUNT checkpoint lines (60 s at most)
  for _ in $(seq 600); do
    [ "$(grep -c '^  checkpoint:' "$1" 2>/dev/null)" -ge "$2" ] && return 0
    sleep 0.1
  done
  fail "no checkpoint after 60 s: $(tail -3 "$1")"
}
every=20
# 1. SIGKILL
"$ondine" run "$case_file" --out "$out/run" --set checkpoint.every_steps=$every --set time.duration=10 2> "$out/kill.log" &
pid=$!
wait_for "$out/kill.log" 3
kill -9 $pid; wait $pid 2>/dev/null
last=$(grep '^  checkpoint:' "$out/kill.log" | tail -1 | sed 's/.*step \([0-9]*\),.*/\1/')
step=$(h5dump -a step "$out/run/checkpoint.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
echo "killed after the checkpoint of step $last; checkpoint.h5 holds step $step"
[ "$step" -eq "$last" ] || [ "$step" -eq $((last + every)) ] || fail "checkpoint.h5 holds step $step, the last written was $last"
"$ondine" run "$case_file" --out "$out/run" --quiet --restart "$out/run/checkpoint.h5" --set time.max_steps=$((step + 5)) \
  || fail "restart after SIGKILL"
grep -q "\"total_steps\": $((step + 5))" "$out/run/summary.json" || fail "the restart did not go on from step $step"
# 2. SIGTERM: clean stop with a checkpoint
"$ondine" run "$case_file" --out "$out/term" --set checkpoint.every_steps=$every --set time.duration=10 2> "$out/term.log" &
pid=$!
wait_for "$out/term.log" 1
kill -TERM $pid; wait $pid; rc=$?
[ $rc -eq 143 ] || fail "SIGTERM: exit status $rc, expected 143"
grep -q "stopped by signal 15" "$out/term.log" || fail "SIGTERM: no stop message"
tstep=$(h5dump -a step "$out/term/checkpoint.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
"$ondine" run "$case_file" --out "$out/term" --quiet --restart "$out/term/checkpoint.h5" --set time.max_steps=$((tstep + 5)) \
  --set time.duration=10 2>/dev/null || fail "restart after SIGTERM"
grep -q "\"total_steps\": $((tstep + 5))" "$out/term/summary.json" || fail "the restart after SIGTERM did not go on from step $tstep"
echo "SIGTERM: exit status 143, checkpoint at step $tstep, restart OK"
# 3. files that must be refused
refuse() {  # refuse FILE EXPECTED_TEXT [--set ...]
  local f=$1 text=$2; shift 2
  "$ondine" run "$case_file" --out "$out/refused" --quiet --restart "$f" "$@" 2> "$out/refuse.log"; local rc=$?
  [ $rc -eq 2 ] || fail "$f: exit status $rc, expected 2 ($(cat "$out/refuse.log"))"
  grep -q "$text" "$out/refuse.log" || fail "$f: expected '$text' in: $(cat "$out/refuse.log")"
  [ ! -e "$out/refused" ] || fail "$f: a refused restart left an output folder"
  echo "refused $(basename "$f"): $(tail -1 "$out/refuse.log")"
}
good="$out/run/checkpoint.h5"
size=$(stat -c %s "$good")
head -c $((size / 2)) "$good" > "$out/truncated.h5"
refuse "$out/truncated.h5" "cannot restart"
cp "$good" "$out/corrupted.h5"
# overwrite 64 bytes inside the particle data (the last quarter of the file)
printf '%064d' 7 | dd of="$out/corrupted.h5" bs=1 seek=$((size * 3 / 4)) conv=notrunc status=none
refuse "$out/corrupted.h5" "checksum\|cannot be read\|corrupted"
echo "not a checkpoint" > "$out/foreign.h5"
refuse "$out/foreign.h5" "cannot be opened as an HDF5 file"
refuse "$good" "dx =" --set discretisation.dx=0.002286
refuse "$out/missing.h5" "cannot be opened"
echo "checkpoint checks OK"
