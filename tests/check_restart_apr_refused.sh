#!/usr/bin/env bash
# Restarts that cannot continue a run with refinement zones (docs/apr.md) are
# refused with exit status 2, a message naming the checkpoint and what is missing
# or different, and no output folder:
#  1. a checkpoint of a uniform run (no APR state), restarted with a case with zones;
#  2. a checkpoint with APR state, restarted with a case without zones;
#  3. the same, with other zones: another box, a nested zone (another level count),
#     another transition width, a zone that moves;
#  4. (with h5py) an APR field changed (checksum) or missing (dataset).
# usage: check_restart_apr_refused.sh ONDINE SRC OUT
set -uo pipefail
ondine=$1; src=$2; out=$3
apr="$src/cases/dam_break_apr_2d.yaml"
uniform="$src/cases/dam_break_impact_2d.yaml"  # the same scene (and dx) without zones
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
export OMP_NUM_THREADS=1
"$ondine" run "$uniform" --out "$out/uniform" --quiet --set time.max_steps=2 2>/dev/null || fail "the uniform run"
"$ondine" run "$apr" --out "$out/apr" --quiet --set time.max_steps=2 2>/dev/null || fail "the APR run"
h5ls "$out/uniform/checkpoint.h5" | grep -q "birth_level\|parent_id" && fail "a uniform run's checkpoint has APR fields"
h5dump -A "$out/uniform/checkpoint.h5" | grep -q "refinement" && fail "a uniform run's checkpoint has APR attributes"
for d in birth_level level guard mother parent_id; do
  h5ls "$out/apr/checkpoint.h5" | grep -q "^$d " || fail "the APR checkpoint has no dataset $d"
done
refuse() {  # refuse CASE FILE EXPECTED_TEXT... [-- --set ...]
  local case_file=$1 f=$2; shift 2
  local texts=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do texts+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  "$ondine" run "$case_file" --out "$out/refused" --quiet --restart "$f" "$@" 2> "$out/refuse.log"; local rc=$?
  [ $rc -eq 2 ] || fail "$f: exit status $rc, expected 2 ($(cat "$out/refuse.log"))"
  grep -q "ondine: error: cannot restart: $f: " "$out/refuse.log" || fail "$f: the message does not name the file: $(cat "$out/refuse.log")"
  for t in "${texts[@]}"; do
    grep -q -- "$t" "$out/refuse.log" || fail "$f: expected '$t' in: $(cat "$out/refuse.log")"
  done
  [ ! -e "$out/refused" ] || fail "$f: a refused restart left an output folder"
  echo "refused: $(tail -1 "$out/refuse.log")"
}
refuse "$apr" "$out/uniform/checkpoint.h5" "has no refinement state" "without refinement zones" "key 'refinement'"
refuse "$uniform" "$out/apr/checkpoint.h5" "written by a run with refinement zones" "has none"
refuse "$apr" "$out/apr/checkpoint.h5" "other refinement zones" "zone impact: level 1, in -, min \[0.2, -0.01\], max \[0.3, 0.1\], static" \
  "max \[0.29, 0.1\]" -- --set "refinement.zones.0.max=[0.29,0.1]"
refuse "$apr" "$out/apr/checkpoint.h5" "other refinement zones" "zone core: level 2, in impact" "2 zones in the case" \
  -- --set "refinement.zones.0.zones=[{name: core, min: [0.25, -0.01], max: [0.28, 0.05]}]"
refuse "$apr" "$out/apr/checkpoint.h5" "other refinement zones" "'transition 1', the case has 'transition 1.5'" \
  -- --set refinement.transition=1.5
refuse "$apr" "$out/apr/checkpoint.h5" "other refinement zones" "velocity \[1, 0\]" -- --set "refinement.zones.0.velocity=[1,0]"
if /usr/bin/python3 -c "import h5py" 2>/dev/null; then
  cp "$out/apr/checkpoint.h5" "$out/guard_changed.h5"
  /usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); g = f['guard']; i = int((g[:] == 0).argmax()); g[i] = 1" \
    "$out/guard_changed.h5"
  refuse "$apr" "$out/guard_changed.h5" "the APR fields" "refinement_checksum" "corrupted"
  cp "$out/apr/checkpoint.h5" "$out/no_parent.h5"
  /usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); del f['parent_id']" "$out/no_parent.h5"
  refuse "$apr" "$out/no_parent.h5" "dataset 'parent_id' is missing"
else
  echo "(h5py not found: the changed and missing APR field checks are skipped)"
fi
echo "APR restart checks OK"
