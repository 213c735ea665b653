#!/usr/bin/python3
"""Where a refined cylinder run's drag goes wrong: the wake's volume, pressure and families.

From the snapshots of one run of `ondine validate --case apr_cylinder_re100_2d` (or any run of
the cylinder cases) in [--from, --to], over the SPH particles (guards excluded):
  - the volume fraction sum(m / rho) / area in bins of --bin m along x, on the axis band
    |y - yc| < --band and in a band --outer away from the axis (1 where the particles tile the
    plane; below 1, holes);
  - the time-mean pressure coefficient on the axis band, (p - p_ref) / (rho0 U^2 / 2), p_ref the
    mean pressure in the upstream box --ref (the background pressure drops out);
  - the wall pressure coefficient Cp(theta) in --sector degree sectors (0 = the front), from
    the particles within --ring m of the body's surface, with the same p_ref;
and, from the run's checkpoint.h5 when there is one (the only file with the parents), the
distance of each daughter to her mother, in finest spacings --dx, on the axis band downstream
of the body and elsewhere (median, 90th percentile, largest).

usage: cylinder_wake.py RUN_DIR [--from T] [--to T] [--centre X,Y] [--radius R] [--U U]
         [--rho0 RHO] [--bin W] [--band H] [--outer Y0,Y1] [--xrange X0,X1] [--ref X0,Y0,X1,Y1]
         [--ring W] [--sector DEG] [--dx DX] [--json OUT]
Defaults: the cylinder of cases/cylinder_re100_apr_2d.yaml (centre 0,0, radius 0.05 m,
U = 1 m/s, rho0 = 1000), bins of 0.05 m over x in [-0.45, 1.2], band 0.1 m, outer band
|y| in [0.3, 0.5], reference box [-0.6, -0.3] x [-0.3, 0.3], ring 0.003 m, sectors of 15
degrees, dx 0.002 m (D / 50), times from 2.4 s.
"""
import argparse
import glob
import json
import os
import sys

import h5py
import numpy as np


def pair(s, n):
    v = [float(a) for a in s.split(",")]
    if len(v) != n:
        raise argparse.ArgumentTypeError(f"expected {n} comma-separated numbers, got '{s}'")
    return v


