#!/usr/bin/python3
"""Pressure noise and long-time particle regularity, per fluid flux (scheme.flux).

For each scheme (delta_sph as the case files say; riemann: Riemann-SPH with MUSCL, Leduc's form;
each also with particle shifting, _shifting; riemann_ale: Leduc's form moved by Oger's transport
velocity (2.101); riemann_vila: Vila's form with mass fluxes (2.84-2.89), Lagrangian;
riemann_vila_ale: Vila's ALE form with Oger's transport velocity; _free: with
scheme.ale.cut_supports: free):
  * hydrostatic_tank_2d run to T_TANK s (20 by default, the shipped 0.5 s damping kept), the
    bottom probe sampled every 2 ms;
  * dam_break_impact_2d (0.35 s: the surge hits the right wall at about 0.2 s), the right-wall
    probe sampled every 0.5 ms.
The pressure noise of a probe is the RMS of its signal minus the signal's centred moving
average over ten acoustic periods of the kernel, 10 R / c0 (R = 3 dx): what remains are the
oscillations at the particle scale, which the physics of these flows does not have (the column's
own acoustic mode, 4 H / c0, is 12 R / c0 in the tank at H / dx = 25 and 20 R / c0 in the dam
break at a / dx = 25, so it stays in the average). The tank's is taken after 2 s (the start-up
wave damped), the dam break's over the whole run, the probes sampled at 2 ms and 0.2 ms.
Long run: dam_break_2d at a/25 to T = t sqrt(2 g / a) = 10 (0.54 s: the surge has hit the far
wall, run up and fallen back), with the case's CFL for delta_sph and 0.5 for riemann.
Regularity at the tank's and the long dam break's last state: the spread (std / mean) of each particle's nearest-
neighbour distance, the smallest distance over dx (clumping), the density bounds; at rest the
lattice stays regular when the spread stays small.
Writes perf/results/pressure-noise-<date>.json and prints one line per run.
usage: perf/pressure_noise.py [--tank-duration 20] [--schemes "delta_sph delta_sph_shifting riemann riemann_shifting"]
                              [--out perf/results]
"""
import argparse, csv, glob, json, os, subprocess, sys, tempfile, time

import numpy as np

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("--tank-duration", type=float, default=20.0)
ap.add_argument("--schemes", default="delta_sph delta_sph_shifting riemann riemann_shifting")
ap.add_argument("--out", default=os.path.join(here, "perf", "results"))
args = ap.parse_args()
ondine = os.environ.get("ONDINE", os.path.join(here, "build", "ondine"))
if not os.access(ondine, os.X_OK):
    sys.exit("perf/pressure_noise.py: build first (make build): no " + ondine)
RIEMANN = ["scheme.flux=riemann", "scheme.delta_sph=0", "scheme.density_gradient=stage"]
VILA = RIEMANN + ["scheme.riemann.variant=vila"]
SCHEMES = {"delta_sph": [], "delta_sph_shifting": ["scheme.shifting=true"],
           "riemann": RIEMANN, "riemann_shifting": RIEMANN + ["scheme.shifting=true"],
           "riemann_ale": RIEMANN + ["scheme.transport=ale"],
           "riemann_ale_free": RIEMANN + ["scheme.transport=ale", "scheme.ale.cut_supports=free"],
           "riemann_vila": VILA, "riemann_vila_ale": VILA + ["scheme.transport=ale"],
           "riemann_vila_ale_free": VILA + ["scheme.transport=ale", "scheme.ale.cut_supports=free"]}
for s in args.schemes.split():
    if s not in SCHEMES:
        sys.exit("perf/pressure_noise.py: unknown scheme '%s' (expected some of %s)" % (s, " ".join(SCHEMES)))


def run(case, sets, out):
    cmd = [ondine, "run", os.path.join(here, "cases", case), "--out", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    env = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "2"))
    t0 = time.time()
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("perf/pressure_noise.py: %s failed:\n%s" % (" ".join(cmd), p.stderr[-2000:]))
    return json.load(open(os.path.join(out, "summary.json"))), time.time() - t0


def probe(out, name):
    rows = list(csv.DictReader(open(os.path.join(out, "probes.csv"))))
    return np.array([float(r["time"]) for r in rows]), np.array([float(r[name + ".pressure"]) for r in rows])


def noise(t, p, window, t_from=0.0):
    """RMS of p minus its centred moving average over `window` seconds, for t >= t_from (and
    at least half a window from either end, where the average is one-sided)."""
    dt = t[1] - t[0]
    k = max(1, int(round(window / dt)))
    k += (k + 1) % 2  # odd, centred
    avg = np.convolve(p, np.ones(k) / k, mode="same")
    half = k // 2
    keep = (t >= t_from) & (np.arange(len(t)) >= half) & (np.arange(len(t)) < len(t) - half)
    return float(np.sqrt(np.mean((p[keep] - avg[keep]) ** 2))), int(keep.sum())


