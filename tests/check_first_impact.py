#!/usr/bin/env python3
"""scripts/first_impact_table.py's measure on the measured series and on one run.

usage: check_first_impact.py SCRIPT MEASURED_CSV RUN_DIR MAX_IMPULSE_ERROR
The measured series must give Kleefsman et al.'s P1 first peak (10.8 kPa at 0.408 s, the figures
docs/validation.md quotes) and its impulse over 0.35-0.60 s (1 413 Pa s); the run's P1 probe
impulse must lie within MAX_IMPULSE_ERROR of the measured one. Exit 1, naming the figure, if not."""
import importlib.util
import os
import sys

script, measured, run, bound = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
spec = importlib.util.spec_from_file_location("first_impact_table", script)
table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(table)
m = table.figures(table.series(measured, "P1"))
got = f"{m['peak'] / 1e3:.1f} at {m['t_peak']:.3f}, {m['impulse']:.0f}"
if got != "10.8 at 0.408, 1413":
    sys.exit(f"check_first_impact.py: the measured P1 reads {got!r}, expected '10.8 at 0.408, 1413'")
try:
    r = table.figures(table.series(os.path.join(run, "probes.csv"), "P1.pressure"))
except (OSError, KeyError, ValueError) as e:
    sys.exit(f"check_first_impact.py: cannot read {os.path.join(run, 'probes.csv')}: {e}")
if r is None:
    sys.exit(f"check_first_impact.py: {run}: no P1 probe samples over 0.35-0.60 s")
err = abs(r["impulse"] - m["impulse"]) / m["impulse"]
print(f"P1 probe impulse {r['impulse']:.0f} Pa s against {m['impulse']:.0f}: {err:.3f}")
sys.exit(0 if err <= bound else f"check_first_impact.py: the P1 probe impulse is {err:.3f} off the measured, above {bound}")