def snapshots(run_dir, t_from, t_to):
    files = sorted(glob.glob(os.path.join(run_dir, "*_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    out = []
    for f in files:
        with h5py.File(f, "r") as h:
            t = float(h.attrs["time"])
            if t < t_from or t > t_to:
                continue
            sph = (h["guard"][:] == 0) if "guard" in h else np.ones(h["pressure"].shape[0], dtype=bool)
            out.append((t, h["position"][:, :2][sph], h["mass"][:][sph], h["density"][:][sph], h["pressure"][:][sph]))
    return out


def measure(snaps, a):
    edges = np.arange(a.xrange[0], a.xrange[1] + 0.5 * a.bin, a.bin)
    nb = len(edges) - 1
    xc, yc = a.centre
    q = 0.5 * a.rho0 * a.U ** 2
    axis_v, outer_v, axis_p = np.zeros(nb), np.zeros(nb), np.zeros(nb)
    sectors = int(round(180.0 / a.sector))
    wall = np.zeros(sectors)
    wall_n = np.zeros(sectors)
    for t, x, m, rho, p in snaps:
        dx_, dy = x[:, 0] - xc, x[:, 1] - yc
        k = np.digitize(x[:, 0], edges) - 1
        inside = (k >= 0) & (k < nb)
        vol = m / rho
        on_axis = inside & (np.abs(dy) < a.band)
        outer = inside & (np.abs(dy) >= a.outer[0]) & (np.abs(dy) < a.outer[1])
        axis_v += np.bincount(k[on_axis], weights=vol[on_axis], minlength=nb) / (a.bin * 2 * a.band)
        outer_v += np.bincount(k[outer], weights=vol[outer], minlength=nb) / (a.bin * 2 * (a.outer[1] - a.outer[0]))
        ref = (x[:, 0] >= a.ref[0]) & (x[:, 1] >= a.ref[1]) & (x[:, 0] < a.ref[2]) & (x[:, 1] < a.ref[3])
        p_ref = p[ref].mean() if ref.any() else 0.0
        cnt = np.bincount(k[on_axis], minlength=nb)
        s = np.bincount(k[on_axis], weights=p[on_axis] - p_ref, minlength=nb)
        axis_p += np.where(cnt > 0, s / np.maximum(cnt, 1), np.nan) / q
        r = np.hypot(dx_, dy)
        ring = (r >= a.radius) & (r < a.radius + a.ring)
        theta = np.degrees(np.arccos(np.clip(-dx_[ring] / r[ring], -1.0, 1.0)))  # 0 at the front (facing -x)
        j = np.minimum((theta / a.sector).astype(int), sectors - 1)
        wall += np.bincount(j, weights=(p[ring] - p_ref) / q, minlength=sectors)
        wall_n += np.bincount(j, minlength=sectors)
    n = max(len(snaps), 1)
    return {
        "snapshots": len(snaps),
        "x_bins": [[float(edges[i]), float(edges[i + 1])] for i in range(nb)],
        "axis_volume_fraction": (axis_v / n).tolist(),
        "outer_volume_fraction": (outer_v / n).tolist(),
        "axis_cp": (axis_p / n).tolist(),
        "wall_cp_sectors_deg": [[a.sector * i, a.sector * (i + 1)] for i in range(sectors)],
        "wall_cp": np.where(wall_n > 0, wall / np.maximum(wall_n, 1), np.nan).tolist(),
    }


def families(path, a):
    with h5py.File(path, "r") as h:
        if "parent_id" not in h:
            return None
        x, ids, parent = h["position"][:, :2], h["id"][:], h["parent_id"][:]
        birth = h["birth_level"][:]
    where = {int(i): k for k, i in enumerate(ids)}
    out = {}
    for lv in range(1, int(birth.max()) + 1 if len(birth) else 1):
        ks = np.flatnonzero((birth == lv) & (parent >= 0))
        ms = np.array([where.get(int(parent[k]), -1) for k in ks])
        ok = ms >= 0
        ks, ms = ks[ok], ms[ok]
        d = np.hypot(*(x[ks] - x[ms]).T) / a.dx
        wake = (np.abs(x[ks, 1] - a.centre[1]) < a.band) & (x[ks, 0] > a.centre[0] + a.radius)
        entry = {}
        for name, s in (("wake", wake), ("elsewhere", ~wake)):
            entry[name] = ({"daughters": int(s.sum()), "median": float(np.median(d[s])), "p90": float(np.percentile(d[s], 90)),
                            "max": float(d[s].max())} if s.any() else {"daughters": 0})
        out[f"level {lv}"] = entry
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--from", dest="t_from", type=float, default=2.4)
    ap.add_argument("--to", dest="t_to", type=float, default=1e300)
    ap.add_argument("--centre", type=lambda s: pair(s, 2), default=[0.0, 0.0])
    ap.add_argument("--radius", type=float, default=0.05)
    ap.add_argument("--U", type=float, default=1.0)
    ap.add_argument("--rho0", type=float, default=1000.0)
    ap.add_argument("--bin", type=float, default=0.05)
    ap.add_argument("--band", type=float, default=0.1)
    ap.add_argument("--outer", type=lambda s: pair(s, 2), default=[0.3, 0.5])
    ap.add_argument("--xrange", type=lambda s: pair(s, 2), default=[-0.45, 1.2])
    ap.add_argument("--ref", type=lambda s: pair(s, 4), default=[-0.6, -0.3, -0.3, 0.3])
    ap.add_argument("--ring", type=float, default=0.003)
    ap.add_argument("--sector", type=float, default=15.0)
    ap.add_argument("--dx", type=float, default=0.002)
    ap.add_argument("--json")
    a = ap.parse_args()
    if not os.path.isdir(a.run_dir):
        sys.exit(f"cylinder_wake.py: {a.run_dir}: not a folder")
    snaps = snapshots(a.run_dir, a.t_from, a.t_to)
    if not snaps:
        sys.exit(f"cylinder_wake.py: {a.run_dir}: no snapshot (*_NNNNNN.h5) between t = {a.t_from:g} and {a.t_to:g} s")
    res = measure(snaps, a)
    cp = os.path.join(a.run_dir, "checkpoint.h5")
    res["families"] = families(cp, a) if os.path.exists(cp) else None
    print(f"cylinder_wake.py: {res['snapshots']} snapshots of {a.run_dir}")
    print("x bin            | axis volume | outer volume | axis Cp")
    for (x0, x1), v, o, c in zip(res["x_bins"], res["axis_volume_fraction"], res["outer_volume_fraction"], res["axis_cp"]):
        print(f"[{x0:6.3f}, {x1:6.3f}) | {v:11.4f} | {o:12.4f} | {c:7.3f}")
    print("wall Cp by sector (0 = front): " + " ".join(f"{c:.2f}" for c in res["wall_cp"]))
    if res["families"]:
        for lv, e in res["families"].items():
            for name, s in e.items():
                if s["daughters"]:
                    print(f"{lv} daughters {name}: {s['daughters']}, distance to the mother in dx: median {s['median']:.2f}, "
                          f"p90 {s['p90']:.2f}, max {s['max']:.2f}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f, indent=1)


if __name__ == "__main__":
    main()