def regularity(out, dx):
    import h5py
    last = sorted(glob.glob(os.path.join(out, "*_[0-9]*.h5")))[-1]
    with h5py.File(last, "r") as f:
        x = np.array(f["position"])
        rho = np.array(f["density"])
    if x.shape[0] < x.shape[1]:
        x = x.T
    d = np.full(len(x), np.inf)
    for i in range(0, len(x), 512):  # brute force in blocks
        b = x[i:i + 512]
        r = np.sqrt(((b[:, None, :] - x[None, :, :]) ** 2).sum(-1))
        r[np.arange(len(b)), np.arange(i, i + len(b))] = np.inf
        d[i:i + len(b)] = r.min(1)
    return {"nearest_distance_spread": float(d.std() / d.mean()), "nearest_distance_min_over_dx": float(d.min() / dx),
            "nearest_distance_mean_over_dx": float(d.mean() / dx), "density_min": float(rho.min()), "density_max": float(rho.max())}


results = []
work = tempfile.mkdtemp()
for scheme in args.schemes.split():
    # the tank: H = 0.5 m, dx = 0.02 m
    out = os.path.join(work, "tank_" + scheme)
    s, wall = run("hydrostatic_tank_2d.yaml", SCHEMES[scheme] + ["time.duration=%g" % args.tank_duration,
                                                                  "time.output_interval=0.002", "time.snapshot_every=1000000"], out)
    c0, H, dx, R = s["scheme"]["c0"], 0.5, s["scheme"]["dx"], s["scheme"]["dx"] * s["scheme"]["R_over_dx"]
    t, p = probe(out, "bottom")
    rms, n = noise(t, p, 10 * R / c0, 2.0)
    late = t >= 2.0
    r = {"case": "hydrostatic_tank_2d", "scheme": scheme, "duration": args.tank_duration, "wall_seconds": wall,
         "steps": s["total_steps"], "probe": "bottom", "window_seconds": 10 * R / c0, "samples": n,
         "pressure_noise_rms_pa": rms, "pressure_noise_over_rho_g_H": rms / (1000 * 9.81 * H),
         "mean_pressure_error_over_rho_g_H": float(abs(p[late].mean() - 1000 * 9.81 * (H - 0.05)) / (1000 * 9.81 * H)),
         "errors": s.get("errors", {})}
    r.update(regularity(out, dx))
    results.append(r)
    print(json.dumps(r), flush=True)
    # the dam break's impact on the right wall: column 2a = 0.1143 m
    out = os.path.join(work, "impact_" + scheme)
    s, wall = run("dam_break_impact_2d.yaml", SCHEMES[scheme] + ["time.output_interval=0.0002", "time.snapshot_every=1000000"], out)
    c0, H, R = s["scheme"]["c0"], 0.1143, s["scheme"]["dx"] * s["scheme"]["R_over_dx"]
    t, p = probe(out, "right_wall")
    rms, n = noise(t, p, 10 * R / c0)
    r = {"case": "dam_break_impact_2d", "scheme": scheme, "wall_seconds": wall, "steps": s["total_steps"], "probe": "right_wall",
         "window_seconds": 10 * R / c0, "samples": n, "pressure_noise_rms_pa": rms,
         "pressure_noise_over_rho_g_2a": rms / (1000 * 9.81 * H), "peak_pressure_pa": float(p.max())}
    results.append(r)
    print(json.dumps(r), flush=True)
    # the dam break to T = 10 (a = 0.05715 m)
    out = os.path.join(work, "long_" + scheme)
    t_end = 10.0 / (2 * 9.81 / 0.05715) ** 0.5
    extra = ["scheme.cfl.acoustic=0.5"] if scheme.startswith("riemann") else []
    s, wall = run("dam_break_2d.yaml", SCHEMES[scheme] + extra + ["discretisation.dx=0.002286", "time.duration=%g" % t_end,
                                                                   "time.output_interval=%g" % (t_end / 10)], out)
    r = {"case": "dam_break_2d_T10", "scheme": scheme, "wall_seconds": wall, "steps": s["total_steps"], "errors": s.get("errors", {})}
    r.update(regularity(out, s["scheme"]["dx"]))
    results.append(r)
    print(json.dumps(r), flush=True)
os.makedirs(args.out, exist_ok=True)
stem = os.path.join(args.out, time.strftime("pressure-noise-%Y%m%d-%H%M%S"))
json.dump({"runs": results, "omp_num_threads": os.environ.get("OMP_NUM_THREADS", "2")}, open(stem + ".json", "w"), indent=1)
print("wrote", stem + ".json")
