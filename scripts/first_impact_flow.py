#!/usr/bin/python3
"""The flow that makes SPHERIC Test 2's first impact, read from the snapshots of 2D runs.

    first_impact_flow.py RUN_DIR [RUN_DIR ...] [--times 0.30,0.40,...] [--face-time 0.47]

Each RUN_DIR holds an `ondine run` of cases/kleefsman_2d.yaml or cases/kleefsman_impact_apr_2d.yaml
(the centre plane: the box's face at x = 0.8245 m, its top at y = 0.161 m, the water coming from
x = 3.22 m), with snapshots at the times asked (`--set time.snapshot_every=10` gives every 10 ms).
With refinement zones the leaves (particles that are not mothers) carry the mass, and the SPH
particles (not guards) the pressure. Fixed measures, the same for every run:
- front: the smallest x of a leaf below y = 0.03 m, beyond the face (x > 0.83 m);
- delivered: the leaves' mass (kg/m) with x < 1.0 m: the water that has reached the box;
- jet: the highest leaf beyond the face (0.8245 < x < 0.95 m), and the mass above the box's top
  there (y > 0.16 m);
- inflow: over 0.95 < x < 1.45 m, the depth (leaves' mass / (rho0 width)), the mass-weighted u_x,
  and the momentum flux rho u^2 h + p h (kN/m);
- face: at --face-time, the SPH particles' mean pressure (kPa) within 0.012 m of the face in bands
  0.02 m high from the floor to the box's top.
"""
import argparse
import glob
import os
import re
import sys

import h5py
import numpy as np

FACE_X, BOX_TOP, RHO0 = 0.8245, 0.161, 1000.0


def snapshots(run):
    xmf = glob.glob(os.path.join(run, "*.xmf"))
    xmf = [f for f in xmf if not f.endswith("_walls.xmf")]
    if not xmf:
        sys.exit(f"first_impact_flow.py: {run}: no snapshot series (*.xmf)")
    times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', open(xmf[0]).read())]
    files = sorted(glob.glob(os.path.join(run, "*_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    return list(zip(times, files))


def at(series, t):
    best = min(series, key=lambda s: abs(s[0] - t))
    return best if abs(best[0] - t) < 2e-3 else None


def fields(path):
    with h5py.File(path, "r") as h:
        x = h["position"][:, :2]
        n = len(x)
        get = lambda k: h[k][:] if k in h else np.zeros(n)
        return x, h["mass"][:], h["velocity"][:, :2], h["pressure"][:], get("mother") == 0, get("guard") == 0


def flow(path):
    x, m, u, p, leaf, sph = fields(path)
    beyond = leaf & (x[:, 0] > 0.83)
    floor = beyond & (x[:, 1] < 0.03)
    jet = leaf & (x[:, 0] > FACE_X) & (x[:, 0] < 0.95)
    inflow = leaf & (x[:, 0] > 0.95) & (x[:, 0] < 1.45) & (x[:, 1] < 0.5)
    depth = m[inflow].sum() / RHO0 / 0.5
    ux = (m[inflow] * u[inflow, 0]).sum() / max(m[inflow].sum(), 1e-300)
    q = inflow & sph
    pm = (m[q] * p[q]).sum() / max(m[q].sum(), 1e-300)
    return {
        "front": x[floor, 0].min() if floor.any() else float("nan"),
        "delivered": m[leaf & (x[:, 0] < 1.0)].sum(),
        "jet_tip": x[jet, 1].max() if jet.any() else float("nan"),
        "jet_mass": m[jet & (x[:, 1] > BOX_TOP)].sum(),
        "depth": depth, "ux": ux, "flux": (RHO0 * ux * ux * depth + pm * depth) / 1e3,
    }


def face(path):
    x, m, u, p, leaf, sph = fields(path)
    s = sph & (x[:, 0] > FACE_X) & (x[:, 0] < FACE_X + 0.012)
    out = []
    for y0 in np.arange(0.0, 0.16, 0.02):
        b = s & (x[:, 1] >= y0) & (x[:, 1] < y0 + 0.02)
        out.append(p[b].mean() / 1e3 if b.any() else float("nan"))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--times", default="0.30,0.36,0.40,0.42,0.44,0.46,0.48")
    ap.add_argument("--face-time", type=float, default=0.47)
    a = ap.parse_args()
    series = {r: snapshots(r) for r in a.runs}
    print("| t (s) | run | front x (m) | delivered, x < 1 m (kg/m) | jet tip y (m) | jet mass above the box (kg/m) "
          "| inflow depth (m) | inflow u_x (m/s) | inflow momentum flux (kN/m) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for t in [float(v) for v in a.times.split(",")]:
        for r in a.runs:
            s = at(series[r], t)
            if s is None:
                continue
            f = flow(s[1])
            print(f"| {s[0]:.3f} | {os.path.basename(os.path.normpath(r))} | {f['front']:.3f} | {f['delivered']:.2f} | "
                  f"{f['jet_tip']:.3f} | {f['jet_mass']:.2f} | {f['depth']:.3f} | {f['ux']:.2f} | {f['flux']:.3f} |")
    print()
    print(f"face pressure (kPa) at t = {a.face_time}, bands of 0.02 m from the floor:")
    print("| run | " + " | ".join(f"{y:.2f}-{y + 0.02:.2f}" for y in np.arange(0.0, 0.16, 0.02)) + " |")
    print("|---|" + "---|" * 8)
    for r in a.runs:
        s = at(series[r], a.face_time)
        if s is not None:
            print(f"| {os.path.basename(os.path.normpath(r))} | " + " | ".join(f"{v:.1f}" for v in face(s[1])) + " |")


if __name__ == "__main__":
    main()
