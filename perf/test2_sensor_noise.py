#!/usr/bin/env python3
"""SPHERIC Test 2: the pressure noise of the box-face sensors P1-P4, run by run, by one rule.

The figures (fixed before any comparison, the same for every run and for the measured series):
  noise:   RMS over 0.5 <= t <= 2.0 s (after the first impact) of p - p_smooth, p_smooth the
           centred 20 ms moving mean of the series on its own samples: the part faster than
           50 Hz, which the experiment's slow sloshing load does not have;
  rms:     RMS over 0.35 <= t <= 2.0 s of (run - measured interpolated at the run's samples);
  peak:    the largest value with t <= 0.8 s (the first impact).
Runs: OUTDIR/wall_sensors.csv (columns P1.pressure ...); the measured: MEASURED_CSV (P1-P8).
usage: test2_sensor_noise.py MEASURED_CSV LABEL=OUTDIR [LABEL=OUTDIR ...]   (prints one JSON object)
"""
import bisect
import csv
import json
import math
import sys

SENSORS = ("P1", "P2", "P3", "P4")
NOISE, RMS, FIRST_IMPACT, WINDOW = (0.5, 2.0), (0.35, 2.0), 0.8, 0.020


def measured(path):
    rows = [l for l in open(path) if l.strip() and not l.startswith("#")]
    r = list(csv.DictReader(rows))
    t = [float(x["time"]) for x in r]
    return {k: (t, [float(x[k]) for x in r]) for k in SENSORS}


def run(out):
    r = list(csv.DictReader(open(f"{out}/wall_sensors.csv")))
    t = [float(x["time"]) for x in r]
    return {k: (t, [float(x[f"{k}.pressure"]) for x in r]) for k in SENSORS}


def interp(t, v, x):
    i = bisect.bisect_left(t, x)
    if i <= 0:
        return v[0]
    if i >= len(t):
        return v[-1]
    w = (x - t[i - 1]) / (t[i] - t[i - 1])
    return v[i - 1] + w * (v[i] - v[i - 1])


def noise(t, v):
    # prefix sums for the centred moving mean over +-WINDOW/2
    c = [0.0]
    for x in v:
        c.append(c[-1] + x)
    acc, n = 0.0, 0
    for i, ti in enumerate(t):
        if not NOISE[0] <= ti <= NOISE[1]:
            continue
        lo = bisect.bisect_left(t, ti - WINDOW / 2)
        hi = bisect.bisect_right(t, ti + WINDOW / 2)
        mean = (c[hi] - c[lo]) / (hi - lo)
        acc += (v[i] - mean) ** 2
        n += 1
    return math.sqrt(acc / n) if n else float("nan")


def figures(series, ref):
    f = {}
    for k in SENSORS:
        t, v = series[k]
        f[f"{k}_noise_Pa"] = noise(t, v)
        f[f"{k}_peak_Pa"] = max((x for ti, x in zip(t, v) if ti <= FIRST_IMPACT), default=float("nan"))
        if ref is not None:
            rt, rv = ref[k]
            d = [(x - interp(rt, rv, ti)) ** 2 for ti, x in zip(t, v) if RMS[0] <= ti <= RMS[1]]
            f[f"{k}_rms_Pa"] = math.sqrt(sum(d) / len(d)) if d else float("nan")
    return f


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    ref = measured(sys.argv[1])
    out = {"measured": figures(ref, None)}
    for arg in sys.argv[2:]:
        label, _, path = arg.partition("=")
        out[label] = figures(run(path), ref)
    print(json.dumps(out, indent=1, sort_keys=True))


if __name__ == "__main__":
    main()
