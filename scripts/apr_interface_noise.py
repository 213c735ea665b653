#!/usr/bin/python3
"""Pressure noise at the level interface of an APR run, against the uniform runs.

The APR requirement: "no spurious pressure oscillation at level interfaces (the pressure jump
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
         [--R R] [--rho-g-H P] [--json OUT] [--breakdown] [--per-snapshot]
         [--wall x0,y0,x1,y1 ...] [--inside x0,y0,x1,y1]
CASE_DIR holds the folders coarse/, apr/ and fine/ of `ondine validate --case
apr_dam_break_2d` (defaults: the dam break's impact box, x = 0.2 m below
y = 0.1 m and y = 0.1 m right of x = 0.2 m; R = 3 a / 25; rho0 g 2a).

--breakdown splits the same samples (the default figures are unchanged) by: the
interface segment nearest to the particle; the side of the interface (inside the
zone --inside, default the impact box, or outside it); the particle's level (APR);
near a wall (within 1.5 dx_coarse = R / 2 of a --wall segment, default the tank's
floor and right wall) or not; flagged free surface / within R of a flagged particle /
farther (the bulk); and the "one-sidedness" |sum_j w_j (x_j - x_i)| / (R_i sum_j w_j)
of the fit's support (above 0.15: a support cut by a wall or a surface). Each part
with its RMS and sample count in the three runs, so that equally surface-laden parts
of the band can be compared. --per-snapshot prints the RMS of each snapshot.
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
    """P_i minus the linear least-squares fit of its neighbours at x_i, for i in band;
    with the indices i kept and the one-sidedness of each fit's support."""
    tree = cKDTree(x)
    out, kept, side = [], [], []
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
        kept.append(i)
        side.append(np.linalg.norm(w @ d) / (R_i[i] * w.sum()))
    return np.array(out), np.array(kept, dtype=int), np.array(side)


def measure(run_dir, segments, R, t_from, t_to, walls=(), inside=None):
    files = sorted(glob.glob(os.path.join(run_dir, "*_[0-9][0-9][0-9][0-9][0-9][0-9].h5")))
    if not files:
        sys.exit(f"apr_interface_noise.py: no snapshots in {run_dir}")
    values, parts, snaps = [], [], 0
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
            fs = h["free_surface"][:] if "free_surface" in h else np.zeros(len(P), dtype=int)
        x, P, birth, fs = x[sph], P[sph], birth[sph], fs[sph]
        R_i = R / 2.0 ** birth  # a particle's radius is that of the level it was born on
        dseg = np.array([segment_distance(x, a, b) for a, b in segments])
        d = np.min(dseg, axis=0)
        v, kept, side = noise(x, P, R_i, d < R)
        values.append(v)
        snaps += 1
        # attributes of each sample, for --breakdown and --per-snapshot
        xs = x[kept]
        dwall = np.min([segment_distance(xs, a, b) for a, b in walls], axis=0) if walls else np.full(len(kept), np.inf)
        dfs = cKDTree(x[fs > 0]).query(xs)[0] if np.any(fs > 0) else np.full(len(kept), np.inf)
        ins = ((xs >= inside[0]) & (xs <= inside[1])).all(axis=1) if inside is not None else np.zeros(len(kept), bool)
        parts.append(np.column_stack([np.full(len(kept), t), np.argmin(dseg[:, kept], axis=0), ins, birth[kept],
                                      dwall, fs[kept] > 0, dfs, side]))
    v = np.concatenate(values) if values else np.array([])
    out = {"snapshots": snaps, "samples": int(v.size), "rms": float(np.sqrt(np.mean(v * v))) if v.size else float("nan")}
    return out, v, (np.concatenate(parts) if parts else np.zeros((0, 8)))


