#!/usr/bin/env python3
"""scripts/first_impact_table.py on the measured series and on one run.

usage: check_first_impact.py SCRIPT MEASURED_CSV RUN_DIR MAX_IMPULSE_ERROR
The measured row must give Kleefsman et al.'s P1 first peak (10.8 kPa at 0.408 s, the figures
docs/validation.md quotes) and its impulse over 0.35-0.60 s (1 413 Pa s); the run's P1 probe
impulse must lie within MAX_IMPULSE_ERROR of the measured one. Exit 1, naming the figure, if not."""
import subprocess
import sys

script, measured, run, bound = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
out = subprocess.run([sys.executable, script, run, "--measured", measured], check=True, capture_output=True, text=True).stdout
rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[1:-1]] for line in out.splitlines() if line.startswith("| ")}
m = rows.get("measured")
if not m or m[5] != "10.8 at 0.408, 1413":
    sys.exit(f"check_first_impact.py: the measured P1 row reads {m[5] if m else None!r}, expected '10.8 at 0.408, 1413'")
r = rows.get(run)
if not r or " at " not in r[5]:
    sys.exit(f"check_first_impact.py: no figures for {run}: {r}")
impulse = float(r[5].split(",")[1])
err = abs(impulse - 1413) / 1413
print(f"P1 probe impulse {impulse:.0f} Pa s against 1413: {err:.3f}")
sys.exit(0 if err <= bound else f"check_first_impact.py: the P1 probe impulse is {err:.3f} off the measured, above {bound}")
