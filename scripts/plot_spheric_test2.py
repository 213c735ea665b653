#!/usr/bin/env python3
"""SPHERIC Test 2: a run's sensors against the measured series (Kleefsman et al. 2005).

usage: plot_spheric_test2.py OUT.png RUN_DIR [RUN_DIR ...]
Each RUN_DIR is the output folder of cases/spheric_test2_3d.yaml (probes.csv, waves.csv,
summary.json); the measured series is cases/reference/spheric_test2_kleefsman2005.csv.
Plots P1, P3 (Pa) and H2, H4 (m) over 0-2 s; the pressures are the raw Shepard samples
at the sensor points, unfiltered.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
measured = os.path.join(here, "..", "cases", "reference", "spheric_test2_kleefsman2005.csv")


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#")) if r]
    head, body = rows[0], rows[1:]
    return {h: [float(r[k]) for r in body] for k, h in enumerate(head)}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    exp = read_csv(measured)
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    panels = [("P1", "probes.csv", "P1.pressure", "Pa"), ("P3", "probes.csv", "P3.pressure", "Pa"),
              ("H2", "waves.csv", "H2.elevation", "m"), ("H4", "waves.csv", "H4.elevation", "m")]
    for ax, (name, _, _, unit) in zip(axes.flat, panels):
        sel = [k for k, t in enumerate(exp["time"]) if t <= 2.0]
        ax.plot([exp["time"][k] for k in sel], [exp[name][k] for k in sel], "k-", lw=0.8, label="experiment")
        ax.set_title(name)
        ax.set_xlabel("t (s)")
        ax.set_ylabel(unit)
    for run in sys.argv[2:]:
        with open(os.path.join(run, "summary.json")) as f:
            s = json.load(f)
        label = "dx = %g m, %d particles, %.0f s" % (s["scheme"]["dx"], s["particles"], s["wall_seconds"])
        if "refinement" in s:  # APR: the coarse dx, the finest, and the most particles of one snapshot
            r = s["refinement"]
            label = "APR dx = %g / %g m, %d particles at the end, %.0f s" % (
                s["scheme"]["dx"], s["scheme"]["dx"] / 2 ** (r["levels"] - 1), r["particles"], s["wall_seconds"])
        for ax, (name, file, column, _) in zip(axes.flat, panels):
            d = read_csv(os.path.join(run, file))
            ax.plot(d["time"], d[column], lw=0.8, label=label)
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("SPHERIC Test 2: sensors against Kleefsman et al. (2005)")
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=110)


if __name__ == "__main__":
    main()
