#!/usr/bin/env bash
# Runs a short case through the ondine executable and checks its output with
# h5dump: snapshots, an XDMF index naming them, summary.json, no temporaries.
set -euo pipefail
ondine=$1; src=$2; out=$3; backend=${4:-OpenMP}
rm -rf "$out"
"$ondine" run "$src/cases/taylor_green_2d.yaml" --out "$out" --quiet \
  --set discretisation.dx=0.05 --set time.duration=0.05 --set time.output_interval=0.025
test -f "$out/summary.json"
test -f "$out/taylor_green_2d.xmf"
ls "$out"/*.tmp 2>/dev/null && { echo "temporary files left behind"; exit 1; }
n=$(ls "$out"/taylor_green_2d_*.h5 | wc -l)
[ "$n" -eq 3 ] || { echo "expected 3 snapshots, got $n"; exit 1; }
h5dump -H "$out/taylor_green_2d_000002.h5" > "$out/header.txt"
grep -q 'DATASET "position"' "$out/header.txt"
grep -q 'DATASET "velocity"' "$out/header.txt"
grep -q 'DATASET "pressure"' "$out/header.txt"
grep -q 'DATASET "density"' "$out/header.txt"
grep -q 'DATASPACE  SIMPLE { ( 400, 3 )' "$out/header.txt"
h5dump -a time "$out/taylor_green_2d_000002.h5" | grep -q '0.05'
grep -q 'taylor_green_2d_000002.h5:/position' "$out/taylor_green_2d.xmf"
grep -q '"particles": 400' "$out/summary.json"
grep -q "\"backend\": \"$backend\"" "$out/summary.json"
# a second, shorter run into the same folder leaves none of the first run's snapshots
"$ondine" run "$src/cases/taylor_green_2d.yaml" --out "$out" --quiet \
  --set discretisation.dx=0.05 --set time.duration=0.025 --set time.output_interval=0.025
n=$(ls "$out"/taylor_green_2d_*.h5 | wc -l)
[ "$n" -eq 2 ] || { echo "a rerun left stale snapshots: $n files, expected 2"; exit 1; }
echo "run output OK"
