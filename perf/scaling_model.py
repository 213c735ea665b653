#!/usr/bin/env python3
"""Predicted parallel efficiency of Ondine's distributed runs at 8 to 1024 ranks
(docs/parallel.md), from what one rank measures and a latency-bandwidth model
of the network. Prints markdown tables. All inputs are options with the values
measured on the development machine (2 cores) or typical of a cluster.

Per RK4 step a rank:
  computes  N_p t_p                                   (t_p: seconds per particle-step on one core)
  refreshes its halos 8 times (4 stages x (state, density gradient)), each one
  MPI_Alltoallv: p alpha + H w 8 bytes / beta       (alpha latency, beta bandwidth, w doubles per halo row)
  reduces   ~8 scalars (time step, Verlet check):    8 alpha log2 p
  rebuilds (every ~8 evaluations): migration + halo build, ~2 refreshes' worth.
with H the halo of a cubic subdomain of side L = N_p^(1/D) dx and a ring one
cell (R + skin) wide: H = ((L + 2h)^D - L^D) / dx^D.
Imbalance: the step waits for the slowest rank, T_comp / tau (tau >= the
rebalance threshold)."""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("--t2d", type=float, default=1 / 2.2e5, help="s per particle-step per core, 2D full scheme (measured)")
ap.add_argument("--t3d", type=float, default=1 / 4.0e4, help="s per particle-step per core, 3D full scheme (measured)")
ap.add_argument("--alpha", type=float, default=2e-6, help="message latency (s)")
ap.add_argument("--beta", type=float, default=5e9, help="bandwidth per rank (bytes/s)")
ap.add_argument("--h", type=float, default=3.3, help="halo ring width in dx (R + skin = 3 dx + 0.3 dx)")
ap.add_argument("--tau", type=float, default=0.95, help="balance indicator kept by rebalancing")
a = ap.parse_args()


def step_time(D, n_per_rank, p):
    t_p = a.t2d if D == 2 else a.t3d
    L = n_per_rank ** (1.0 / D)  # in dx
    H = (L + 2 * a.h) ** D - L ** D
    w = 2 * D + 1  # position, velocity, density (the density-gradient refresh: D more, counted below)
    refresh_bytes = H * 8 * (w + D) / 2
    comp = n_per_rank * t_p / a.tau
    comm = 8 * (p * a.alpha + refresh_bytes / a.beta) * (1 + 2 / 8) + 8 * a.alpha * math.log2(max(p, 2))
    return comp, comm, H / n_per_rank


print("| D | scaling | particles per rank | ranks | halo / owned | comm share | efficiency |")
print("|---|---|---|---|---|---|---|")
for D, total, per_rank in ((2, 1e8, 1e5), (3, 1e8, 1e5)):
    for p in (8, 64, 256, 1024):
        c1, _, _ = step_time(D, total, 1)
        c, m, hr = step_time(D, total / p, p)
        print("| %dD | strong, N = %.0e | %.3g | %d | %.3f | %.3f | %.2f |" % (D, total, total / p, p, hr, m / (c + m), (c1 * a.tau) / (p * (c + m))))
    for p in (8, 64, 256, 1024):
        c1, _, _ = step_time(D, per_rank, 1)
        c, m, hr = step_time(D, per_rank, p)
        print("| %dD | weak | %.3g | %d | %.3f | %.3f | %.2f |" % (D, per_rank, p, hr, m / (c + m), (c1 * a.tau) / (c + m)))
