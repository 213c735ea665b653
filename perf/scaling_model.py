#!/usr/bin/env python3
"""Predicted parallel efficiency of Ondine's distributed runs at 8 to 1024 ranks
(docs/parallel.md), from what the development machine measures and a latency-bandwidth
model of the network. Prints markdown tables.

Per RK4 step a rank:
  computes  N_p t_p                                  (t_p: seconds per particle-step on one core)
  refreshes its halos 8 times (4 stages x (state, density gradient)) plus ~2 refreshes' worth
  at list builds, each an MPI_Alltoallv:  p alpha + H (c_row + 8 w / beta)
            (alpha latency, beta bandwidth, w doubles per halo row, c_row the packing, host
             copies and unpacking per row, measured)
  reduces   ~8 scalars (time step, Verlet check):    8 alpha log2 p
with H the halo of a cubic subdomain of side L = N_p^(1/D) dx and a ring h = R + skin wide:
H = ((L + 2h)^D - L^D) / dx^D. Imbalance: the step waits for the slowest rank, T_comp / tau.

--calibrate FILE (perf/scaling.sh --dim 3 output, JSON lines) takes t_p (3D) from the
1-rank strong run and c_row from the 2-rank runs' halo share: the 2 ranks of the 3D dam
break are cut across the water column (1 x 0.55 m), so each holds a slab halo of
1 x 0.55 x h; c_row = halo seconds per step / (10 refreshes x that slab's rows)."""
import argparse
import json
import math

ap = argparse.ArgumentParser()
ap.add_argument("--t2d", type=float, default=1 / 2.2e5, help="s per particle-step per core, 2D full scheme (measured)")
ap.add_argument("--t3d", type=float, default=1 / 4.0e4, help="s per particle-step per core, 3D full scheme (measured)")
ap.add_argument("--alpha", type=float, default=2e-6, help="message latency (s)")
ap.add_argument("--beta", type=float, default=5e9, help="bandwidth per rank (bytes/s)")
ap.add_argument("--c-row", type=float, default=0.0, help="s per halo row per refresh: packing, copies, unpacking")
ap.add_argument("--h", type=float, default=2.8, help="halo ring width in dx (3D dam break: R + skin = 2.5 dx + 0.3 dx)")
ap.add_argument("--tau", type=float, default=0.95, help="balance indicator kept by rebalancing")
ap.add_argument("--calibrate", help="perf/scaling.sh JSON lines (3D) to take t3d and c_row from")
a = ap.parse_args()

if a.calibrate:
    runs = [json.loads(l) for l in open(a.calibrate) if l.strip()]
    one = [r for r in runs if r["ranks"] == 1 and r["kind"] == "strong"]
    two = [r for r in runs if r["ranks"] == 2 and not r.get("oversubscribed")]
    if one:
        a.t3d = one[0]["seconds_per_step"] / one[0]["particles"]
    rows = []
    for r in two:
        dx = (1.228 * 1.0 * 0.55 / r["particles"]) ** (1 / 3)
        slab = 1.0 * 0.55 * a.h * dx / dx ** 3  # halo rows of each rank: the cut across the column
        rows.append(r["halo_share"] * r["seconds_per_step"] / (10 * slab))
    if rows:
        a.c_row = max(rows)
    print("calibrated on %s: t3d = %.3g s per particle-step (%.3g particle-steps/s per core), c_row = %.3g s per halo row "
          "per refresh (from %d two-rank runs)\n" % (a.calibrate, a.t3d, 1 / a.t3d, a.c_row, len(rows)))


def step_time(D, n_per_rank, p):
    """(computation, communication, halo / owned, the largest communication term's name)"""
    t_p = a.t2d if D == 2 else a.t3d
    L = n_per_rank ** (1.0 / D)  # in dx
    H = (L + 2 * a.h) ** D - L ** D if p > 1 else 0.0
    w = 2 * D + 1  # position, velocity, density (the density-gradient refresh: D more, averaged below)
    rows = H * (a.c_row + 8 * (w + D / 2) / a.beta)
    comp = n_per_rank * t_p / a.tau
    latency = 10 * p * a.alpha + 8 * a.alpha * math.log2(max(p, 2))
    volume = 10 * rows
    largest = "Alltoallv latency (p alpha)" if latency > volume else "halo volume"
    return comp, latency + volume, H / n_per_rank, largest


print("| D | scaling | particles per rank | ranks | halo / owned | comm share | efficiency | largest comm term |")
print("|---|---|---|---|---|---|---|---|")
breaks = []
for D in (2, 3):
    for per_rank in (1e5, 1e6):
        for p in (8, 64, 256, 1024):
            c1, _, _, _ = step_time(D, per_rank, 1)
            c, m, hr, big = step_time(D, per_rank, p)
            e = (c1 * a.tau) / (c + m)
            print("| %dD | weak | %.0e | %d | %.3f | %.3f | %.2f | %s |" % (D, per_rank, p, hr, m / (c + m), e, big))
            if e < 0.8:
                breaks.append("%dD, %.0e per rank, %d ranks: efficiency %.2f, %s" % (D, per_rank, p, e, big))
    total = 1e8 if D == 3 else 1e9
    for p in (8, 64, 256, 1024):
        c1, _, _, _ = step_time(D, total, 1)
        c, m, hr, big = step_time(D, total / p, p)
        e = (c1 * a.tau) / (p * (c + m))
        print("| %dD | strong, N = %.0e | %.3g | %d | %.3f | %.3f | %.2f | %s |" % (D, total, total / p, p, hr, m / (c + m), e, big))
        if e < 0.8:
            breaks.append("%dD, strong N = %.0e, %d ranks: efficiency %.2f, %s" % (D, total, p, e, big))
print("\nBelow 0.8 efficiency:" if breaks else "\nEvery configuration stays at or above 0.8 efficiency.")
for b in breaks:
    print("- " + b)
