#!/usr/bin/env python3
"""Plots of `ondine validate`: error against wall time (log-log) per case and
error name, from DIR/validation.json, into DIR/error_vs_wall_time.png."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]
runs = json.load(open(f"{out}/validation.json"))["runs"]
cases = sorted({r["case"] for r in runs})
fig, axes = plt.subplots(1, len(cases), figsize=(4.5 * len(cases), 4), squeeze=False)
for ax, case in zip(axes[0], cases):
    rs = [r for r in runs if r["case"] == case]
    names = sorted({k for r in rs for k in r["errors"] if r["errors"][k] > 0 and k in r["thresholds"]})
    for name in names:
        pts = [(r["wall_seconds"], r["errors"][name]) for r in rs if r["errors"].get(name, 0) > 0]
        if pts:
            ax.loglog(*zip(*pts), "o-", label=name)
    ax.set_title(case)
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(f"{out}/error_vs_wall_time.png", dpi=90)
