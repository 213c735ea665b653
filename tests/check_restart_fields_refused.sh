#!/usr/bin/env bash
# The fields a checkpoint carries beyond the state (here the Langevin model's path-averaged
# gradient and k) each have their own checksum (checksum_LABEL): a value changed in the file is
# refused with exit status 2, a message naming the file and that field, and no output folder;
# the file as written restarts, and so does a case that does not read the averaged gradient.
# Needs h5py to change a value (exit 77, skipped, without it).
# usage: check_restart_fields_refused.sh ONDINE SRC OUT
set -uo pipefail
ondine=$1; src=$2; out=$3
case_file="$src/cases/turbulent_channel_langevin_2d.yaml"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
export OMP_NUM_THREADS=1
set_avg=(--set turbulence.langevin.mean_gradient=averaged)
"$ondine" run "$case_file" --out "$out/a" --quiet --set time.max_steps=10 "${set_avg[@]}" 2>/dev/null || fail "the first run"
if ! /usr/bin/python3 -c "import h5py" 2>/dev/null; then
  echo "(h5py not found: the checks are skipped)"
  exit 77
fi
/usr/bin/python3 -c "import h5py, sys; a = h5py.File(sys.argv[1], 'r').attrs; sys.exit(0 if 'checksum_k' in a and 'checksum_langevin_gradient_x' in a else 1)" \
  "$out/a/checkpoint.h5" || fail "the checkpoint has no checksum_k or checksum_langevin_gradient_x"
cp "$out/a/checkpoint.h5" "$out/written.h5"
"$ondine" run "$case_file" --out "$out/a" --quiet --set time.max_steps=20 "${set_avg[@]}" --restart "$out/a/checkpoint.h5" 2> "$out/b.err" ||
  fail "the checkpoint as written does not restart: $(cat "$out/b.err")"
"$ondine" run "$case_file" --out "$out/a" --quiet --set time.max_steps=20 --restart "$out/written.h5" 2> "$out/f.err" ||
  fail "a case without the averaged gradient does not restart from the file: $(cat "$out/f.err")"
for d in langevin_gradient_x k; do
  cp "$out/written.h5" "$out/$d.h5"
  /usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); g = f[sys.argv[2]]; v = g[0]; v = v * (1 + 1e-12) + 1e-300; g[0] = v" \
    "$out/$d.h5" "$d"
  "$ondine" run "$case_file" --out "$out/refused" --quiet --set time.max_steps=20 "${set_avg[@]}" --restart "$out/$d.h5" 2> "$out/refuse.log"
  rc=$?
  [ $rc -eq 2 ] || fail "$d changed: exit status $rc, expected 2 ($(cat "$out/refuse.log"))"
  for t in "$out/$d.h5" "the field $d does not match" "checksum_$d" "corrupted"; do
    grep -q -- "$t" "$out/refuse.log" || fail "$d changed: expected '$t' in: $(cat "$out/refuse.log")"
  done
  [ ! -e "$out/refused" ] || fail "$d changed: a refused restart left an output folder"
  echo "refused: $(tail -1 "$out/refuse.log")"
done
echo "fields checksum checks OK"
