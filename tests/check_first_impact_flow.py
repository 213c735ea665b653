#!/usr/bin/python3
"""scripts/first_impact_flow.py on a synthetic snapshot whose figures are known by hand.

    check_first_impact_flow.py SCRIPT WORK_DIR

One snapshot at t = 0.40 s of eight particles (mass 0.1 kg/m each, refinement fields as a run
with zones writes them): a mother (its mass must not count), guards (their pressure must not
count), the floor front at x = 0.832 m, a jet particle at y = 0.3 m beyond the face, and three in
the inflow band 0.95-1.45 m, one of them a guard. Expected: front 0.832, delivered 0.30 kg/m (the
three leaves below x = 1 m: the front, the jet particle and a guard), jet tip 0.300 m with 0.10
kg/m above the box's top, inflow depth 3 x 0.1 / (1000 x 0.5) = 0.0006 m, u_x -2.00 m/s, momentum
flux (1000 x 4 x 0.0006 + 2000 x 0.0006) / 1000 = 0.0036 kN/m (the band's SPH particles at 2 kPa;
the guard's 50 kPa left out: with it, 0.0176), and the face's lowest band at 3.0 kPa.
"""
import os
import subprocess
import sys

import h5py
import numpy as np

script, work = sys.argv[1], sys.argv[2]
run = os.path.join(work, "flow_run")
os.makedirs(run, exist_ok=True)
#            x      y      ux    P       mother guard
rows = [(0.832, 0.010, -3.0, 3000.0, 0, 0),   # front, in the face's lowest band
        (0.900, 0.300, 0.0, 0.0, 0, 0),       # jet, above the box's top
        (0.930, 0.020, -1.0, 50000.0, 0, 1),  # guard below x = 1 m (its mass counts)
        (1.000, 0.020, -2.0, 2000.0, 0, 0),   # inflow band (x = 1 m not delivered)
        (1.200, 0.020, -2.0, 50000.0, 0, 1),  # a guard in the band: its mass and u_x count, its pressure not
        (1.400, 0.020, -2.0, 2000.0, 0, 0),
        (1.300, 0.020, -9.0, 9000.0, 1, 0),   # a mother: no mass, no pressure
        (2.000, 0.020, -2.0, 2000.0, 0, 0)]   # beyond the band
a = np.array(rows)
n = len(a)
with h5py.File(os.path.join(run, "t_000000.h5"), "w") as h:
    h["position"] = np.column_stack([a[:, 0], a[:, 1], np.zeros(n)])
    h["velocity"] = np.column_stack([a[:, 2], np.zeros(n), np.zeros(n)])
    h["pressure"] = a[:, 3]
    h["mass"] = np.full(n, 0.1)
    h["mother"] = a[:, 4].astype(np.int32)
    h["guard"] = a[:, 5].astype(np.int32)
with open(os.path.join(run, "t.xmf"), "w") as f:
    f.write('<Xdmf><Domain><Grid><Grid><Time Value="0.4"/></Grid></Grid></Domain></Xdmf>\n')
out = subprocess.run([sys.executable, script, run, "--times", "0.4", "--face-time", "0.4"],
                     capture_output=True, text=True)
if out.returncode != 0:
    sys.exit(f"check_first_impact_flow.py: the script failed: {out.stderr}")
lines = out.stdout.splitlines()
row = [c.strip() for c in next(l for l in lines if l.startswith("| 0.400 |")).strip("|").split("|")]
expected = ["0.400", "flow_run", "0.832", "0.30", "0.300", "0.10", "0.001", "-2.00", "0.004"]
face = [c.strip() for c in next(l for l in lines if l.startswith("| flow_run |")).strip("|").split("|")]
errors = []
if row != expected:
    errors.append(f"flow row {row}, expected {expected}")
if face[1] != "3.0":
    errors.append(f"face's lowest band {face[1]} kPa, expected 3.0")
if errors:
    sys.exit("check_first_impact_flow.py: " + "; ".join(errors))
print("check_first_impact_flow.py: the figures of the synthetic snapshot, as computed by hand")
