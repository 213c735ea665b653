#!/usr/bin/env python3
"""SPHERIC Test 2's first impact against resolution, 2D and 3D, in one figure.

    plot_first_impact.py VALIDATION_JSON OUT_PNG [--extra GPU_JSON ...]

Reads the recorded runs of `ondine validate` (docs/validation/validation.json): the 3D case
file's ladder (spheric_test2_3d, fine_spheric_test2_3d, fine_spheric_test2_3d_thesis,
fine_first_impact_3d) and the 2D ladders (fine_first_impact_2d: the 3D case's c0 = 40 m/s,
R/dx = 2.5; apr_kleefsman_2d's uniform runs: the thesis' 2D c0 = 100 m/s, R/dx = 3), and the
refined 2D runs of apr_first_impact_2d, placed at their finest level's H/dx (two levels: dx / 4). --extra
adds hand runs from a perf/results JSON (perf/results/gpu-h200-20261127-first-impact.json:
its "runs", each with P1_sensor/P1_probe peaks), drawn hollow: not recorded.
The y axis is the P1 first-impact peak's relative error, |peak - measured| / measured
(measured 10.8 kPa, read from the reference series); the x axis H/dx with H = 0.55 m, the column's height.
"""
import argparse
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from first_impact_table import figures, series  # noqa: E402  (the same measure as the docs' tables)

H = 0.55
MEASURED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cases", "reference", "spheric_test2_kleefsman2005.csv")

# (label, case names, a filter on the run, colour, marker[, the finest level's dx over the run's dx])
SERIES = [
    ("3D, c0 40 m/s, R/dx 2.5", ("spheric_test2_3d", "fine_spheric_test2_3d", "fine_spheric_test2_3d_thesis", "fine_first_impact_3d"),
     lambda r: r.get("flux") == "case" and r.get("transport") == "case", "tab:red", "o"),
    ("2D, c0 40 m/s, R/dx 2.5", ("fine_first_impact_2d",), lambda r: True, "tab:blue", "s"),
    ("2D, c0 100 m/s, R/dx 3 (thesis)", ("apr_kleefsman_2d",), lambda r: r.get("variant") in ("coarse", "fine"), "tab:green", "^"),
    ("2D, c0 40 m/s, refined: H/55 to H/220, H/110 to H/440", ("apr_first_impact_2d",),
     lambda r: r.get("variant", "").startswith("apr") and r.get("transport") == "case", "tab:purple", "D", 0.25),
]


def recorded(runs, names, keep, finest=1.0):
    pts = {}
    for r in runs:
        if r["case"] not in names or r.get("status") != "completed" or not keep(r):
            continue
        e = r.get("errors", {})
        if "P1_peak_relative_error" not in e:
            continue
        pts[round(H / (r["dx"] * finest), 3)] = (e["P1_peak_relative_error"], e.get("P1_probe_peak_relative_error"))
    return sorted(pts.items())


def extra_points(path):
    """The hand runs of a perf/results JSON, grouped by dimension."""
    measured_p1 = figures(series(MEASURED, "P1"))["peak"]
    d = json.load(open(path))
    groups = {}
    for r in d.get("runs", {}).values():
        cmd = r.get("command", "")
        m = re.search(r"discretisation\.dx=([0-9.e-]+)", cmd)
        if not m or "apr" in cmd:
            continue
        dx = float(m.group(1))
        key = "3D" if "spheric_test2_3d" in cmd else "2D"
        s, p = r["P1_sensor"]["peak_kPa"] * 1e3, r["P1_probe"]["peak_kPa"] * 1e3
        groups.setdefault(key, []).append((H / dx, (abs(s - measured_p1) / measured_p1, abs(p - measured_p1) / measured_p1)))
    return groups


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("validation_json")
    ap.add_argument("out_png")
    ap.add_argument("--extra", action="append", default=[])
    a = ap.parse_args()
    runs = json.load(open(a.validation_json))["runs"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, which, title in ((axes[0], 0, "wall sensor"), (axes[1], 1, "probe")):
        for label, names, keep, colour, marker, *finest in SERIES:
            pts = [(x, v[which]) for x, v in recorded(runs, names, keep, *finest) if v[which] is not None]
            if pts:
                ax.plot(*zip(*pts), marker=marker, color=colour, label=label + " (recorded)")
        for path in a.extra:
            for key, pts in extra_points(path).items():
                colour = "tab:red" if key == "3D" else "tab:green"
                pts = sorted((x, v[which]) for x, v in pts)
                ax.plot(*zip(*pts), marker="D", color=colour, mfc="none", ls=":", label=key + ", GPU hand runs (" + path.split("/")[-1] + ")")
        ax.axhline(0.15, color="grey", ls="--", lw=0.8, label="15 % (issue 39's goal)" if which else None)
        ax.set_xscale("log")
        ax.set_ylim(bottom=0)
        ax.set_xlabel("H / dx (H = 0.55 m)")
        ax.set_title("P1 first-impact peak, " + title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("|peak - measured| / measured (10.8 kPa)")
    axes[1].legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(a.out_png, dpi=110)


if __name__ == "__main__":
    main()
