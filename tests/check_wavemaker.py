#!/usr/bin/env python3
"""Checks the wave height made by the piston wavemaker of cases/wave_paddle_2d.yaml
against linear wavemaker theory (Biesel 1951; Dean & Dalrymple eq. 6.19):
  H / S = 2 (cosh 2kh - 1) / (sinh 2kh + 2kh),  omega^2 = g k tanh kh,
with H the crest-to-trough height at a gauge over a window of time (after the
front has passed, before the reflection from the far wall returns).
usage: check_wavemaker.py WAVES_CSV GAUGE T0 T1 STROKE PERIOD DEPTH TOL"""
import math
import sys

import numpy as np

csv, gauge, t0, t1, stroke, period, h, tol = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:])
g = 9.81
omega = 2 * math.pi / period
k = omega * omega / g  # deep-water start, then Newton on omega^2 = g k tanh kh
for _ in range(50):
    f = g * k * math.tanh(k * h) - omega * omega
    df = g * math.tanh(k * h) + g * k * h / math.cosh(k * h) ** 2
    k -= f / df
H_theory = stroke * 2 * (math.cosh(2 * k * h) - 1) / (math.sinh(2 * k * h) + 2 * k * h)
d = np.genfromtxt(csv, delimiter=",", names=True)
col = [n for n in d.dtype.names if n.startswith(gauge.replace(".", ""))][0]
window = (d["time"] >= t0) & (d["time"] <= t1)
z = d[col][window]
H = z.max() - z.min()
err = abs(H - H_theory) / H_theory
print("k = %.4f 1/m, kh = %.3f: Biesel H = %.5f m; measured H = %.5f m at %s over t in [%g, %g] s: %.1f %% off"
      % (k, k * h, H_theory, H, gauge, t0, t1, 100 * err))
sys.exit(0 if err <= tol else 1)
