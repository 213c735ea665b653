#!/usr/bin/python3
"""scripts/cylinder_wake.py against a made-up run whose answers are known by construction: a
lattice of spacing 0.01 m around a cylinder of radius 0.05 m at the origin, m / rho = dx^2 (so
the volume fraction is 1 wherever the lattice is whole), every other particle removed from
one bin of the axis band (fraction 1/2 there), a linear pressure p = 1000 + 250 x, guards that
must be left out, a snapshot outside the time window that must be left out, and a checkpoint
whose daughters sit 3 dx from their mothers on the axis and 1 dx elsewhere. Then bad input:
a missing folder and a folder without snapshots are refused.
usage: check_cylinder_wake.py SCRIPT WORK_DIR"""
import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

script, work = sys.argv[1], os.path.join(sys.argv[2], "cylinder_wake_check")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
dx, rho = 0.01, 1000.0
gx, gy = np.meshgrid(np.arange(-0.7, 1.3, dx) + dx / 2, np.arange(-0.6, 0.6, dx) + dx / 2, indexing="ij")
x = np.column_stack([gx.ravel(), gy.ravel()])
x = x[np.hypot(x[:, 0], x[:, 1]) >= 0.05]
hole = (x[:, 0] >= 0.2) & (x[:, 0] < 0.25) & (np.abs(x[:, 1]) < 0.1)
ix, iy = (np.round((x[:, k] - lo - dx / 2) / dx).astype(int) for k, lo in ((0, -0.7), (1, -0.6)))
drop = hole & ((ix + iy) % 2 == 1)  # a checkerboard: half the bin's 5 x 20 particles
x = x[~drop]
n = len(x)
P = 1000.0 + 250.0 * x[:, 0]
guard = np.zeros(n, dtype=np.int32)


def snapshot(path, t, pressure, extra_guards=0):
    with h5py.File(path, "w") as h:
        h.attrs["time"] = t
        pos = np.column_stack([x, np.zeros(n)])
        g = guard.copy()
        m = np.full(n, rho * dx * dx)
        if extra_guards:  # guards on top of the lattice: they must not count
            pos = np.vstack([pos, pos[:extra_guards]])
            g = np.concatenate([g, np.ones(extra_guards, dtype=np.int32)])
            m = np.concatenate([m, m[:extra_guards]])
            pressure = np.concatenate([pressure, np.full(extra_guards, 1e9)])
        h["position"] = pos
        h["mass"] = m
        h["density"] = np.full(len(m), rho)
        h["pressure"] = pressure
        h["guard"] = g


snapshot(os.path.join(work, "run_000001.h5"), 2.5, P, extra_guards=500)
snapshot(os.path.join(work, "run_000002.h5"), 2.6, P)
snapshot(os.path.join(work, "run_000000.h5"), 1.0, np.full(n, 1e9))  # before --from: left out
# a checkpoint: 40 daughters on the axis band behind the body 3 dx from their mothers, 60 elsewhere 1 dx from theirs
with h5py.File(os.path.join(work, "checkpoint.h5"), "w") as h:
    mothers = np.array([[0.3 + 0.01 * k, 0.0] for k in range(40)] + [[-0.4, -0.5 + 0.01 * k] for k in range(60)])
    daughters = mothers + np.array([[0.0, 0.006]] * 40 + [[0.002, 0.0]] * 60)
    pos = np.vstack([mothers, daughters])
    h["position"] = np.column_stack([pos, np.zeros(len(pos))])
    h["id"] = np.arange(len(pos), dtype=np.int64)
    h["parent_id"] = np.concatenate([np.full(100, -1), np.arange(100)]).astype(np.int64)
    h["birth_level"] = np.concatenate([np.zeros(100), np.ones(100)]).astype(np.int32)

out = os.path.join(work, "wake.json")
r = subprocess.run([sys.executable, script, work, "--ring", "0.03", "--json", out], capture_output=True, text=True)
print(r.stdout, r.stderr)
failures = []
if r.returncode != 0:
    sys.exit("check_cylinder_wake.py: the script failed")
res = json.load(open(out))
if res["snapshots"] != 2:
    failures.append(f"snapshots {res['snapshots']}, expected 2 (one outside the window)")
for (x0, x1), v, o, c in zip(res["x_bins"], res["axis_volume_fraction"], res["outer_volume_fraction"], res["axis_cp"]):
    centre = 0.5 * (x0 + x1)
    want = 0.5 if abs(centre - 0.225) < 1e-9 else (None if abs(centre) < 0.1 else 1.0)
    if want is not None and abs(v - want) > 1e-9:
        failures.append(f"axis volume fraction {v:.6f} in [{x0:.2f}, {x1:.2f}), expected {want}")
    if abs(o - 1.0) > 1e-9:
        failures.append(f"outer volume fraction {o:.6f} in [{x0:.2f}, {x1:.2f}), expected 1")
    # p_ref: the mean of p over the reference box [-0.6, -0.3] (lattice points, x mean -0.45)
    if want is not None and want == 1.0 and abs(c - 250.0 * (centre + 0.45) / 500.0) > 1e-9:
        failures.append(f"axis Cp {c:.6f} at x = {centre:.3f}, expected {250 * (centre + 0.45) / 500:.6f}")
# the ring (0.05 to 0.08 m, wide enough for the lattice's spacing): each sector's Cp is 250 (x - x_ref) / 500
# averaged over its particles, between the values at the sector's corners
for (a0, a1), c in zip(res["wall_cp_sectors_deg"], res["wall_cp"]):
    corners = [250.0 * (-r_ * np.cos(np.radians(a)) + 0.45) / 500.0 for a in (a0, a1) for r_ in (0.05, 0.08)]
    lo, hi = min(corners), max(corners)
    if not (lo - 1e-9 <= c <= hi + 1e-9):
        failures.append(f"wall Cp {c:.4f} in sector [{a0}, {a1}], expected within [{lo:.4f}, {hi:.4f}]")
fam = res["families"]["level 1"]
if fam["wake"]["daughters"] != 40 or abs(fam["wake"]["median"] - 3.0) > 1e-9 or abs(fam["elsewhere"]["max"] - 1.0) > 1e-9:
    failures.append(f"families {fam}, expected 40 on the axis at 3 dx and 60 elsewhere at 1 dx")
for args, what in (([os.path.join(work, "missing")], "not a folder"), ([work, "--from", "5"], "no snapshot")):
    r = subprocess.run([sys.executable, script] + args, capture_output=True, text=True)
    if r.returncode == 0 or what not in r.stderr:
        failures.append(f"{args}: exit {r.returncode}, stderr '{r.stderr.strip()}', expected a refusal saying '{what}'")
for f in failures:
    print("FAIL:", f)
print(f"check_cylinder_wake.py: {len(failures)} failures")
sys.exit(1 if failures else 0)
