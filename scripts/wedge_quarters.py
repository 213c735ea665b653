#!/usr/bin/python3
"""The triangular water column's wall sensors against the similarity solution, window by window.

The report's pressure_peak_ratio (src/reference/WedgeImpact.hpp) is the mean over the instants
with s = U (t - t0) in [length/2, length] of max_j p_j / max_j P_j rho U^2, each face j against
the profile's mean over its own span in eta = y / s. This script splits that window into
quarters and prints, for each, the same peak ratio and the floor face's ratio (face 0 against
the profile's mean over its span): a self-similar run gives the same figures in every quarter.

usage: wedge_quarters.py RUN_FOLDER [U t0 length face rho]
  defaults: U = 5 m/s, t0 = 0.01 s, length = 1 m, face = 0.25 m (cases/wedge_impact_2d.yaml's
  48 faces from the floor), rho = 1000 kg/m^3; the profile is cases/reference/wedge_similarity_alpha80.csv
"""
import csv
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def profile():
    path = os.path.join(HERE, "..", "cases", "reference", "wedge_similarity_alpha80.csv")
    rows = [line for line in open(path) if not line.startswith("#") and line.strip()]
    data = np.array([[float(x) for x in line.split(",")] for line in rows[1:]])
    return data[:, 0], data[:, 1]


def main(argv):
    if len(argv) < 1:
        sys.exit(__doc__)
    run = argv[0]
    given = [float(x) for x in argv[1:6]]
    U, t0, length, face, rho = given + [5.0, 0.01, 1.0, 0.25, 1000.0][len(given):]
    eta, P = profile()
    path = os.path.join(run, "wall_sensors.csv")
    try:
        rows = list(csv.DictReader(open(path)))
    except OSError as e:
        sys.exit(f"wedge_quarters.py: cannot read {path}: {e.strerror}")
    names = [k for k in rows[0] if k.endswith(".pressure")] if rows else []
    if not names or "time" not in rows[0]:
        sys.exit(f"wedge_quarters.py: {path}: expected a header with `time` and the faces' `NAME.pressure` columns, "
                 "and at least one row (an `ondine run` output's wall_sensors.csv)")
    q = rho * U * U

    def ref_mean(a, b):  # the profile's mean over [a, b] in eta, zero beyond its end
        xs = np.linspace(a, b, 401)
        return np.interp(xs, eta, P, right=0.0).mean()

    out = []
    for row in rows:
        s = U * (float(row["time"]) - t0)
        if s < length / 2 - 1e-9 or s > length + 1e-9:
            continue
        p = [float(row[n]) / q for n in names]
        ref = [ref_mean(face * j / s, face * (j + 1) / s) for j in range(len(names))]
        if max(ref) <= 0:
            continue
        out.append((s, max(p) / max(ref), p[0] / ref[0]))
    if not out:
        sys.exit(f"wedge_quarters.py: {path}: no instant with s in [{length / 2}, {length}] m")
    out = np.array(out)
    print(f"{run}: {len(out)} instants, peak ratio {out[:, 1].mean():.3f} over the window")
    print("s from (m) | s to (m) | instants | peak ratio | floor face ratio")
    edges = np.linspace(length / 2, length, 5)
    for k in range(4):
        m = (out[:, 0] >= edges[k] - 1e-9) & ((out[:, 0] < edges[k + 1] - 1e-9) | (k == 3))
        print(f"{edges[k]:.3f} | {edges[k + 1]:.3f} | {m.sum()} | {out[m, 1].mean():.3f} | {out[m, 2].mean():.3f}")


if __name__ == "__main__":
    main(sys.argv[1:])