def breakdown(samples, R, segments, rho_g_H):
    """rows (name, selector over the attribute columns) of --breakdown"""
    rows = [("all", lambda a: np.ones(len(a), bool))]
    for k in range(len(segments)):
        (x0, y0), (x1, y1) = segments[k]
        rows.append((f"segment {x0:g},{y0:g}-{x1:g},{y1:g}", lambda a, k=k: a[:, 1] == k))
        for ins, name in ((1, "inside the zone"), (0, "outside")):
            rows.append((f"  {name}", lambda a, k=k, ins=ins: (a[:, 1] == k) & (a[:, 2] == ins)))
    for lv in range(int(max(a[:, 3].max() if len(a) else 0 for _, a in samples.values())) + 1):
        rows.append((f"level {lv}", lambda a, lv=lv: a[:, 3] == lv))
    rows += [(f"within R/2 of a wall", lambda a: a[:, 4] < 0.5 * R),
             (f"farther from the walls", lambda a: a[:, 4] >= 0.5 * R),
             ("flagged free surface", lambda a: a[:, 5] > 0),
             ("not flagged, within R of one", lambda a: (a[:, 5] == 0) & (a[:, 6] < R)),
             ("farther than R from the surface (bulk)", lambda a: a[:, 6] >= R),
             ("one-sided support (> 0.15)", lambda a: a[:, 7] > 0.15),
             ("two-sided support (<= 0.15)", lambda a: a[:, 7] <= 0.15)]
    res = {}
    print(f"{'part of the band':40s}" + "".join(f" | {run:>19s}" for run in samples))
    for name, sel in rows:
        line, entry = f"{name:40s}", {}
        for run, (v, a) in samples.items():
            s = sel(a) if len(a) else np.zeros(0, bool)
            rms = float(np.sqrt(np.mean(v[s] ** 2))) / rho_g_H if s.any() else float("nan")
            entry[run] = {"rms_over_rho_g_H": rms, "samples": int(s.sum())}
            line += f" | {rms:.3e} ({int(s.sum()):5d})"
        res[name.strip()] = entry
        print(line)
    return res


def per_snapshot(samples, rho_g_H):
    times = np.unique(np.concatenate([a[:, 0] for _, a in samples.values()]))
    res = []
    print(f"{'t (s)':>7s}" + "".join(f" | {run:>16s}" for run in samples))
    for t in times:
        line, entry = f"{t:7.3f}", {"t": float(t)}
        for run, (v, a) in samples.items():
            s = np.abs(a[:, 0] - t) < 1e-9
            rms = float(np.sqrt(np.mean(v[s] ** 2))) / rho_g_H if s.any() else float("nan")
            entry[run] = rms
            line += f" | {rms:.3e} ({int(s.sum()):4d})"
        res.append(entry)
        print(line)
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case_dir")
    ap.add_argument("--interface", nargs="+", default=["0.2,0.0,0.2,0.1", "0.2,0.1,0.3,0.1"])
    ap.add_argument("--from", dest="t_from", type=float, default=0.15)
    ap.add_argument("--to", dest="t_to", type=float, default=1e30)
    ap.add_argument("--R", type=float, default=3 * 0.05715 / 25)
    ap.add_argument("--rho-g-H", type=float, default=1000.0 * 9.81 * 2 * 0.05715)
    ap.add_argument("--json")
    ap.add_argument("--breakdown", action="store_true", help="the band split by segment, side, level, wall, free surface")
    ap.add_argument("--per-snapshot", action="store_true", help="the RMS of each snapshot")
    ap.add_argument("--wall", nargs="+", default=["0.0,0.0,0.3,0.0", "0.3,0.0,0.3,0.3"], help="walls for --breakdown")
    ap.add_argument("--inside", default="0.2,-0.01,0.3,0.1", help="the zone's box x0,y0,x1,y1 for --breakdown")
    a = ap.parse_args()

    def segs(strings, what):
        out = []
        for s in strings:
            v = [float(c) for c in s.split(",")]
            if len(v) != 4:
                sys.exit(f"apr_interface_noise.py: {what} '{s}': expected x0,y0,x1,y1")
            out.append((np.array(v[:2]), np.array(v[2:])))
        return out

    segments = segs(a.interface, "--interface")
    walls = segs(a.wall, "--wall")
    inside = np.array(segs([a.inside], "--inside")[0])
    res, samples = {}, {}
    for run in ("coarse", "apr", "fine"):
        m, v, attrs = measure(os.path.join(a.case_dir, run), segments, a.R, a.t_from, a.t_to, walls, inside)
        m["rms_over_rho_g_H"] = m["rms"] / a.rho_g_H
        res[run] = m
        samples[run] = (v, attrs)
        print(f"{run:6s}: interface band pressure noise {m['rms_over_rho_g_H']:.4e} rho0 g H "
              f"({m['samples']} samples, {m['snapshots']} snapshots)")
    worst_uniform = max(res["coarse"]["rms"], res["fine"]["rms"])
    res["apr_over_noisier_uniform"] = res["apr"]["rms"] / worst_uniform
    res["apr_over_fine"] = res["apr"]["rms"] / res["fine"]["rms"]
    print(f"APR / noisier uniform run: {res['apr_over_noisier_uniform']:.3f}; APR / fine: {res['apr_over_fine']:.3f}")
    if a.breakdown:
        res["breakdown"] = breakdown(samples, a.R, segments, a.rho_g_H)
    if a.per_snapshot:
        res["per_snapshot"] = per_snapshot(samples, a.rho_g_H)
    if a.json:
        tmp = a.json + ".tmp"
        with open(tmp, "w") as f:
            json.dump(res, f, indent=1)
        os.replace(tmp, a.json)


if __name__ == "__main__":
    main()
