#!/usr/bin/env python3
"""SPHERIC Test 2: one code's sensors against the measured series, by one rule for both codes.

The figures (fixed before any comparison, the same for Ondine and the peer):
  H2, H4: RMS over the code's samples with t <= 2 s of (code - measured interpolated at the
          sample's time), over the column height 0.55 m;
  P1, P3: the first-impact peak (the largest value with t <= 0.8 s) and its time;
  P1:     the first-impact impulse, the trapezoid integral of P1 dt over 0.35-0.60 s (the code's
          series and the measured one, each on its own samples).
Ondine: OUTDIR/probes.csv and OUTDIR/waves.csv (columns P1.pressure, H2.elevation, ...).
The peer:  OUTDIR/sensors_Press.csv and OUTDIR/heights_Elevation.csv of ../shared/peer/sensors_test2_3d.sh
           (MeasureTool; Press_0..7 are P1-P8 at the face, Elevation_0..3 H1-H4).
usage: test2_metrics.py ondine|peer OUTDIR MEASURED_CSV   (prints one JSON object)
"""
import csv
import json
import sys

HEIGHT, T_END, FIRST_IMPACT, IMPULSE = 0.55, 2.0, 0.8, (0.35, 0.60)


def measured_series(path):
    rows = [l for l in open(path) if l.strip() and not l.startswith("#")]
    r = list(csv.DictReader(rows))
    t = [float(x["time"]) for x in r]
    return {k: (t, [float(x[k]) for x in r]) for k in ("P1", "P3", "H2", "H4")}


def ondine_series(out):
    def read(name, cols):
        r = list(csv.DictReader(open(f"{out}/{name}")))
        t = [float(x["time"]) for x in r]
        return {k: (t, [float(x[c]) for x in r]) for k, c in cols.items()}
    s = read("probes.csv", {"P1": "P1.pressure", "P3": "P3.pressure"})
    s.update(read("waves.csv", {"H2": "H2.elevation", "H4": "H4.elevation"}))
    return s


def peer_series(out):
    def read(name, cols):
        lines = open(f"{out}/{name}").read().splitlines()
        head = next(i for i, l in enumerate(lines) if l.startswith("Part;"))
        names = lines[head].split(";")
        rows = [l.split(";") for l in lines[head + 1:] if l.strip()]
        t = [float(x[1]) for x in rows]
        return {k: (t, [float(x[names.index(c)]) for x in rows]) for k, c in cols.items()}
    s = read("sensors_Press.csv", {"P1": "Press_0 [Pa]", "P3": "Press_2 [Pa]"})
    s.update(read("heights_Elevation.csv", {"H2": "Elevation_1 [m]", "H4": "Elevation_3 [m]"}))
    return s


def interpolate(t, v, x):
    lo, hi = 0, len(t) - 1
    if x <= t[0]:
        return v[0]
    if x >= t[hi]:
        return v[hi]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if t[mid] <= x else (lo, mid)
    return v[lo] + (v[hi] - v[lo]) * (x - t[lo]) / (t[hi] - t[lo])


def impulse(t, v, a, b):
    # the trapezoid over [a, b], the ends interpolated
    pts = [(a, interpolate(t, v, a))] + [(x, y) for x, y in zip(t, v) if a < x < b] + [(b, interpolate(t, v, b))]
    return sum((x1 - x0) * (y0 + y1) / 2 for (x0, y0), (x1, y1) in zip(pts, pts[1:]))


def figures(s, m):
    f = {}
    for h in ("H2", "H4"):
        t, v = s[h]
        d = [(y - interpolate(*m[h], x)) ** 2 for x, y in zip(t, v) if x <= T_END]
        f[h + "_rms_error"] = (sum(d) / len(d)) ** 0.5 / HEIGHT
    for p in ("P1", "P3"):
        for name, (t, v) in (("", s[p]), ("_measured", m[p])):
            peak = max((y, x) for x, y in zip(t, v) if x <= FIRST_IMPACT)
            f[p + "_peak" + name] = peak[0]
            f[p + "_peak_time" + name] = peak[1]
    f["P1_impulse"] = impulse(*s["P1"], *IMPULSE)
    f["P1_impulse_measured"] = impulse(*m["P1"], *IMPULSE)
    f["P1_impulse_relative_error"] = f["P1_impulse"] / f["P1_impulse_measured"] - 1
    return f


if __name__ == "__main__":
    code, out, ref = sys.argv[1:4]
    if code not in ("ondine", "peer"):
        sys.exit(f"test2_metrics.py: the code is 'ondine' or 'peer', not '{code}'")
    series = ondine_series(out) if code == "ondine" else peer_series(out)
    print(json.dumps(figures(series, measured_series(ref))))
