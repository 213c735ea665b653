#!/usr/bin/python3
"""scripts/wedge_quarters.py on a synthetic wall_sensors.csv: every face reads f(s) times the
similarity profile's mean over its span (integrated here on a 20 times finer grid), f(s) = 0.5 + s,
so each quarter's peak and floor ratios are the mean of f over that quarter's instants; instants
outside s = 0.5-1 m read 1e9 and must be left out. A missing folder and an empty file are refused, naming the file.

usage: check_wedge_quarters.py SCRIPT WORKDIR"""
import os
import subprocess
import sys

import numpy as np

script, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(script))
rows = [line for line in open(os.path.join(here, "..", "cases", "reference", "wedge_similarity_alpha80.csv"))
        if not line.startswith("#") and line.strip()]
data = np.array([[float(x) for x in line.split(",")] for line in rows[1:]])
eta, P = data[:, 0], data[:, 1]
U, t0, face, rho, faces = 5.0, 0.01, 0.25, 1000.0, 48


def span_mean(a, b):
    xs = np.linspace(a, b, 8001)
    return np.interp(xs, eta, P, right=0.0).mean()


run = os.path.join(work, "wedge_quarters_run")
os.makedirs(run, exist_ok=True)
with open(os.path.join(run, "wall_sensors.csv"), "w") as f:
    f.write("time,step," + ",".join(f"W{j:02d}.pressure" for j in range(faces)) + "\n")
    for k, s in enumerate(np.arange(0.3, 1.0 + 1e-9, 0.0125)):
        if s < 0.5 - 1e-9:
            p = [1e9] * faces
        else:
            p = [(0.5 + s) * rho * U * U * span_mean(face * j / s, face * (j + 1) / s) for j in range(faces)]
        f.write(f"{t0 + s / U:.12g},{k}," + ",".join(f"{v:.12g}" for v in p) + "\n")

out = subprocess.run([sys.executable, script, run], capture_output=True, text=True)
if out.returncode != 0:
    sys.exit(f"check_wedge_quarters: the script failed: {out.stderr}")
lines = out.stdout.strip().split("\n")
s = np.arange(0.5, 1.0 + 1e-9, 0.0125)
f = 0.5 + s
expected_all = f.mean()
got_all = float(lines[0].split("peak ratio ")[1].split()[0])
bad = []
if abs(got_all - expected_all) > 2e-3:
    bad.append(f"window: peak ratio {got_all} against {expected_all:.4f}")
if "41 instants" not in lines[0]:
    bad.append(f"window: {lines[0]} (41 instants expected)")
edges = np.linspace(0.5, 1.0, 5)
for q, line in enumerate(lines[2:6]):
    cols = [c.strip() for c in line.split("|")]
    m = (s >= edges[q] - 1e-9) & ((s < edges[q + 1] - 1e-9) | (q == 3))
    want = f[m].mean()
    if int(cols[2]) != m.sum() or abs(float(cols[3]) - want) > 2e-3 or abs(float(cols[4]) - want) > 2e-3:
        bad.append(f"quarter {q}: {line} against {m.sum()} instants, ratios {want:.4f}")
missing = subprocess.run([sys.executable, script, os.path.join(work, "no_such_run")], capture_output=True, text=True)
if missing.returncode == 0 or "no_such_run/wall_sensors.csv" not in missing.stderr:
    bad.append(f"a missing folder: exit {missing.returncode}, {missing.stderr.strip()!r}")
empty = os.path.join(work, "wedge_quarters_empty")
os.makedirs(empty, exist_ok=True)
open(os.path.join(empty, "wall_sensors.csv"), "w").close()
refused = subprocess.run([sys.executable, script, empty], capture_output=True, text=True)
if refused.returncode == 0 or "wedge_quarters_empty/wall_sensors.csv: expected a header" not in refused.stderr:
    bad.append(f"an empty wall_sensors.csv: exit {refused.returncode}, {refused.stderr.strip()!r}")
if bad:
    sys.exit("check_wedge_quarters:\n" + "\n".join(bad))
print("check_wedge_quarters: the window's and each quarter's ratios are f(s)'s means")
