#!/usr/bin/python3
"""Pressure noise at the level interface of an APR run, against the uniform runs.

Issue 7: "no spurious pressure oscillation at level interfaces (the pressure jump
across an interface stays within the noise of the uniform run)". For each SPH
particle i (guards excluded) the pressure noise is P_i - a_i, where a_i + b_i.(x - x_i)
is the weighted least-squares linear fit of the pressure of the SPH particles
j != i (every level) within i's own radius R_i, weights W(r_ij / R_i) of the
Wendland C2 shape. The fit is exact for a linear field even with a one-sided
support (walls, free surface), so hydrostatic pressure gives no noise; a jump
across the interface, or particle-scale oscillation, does. The figure is the RMS
of the noise over the particles within R (coarse) of the interface, over every
snapshot in [t_from, t_to], divided by rho0 g H. The same band (same geometry)
is measured in the coarse and fine uniform runs.

usage: apr_interface_noise.py CASE_DIR [--interface x0,y0,x1,y1 ...] [--from T] [--to T]
         [--R R] [--rho-g-H P] [--json OUT]
CASE_DIR holds the folders coarse/, apr/ and fine/ of `ondine validate --case
apr_dam_break_2d` (defaults: the dam break's impact box, x = 0.2 m below
y = 0.1 m and y = 0.1 m right of x = 0.2 m; R = 3 a / 25; rho0 g 2a).
"""
import argparse
import glob
import json
import os
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree


def segment_distance(p, a, b):
    ab = b - a
    t = np.clip(((p - a) @ ab) / (ab @ ab), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[:, None] * ab), axis=1)


def wendland(q):
    q = np.minimum(q, 1.0)
    return (1 - q) ** 4 * (1 + 4 * q)


def noise(x, P, R_i, band):
    """P_i minus the linear least-squares fit of its neighbours at x_i, for i in band."""
    tree = cKDTree(x)
    out = []
    for i in np.flatnonzero(band):
        js = [j for j in tree.query_ball_point(x[i], R_i[i]) if j != i]
        if len(js) < 6:
            continue
        d = x[js] - x[i]
        w = wendland(np.linalg.norm(d, axis=1) / R_i[i])
        A = np.column_stack([np.ones(len(js)), d])
        sw = np.sqrt(w)
        coef, *_ = np.linalg.lstsq(A * sw[:, None], P[js] * sw, rcond=None)
        out.append(P[i] - coef[0])
    return np.array(out)


def measure(run_dir, segments, R, t_from, t_to):
    files = sorted(glob.glob(os.path.join(run_dir, "*_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    if not files:
        sys.exit(f"apr_interface_noise.py: no snapshots in {run_dir}")
    values, snaps = [], 0
    for f in files:
        with h5py.File(f, "r") as h:
            t = float(h.attrs["time"])
            if t < t_from or t > t_to:
                continue
            x = h["position"][:, :2]
            P = h["pressure"][:]
            level = h["level"][:] if "level" in h else np.zeros(len(P), dtype=int)
            sph = (h["guard"][:] == 0) if "guard" in h else np.ones(len(P), dtype=bool)
            birth = h["birth_level"][:] if "birth_level" in h else level
        x, P, birth = x[sph], P[sph], birth[sph]
        R_i = R / 2.0 ** birth  # a particle's radius is that of the level it was born on
        d = np.min([segment_distance(x, a, b) for a, b in segments], axis=0)
        values.append(noise(x, P, R_i, d < R))
        snaps += 1
    v = np.concatenate(values) if values else np.array([])
    return {"snapshots": snaps, "samples": int(v.size), "rms": float(np.sqrt(np.mean(v * v))) if v.size else float("nan")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case_dir")
    ap.add_argument("--interface", nargs="+", default=["0.2,0.0,0.2,0.1", "0.2,0.1,0.3,0.1"])
    ap.add_argument("--from", dest="t_from", type=float, default=0.15)
    ap.add_argument("--to", dest="t_to", type=float, default=1e30)
    ap.add_argument("--R", type=float, default=3 * 0.05715 / 25)
    ap.add_argument("--rho-g-H", type=float, default=1000.0 * 9.81 * 2 * 0.05715)
    ap.add_argument("--json")
    a = ap.parse_args()
    segments = []
    for s in a.interface:
        v = [float(c) for c in s.split(",")]
        if len(v) != 4:
            sys.exit(f"apr_interface_noise.py: --interface '{s}': expected x0,y0,x1,y1")
        segments.append((np.array(v[:2]), np.array(v[2:])))
    res = {}
    for run in ("coarse", "apr", "fine"):
        m = measure(os.path.join(a.case_dir, run), segments, a.R, a.t_from, a.t_to)
        m["rms_over_rho_g_H"] = m["rms"] / a.rho_g_H
        res[run] = m
        print(f"{run:6s}: interface band pressure noise {m['rms_over_rho_g_H']:.4e} rho0 g H "
              f"({m['samples']} samples, {m['snapshots']} snapshots)")
    worst_uniform = max(res["coarse"]["rms"], res["fine"]["rms"])
    res["apr_over_noisier_uniform"] = res["apr"]["rms"] / worst_uniform
    res["apr_over_fine"] = res["apr"]["rms"] / res["fine"]["rms"]
    print(f"APR / noisier uniform run: {res['apr_over_noisier_uniform']:.3f}; APR / fine: {res['apr_over_fine']:.3f}")
    if a.json:
        tmp = a.json + ".tmp"
        with open(tmp, "w") as f:
            json.dump(res, f, indent=1)
        os.replace(tmp, a.json)


if __name__ == "__main__":
    main()
