#!/usr/bin/env python3
"""SPHERIC Test 2: a run's sensors against the measured series (Kleefsman et al. 2005).

usage: plot_spheric_test2.py OUT.png RUN_DIR [RUN_DIR ...] [--names P1,P3,H2,H4,E] [--until T]
Each RUN_DIR is the output folder of cases/spheric_test2_3d.yaml or cases/kleefsman_2d.yaml
(wall_sensors.csv, probes.csv, waves.csv, diagnostics.csv, summary.json); the measured series is
cases/reference/spheric_test2_kleefsman2005.csv. Plots the eight pressure sensors P1-P8 (Pa)
and the heights H2, H4 (m) over 0-2 s: solid, the wall sensors (the NFM wall state's pressure
averaged over the sensor's face); dashed, the raw probes (the fluid's pressure
Shepard-interpolated at the same point); both unfiltered. A run without wall_sensors.csv
shows its probes only. --names picks the panels (default P1-P8, H2, H4; E: the mechanical
energy (E_k + E_p) over its first value, from diagnostics.csv, the thesis' Fig. 5.14), --until
the end of the time axis (default 2 s).
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
    args = sys.argv[1:]
    names = ["P%d" % k for k in range(1, 9)] + ["H2", "H4"]
    until = 2.0
    if "--names" in args:
        k = args.index("--names")
        names = args[k + 1].split(",")
        del args[k:k + 2]
    if "--until" in args:
        k = args.index("--until")
        until = float(args[k + 1])
        del args[k:k + 2]
    if len(args) < 2:
        sys.exit(__doc__)
    exp = read_csv(measured)
    rows = (len(names) + 1) // 2
    fig, axes = plt.subplots(rows, 2, figsize=(11, 3 * rows), squeeze=False)
    sel = [k for k, t in enumerate(exp["time"]) if t <= until]
    for ax, name in zip(axes.flat, names):
        if name in exp:
            ax.plot([exp["time"][k] for k in sel], [exp[name][k] for k in sel], "k-", lw=0.8, label="experiment")
        ax.set_title(name if name != "E" else "(E_k + E_p) / E(0), E_p from the floor")
        ax.set_xlabel("t (s)")
        ax.set_ylabel("Pa" if name[0] == "P" else "m" if name[0] == "H" else "")
        ax.set_xlim(0, until)
    for c, run in enumerate(args[1:]):
        colour = "C%d" % c
        with open(os.path.join(run, "summary.json")) as f:
            s = json.load(f)
        label = "dx = %g m, %d particles, %.0f s" % (s["scheme"]["dx"], s["particles"], s["wall_seconds"])
        if "refinement" in s:  # APR: the coarse dx, the finest, and the most particles of one snapshot
            r = s["refinement"]
            label = "APR dx = %g / %g m, %d particles at the end, %.0f s" % (
                s["scheme"]["dx"], s["scheme"]["dx"] / 2 ** (r["levels"] - 1), r["particles"], s["wall_seconds"])
        probes = read_csv(os.path.join(run, "probes.csv"))
        waves = read_csv(os.path.join(run, "waves.csv"))
        path = os.path.join(run, "wall_sensors.csv")
        wall = read_csv(path) if os.path.exists(path) else None
        for ax, name in zip(axes.flat, names):
            if name == "E":
                d = read_csv(os.path.join(run, "diagnostics.csv"))
                e = [k + p for k, p in zip(d["kinetic_energy"], d["potential_energy"])]
                ax.plot(d["time"], [v / e[0] for v in e], color=colour, lw=0.8, label=label)
                continue
            if name[0] == "H":
                ax.plot(waves["time"], waves[name + ".elevation"], color=colour, lw=0.8, label=label)
                continue
            if wall is not None and name + ".pressure" in wall:
                ax.plot(wall["time"], wall[name + ".pressure"], color=colour, lw=0.8, label=label + ", wall sensor")
            if name + ".pressure" in probes:
                ax.plot(probes["time"], probes[name + ".pressure"], color=colour, lw=0.6, ls="--", label=label + ", probe")
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("SPHERIC Test 2: sensors against Kleefsman et al. (2005)")
    fig.tight_layout()
    fig.savefig(args[0], dpi=100)


if __name__ == "__main__":
    main()
