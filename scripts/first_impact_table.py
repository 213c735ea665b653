#!/usr/bin/env python3
"""SPHERIC Test 2's first impact at P1, read from run folders, as a Markdown table.

    first_impact_table.py RUN_DIR [RUN_DIR ...] [--measured cases/reference/spheric_test2_kleefsman2005.csv]

Each RUN_DIR holds an `ondine run` or `ondine validate` run of cases/spheric_test2_3d.yaml,
cases/kleefsman_2d.yaml or their refined variants (summary.json, wall_sensors.csv, probes.csv).
The figures, the same rule for every run and for the measured series (fixed before comparing):
- peak: the largest sample over 0.35-0.60 s, and its time;
- impulse: the trapezoid rule over 0.35-0.60 s;
- arrival: the first sample after 0.3 s above 2 kPa (probe);
- plateau: the mean over 0.44-0.50 s;
- ringing: the RMS over 0.40-0.52 s of the series less its centred mean over 11 samples
  (11 ms at the runs' 1 kHz, 22 ms in the measured series' 2 ms sampling): the part of the signal
  faster than the water's arrival and stop.
"""
import argparse
import csv
import json
import os
import sys


def series(path, key):
    rows = list(csv.DictReader(line for line in open(path) if not line.startswith("#")))
    return [(float(r["time"]), float(r[key])) for r in rows if r.get(key, "") != ""]


def figures(s):
    w = [(t, v) for t, v in s if 0.35 <= t <= 0.60]
    if not w:
        return None
    pk, tp = max((v, t) for t, v in w)
    imp = sum(0.5 * (w[i][1] + w[i + 1][1]) * (w[i + 1][0] - w[i][0]) for i in range(len(w) - 1))
    arr = next((t for t, v in s if t > 0.3 and v > 2000), None)
    pl = [v for t, v in s if 0.44 <= t <= 0.50]
    r = [(t, v) for t, v in s if 0.40 <= t <= 0.52]
    hp = [(r[i][1] - sum(x[1] for x in r[i - 5:i + 6]) / 11) ** 2 for i in range(5, len(r) - 5)]
    return {"peak": pk, "t_peak": tp, "impulse": imp, "arrival": arr, "plateau": sum(pl) / len(pl) if pl else float("nan"),
            "ringing": (sum(hp) / len(hp)) ** 0.5 if hp else float("nan")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--measured", default="cases/reference/spheric_test2_kleefsman2005.csv")
    a = ap.parse_args()
    print("| run | particles | steps | wall s | P1 sensor: peak (kPa) at (s), impulse (Pa s) | P1 probe: peak (kPa) at (s), impulse (Pa s) |"
          " arrival (s) | plateau 0.44-0.50 s (kPa) | ringing (kPa) | P3 probe peak (kPa) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    m = figures(series(a.measured, "P1"))
    m3 = figures(series(a.measured, "P3"))
    print(f"| measured | | | | | {m['peak'] / 1e3:.1f} at {m['t_peak']:.3f}, {m['impulse']:.0f} | {m['arrival']:.3f} | "
          f"{m['plateau'] / 1e3:.1f} | {m['ringing'] / 1e3:.2f} | {m3['peak'] / 1e3:.1f} |")
    bad = 0
    for d in a.runs:
        try:
            s = json.load(open(os.path.join(d, "summary.json")))
            ws = figures(series(os.path.join(d, "wall_sensors.csv"), "P1.pressure"))
            pr = figures(series(os.path.join(d, "probes.csv"), "P1.pressure"))
            p3 = figures(series(os.path.join(d, "probes.csv"), "P3.pressure"))
        except (OSError, ValueError, KeyError) as e:
            print(f"| {d} | cannot read it: {e} |")
            print(f"first_impact_table.py: {d}: cannot read it: {e}", file=sys.stderr)
            bad += 1
            continue
        if not (ws and pr and p3):
            print(f"| {d} | no samples over 0.35-0.60 s |")
            print(f"first_impact_table.py: {d}: no samples over 0.35-0.60 s", file=sys.stderr)
            bad += 1
            continue
        print(f"| {d} | {s['particles']} | {s['steps']} | {s['wall_seconds']:.1f} | {ws['peak'] / 1e3:.1f} at {ws['t_peak']:.3f}, {ws['impulse']:.0f} | "
              f"{pr['peak'] / 1e3:.1f} at {pr['t_peak']:.3f}, {pr['impulse']:.0f} | {pr['arrival'] or float('nan'):.3f} | "
              f"{pr['plateau'] / 1e3:.1f} | {pr['ringing'] / 1e3:.1f} | {p3['peak'] / 1e3:.1f} |")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
