#!/usr/bin/env bash
# A write that fails names the file and the system's reason, exits non-zero, and leaves no
# temporary file; a complete file is never replaced by a broken one. The failures are made
# without privileges: a temporary's name linked to /dev/full (every write: ENOSPC), a folder in
# a file's place (the rename fails), a file in the output folder's place. Also: an empty --out,
# and a restart into a folder without the run's snapshots.
# usage: check_failed_writes.sh ONDINE SRC OUT
set -uo pipefail
ondine=$1; src=$2; out=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
export OMP_NUM_THREADS=1
case_file="$src/cases/taylor_green_2d.yaml"
short=(--quiet --set discretisation.dx=0.05 --set time.duration=0.05 --set time.output_interval=0.025)
[ -w /dev/full ] || { echo "(no writable /dev/full: skipped)"; exit 77; }

# expect DIR RC_WANTED TEXT...: the last run's exit status and message
expect() {
  local dir=$1 want=$2; shift 2
  [ "$rc" -ne 0 ] || fail "$dir: exit status 0"
  [ "$want" = any ] || [ "$rc" -eq "$want" ] || fail "$dir: exit status $rc, expected $want: $(cat "$out/err")"
  for t in "$@"; do grep -qF -- "$t" "$out/err" || fail "$dir: expected '$t' in: $(cat "$out/err")"; done
  grep -q "HDF5-DIAG\|terminate called\|Segmentation" "$out/err" && fail "$dir: a raw library trace: $(head -3 "$out/err")"
  local left
  left=$(find "$out/$dir" -name '*.tmp' 2>/dev/null)
  [ -z "$left" ] || fail "$dir: temporary files left: $left"
  echo "$dir: $(grep 'ondine: error' "$out/err")"
}

# a snapshot (HDF5) on a full disk
mkdir -p "$out/snap"; ln -s /dev/full "$out/snap/taylor_green_2d_000000.h5.tmp"
"$ondine" run "$case_file" --out "$out/snap" "${short[@]}" 2> "$out/err"; rc=$?
expect snap any "cannot write $out/snap/taylor_green_2d_000000.h5" "No space left on device"
[ ! -e "$out/snap/taylor_green_2d_000000.h5" ] || fail "snap: a snapshot under its final name after a failed write"

# summary.json (text) on a full disk, after a run whose snapshots are complete
mkdir -p "$out/text"; ln -s /dev/full "$out/text/summary.json.tmp"
"$ondine" run "$case_file" --out "$out/text" "${short[@]}" 2> "$out/err"; rc=$?
expect text any "cannot write $out/text/summary.json" "No space left on device"
[ ! -e "$out/text/summary.json" ] || fail "text: summary.json written"
h5dump -a time "$out/text/taylor_green_2d_000002.h5" > /dev/null || fail "text: the complete snapshots are not readable"

# a rename onto a folder
mkdir -p "$out/rename/diagnostics.csv/inside"
"$ondine" run "$case_file" --out "$out/rename" "${short[@]}" 2> "$out/err"; rc=$?
expect rename any "cannot write $out/rename/diagnostics.csv" "Is a directory"

# the output folder: a file in its place, an empty name
touch "$out/afile"
"$ondine" run "$case_file" --out "$out/afile" "${short[@]}" 2> "$out/err"; rc=$?
expect . 2 "--out $out/afile: a file of that name exists"
"$ondine" run "$case_file" --out "" "${short[@]}" 2> "$out/err"; rc=$?
expect . 2 "--out: expected a folder, got an empty name"

# a restart into a folder without the run's snapshots: refused before anything is written
"$ondine" run "$case_file" --out "$out/run" "${short[@]}" 2> "$out/err" || fail "the reference run: $(cat "$out/err")"
"$ondine" run "$case_file" --out "$out/elsewhere" "${short[@]}" --set time.duration=0.1 --restart "$out/run/checkpoint.h5" 2> "$out/err"; rc=$?
expect . 2 "cannot restart: $out/run/checkpoint.h5" "$out/elsewhere/taylor_green_2d_000000.h5 is missing" "give --out the folder"
[ ! -e "$out/elsewhere" ] || fail "a refused restart left an output folder"
# ... and with another case of the same name and dx
"$ondine" run "$src/cases/free_fall_2d.yaml" --out "$out/run" --quiet --set discretisation.dx=0.05 --set name=taylor_green_2d \
  --restart "$out/run/checkpoint.h5" 2> "$out/err"; rc=$?
expect . 2 "cannot restart: $out/run/checkpoint.h5" "key 'fluid.rho0'"
echo "failed writes OK"
