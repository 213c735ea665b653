#!/usr/bin/env bash
# A run with refinement zones (docs/apr.md) stopped every EVERY steps and restarted
# from its checkpoint each time (STEPS / EVERY parts, a restart of a restart
# included) ends bitwise where an uninterrupted run of STEPS steps that writes a
# checkpoint every EVERY steps ends: every dataset of the last snapshot (the APR
# fields level, birth_level, guard, mother included) and of the final checkpoint
# (parent_id too), particles matched by id, and the APR counters of summary.json.
# The stops must matter: daughters were deleted (derefinement) before the first,
# and mothers are refined and daughters deleted after it.
# usage: check_restart_apr.sh ONDINE COMPARE CASE OUT STEPS EVERY [--set ...]
set -euo pipefail
ondine=$1; compare=$2; case_file=$3; out=$4; steps=$5; every=$6; shift 6
export OMP_NUM_THREADS=1
rm -rf "$out"
"$ondine" run "$case_file" --out "$out/whole" --quiet --set time.max_steps=$steps --set checkpoint.every_steps=$every "$@"
"$ondine" run "$case_file" --out "$out/parts" --quiet --set time.max_steps=$every "$@"
cp "$out/parts/summary.json" "$out/first_stop_summary.json"
for ((s = 2 * every; s <= steps; s += every)); do
  "$ondine" run "$case_file" --out "$out/parts" --quiet --set time.max_steps=$s --restart "$out/parts/checkpoint.h5" "$@"
done
/usr/bin/python3 - "$out" <<'EOF'
import json, sys
out = sys.argv[1]
first, whole, parts = (json.load(open(f"{out}/{f}")) for f in ("first_stop_summary.json", "whole/summary.json", "parts/summary.json"))
assert "restarted_from" in parts, "the restarted run's summary.json has no restarted_from"
h, w, p = first["refinement"], whole["refinement"], parts["refinement"]
print(f"APR counters (mothers refined, daughters deleted since t = 0): step {first['total_steps']}: {h['refined']}, {h['deleted']}; "
      f"step {whole['total_steps']}: uninterrupted {w['refined']}, {w['deleted']}, restarted {p['refined']}, {p['deleted']}")
assert h["deleted"] > 0, "no derefinement before the first stop: the checkpoint does not test much"
assert w["refined"] > h["refined"] and w["deleted"] > h["deleted"], "no refinement or no derefinement after the first stop"
assert p == w, f"the APR counters differ: uninterrupted {w}, restarted {p}"
# counters of the whole run that the checkpoint carries too
for k in ("families_moved_off_walls", "wall_corrections", "guard_shifts"):
    if k not in whole["errors"]:
        continue
    print(f"{k}: uninterrupted {whole['errors'][k]:g}, restarted {parts['errors'][k]:g}")
    assert parts["errors"][k] == whole["errors"][k], f"{k} differs"
EOF
a=$(ls "$out/whole"/*_0*.h5 | sort | tail -1); b=$(ls "$out/parts"/*_0*.h5 | sort | tail -1)
echo "uninterrupted vs stopped and restarted every $every steps, last snapshot, every dataset:"
"$compare" "$a" "$b" 0 all
echo "uninterrupted vs stopped and restarted every $every steps, final checkpoint, every dataset:"
"$compare" "$out/whole/checkpoint.h5" "$out/parts/checkpoint.h5" 0 all
