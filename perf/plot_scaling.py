#!/usr/bin/env python3
"""Table and plot of perf/scaling.sh: efficiencies from the JSON lines it wrote.
strong: E(p) = T(1) / (p T(p)); weak: E(p) = T(1) / T(p), T the seconds per step."""
import json
import sys

runs = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
stem = sys.argv[2]
rows = []
for kind in ("strong", "weak"):
    rs = sorted((r for r in runs if r["kind"] == kind), key=lambda r: r["ranks"])
    if not rs:
        continue
    t1 = rs[0]["seconds_per_step"] * rs[0]["ranks"] ** (1 if kind == "strong" else 0)
    for r in rs:
        p = r["ranks"]
        e = t1 / (p * r["seconds_per_step"]) if kind == "strong" else t1 / r["seconds_per_step"]
        rows.append((kind, p, r["particles"], r["seconds_per_step"], r["particle_steps_per_second"], e,
                     r.get("halo_share", r["exchange_share"]), r.get("migration_share", 0.0), r.get("rebalance_share", 0.0),
                     r["balance_tau"], r["checkpoint_seconds_per_million"], r.get("oversubscribed", False)))
dim = runs[0].get("dimension", 2) if runs else 2
with open(stem + ".md", "w") as f:
    f.write("| scaling | ranks | particles | s/step | particle-steps/s | efficiency | halo share | migration share | rebalance share | tau | checkpoint s per 1e6 particles |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        ranks = "%d (oversubscribed)" % r[1] if r[11] else "%d" % r[1]
        f.write("| %s | %s | %d | %.4g | %.3g | %.3f | %.3f | %.3f | %.3f | %.3f | %.3g |\n" % ((r[0], ranks) + r[2:11]))
    if any(r[11] for r in rows):
        f.write("\nOversubscribed: more ranks than cores, so the ranks share cores; their efficiency measures the overhead, not scaling.\n")
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3.5))
    for kind in ("strong", "weak"):
        pts = [(r[1], r[5]) for r in rows if r[0] == kind]
        if pts:
            ax.plot(*zip(*pts), "o-", label=kind)
    ax.set_xlabel("MPI ranks (1 OpenMP thread each)")
    ax.set_ylabel("parallel efficiency")
    ax.set_ylim(0, 1.1)
    ax.grid(True, alpha=0.3)
    ax.legend()
    ax.set_title("3D dam break (SPHERIC Test 2)" if dim == 3 else "2D dam break")
    fig.tight_layout()
    fig.savefig(stem + ".png", dpi=90)
except ImportError:
    print("python3-matplotlib is missing: no plot", file=sys.stderr)
