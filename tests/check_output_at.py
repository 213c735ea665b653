#!/usr/bin/env python3
"""time.output_at: next_step, checked against the run it must reproduce.

An output changes nothing in the run (OutputFrame), so a run whose outputs are taken at the
end of the first step at or past each instant, its steps never shortened for them, must
follow the same trajectory, bitwise, as the same run with no output between its start and
its end. Its rows must come at the first step end at or past each instant: after the
instant, and less than one step after it. The same case with output_at: exact shortens its
steps to land on the instants and takes more of them.
usage: check_output_at.py ONDINE CASE OUTDIR
"""
import csv
import json
import os
import subprocess
import sys

ondine, case, out = sys.argv[1:4]
duration, interval = 0.01, 0.0002  # an interval of about 1.3 steps: exact shortens most steps


def run(name, *sets):
    d = os.path.join(out, name)
    args = [ondine, "run", case, "--out", d, "--set", f"time.duration={duration}", "--set", "time.snapshot_every=1000000"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(d, "diagnostics.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(d, "summary.json")) as f:
        return rows, json.load(f)


nxt, s_nxt = run("next_step", f"time.output_interval={interval}", "time.output_at=next_step")
one, s_one = run("no_output", f"time.output_interval={duration}")
exact, s_exact = run("exact", f"time.output_interval={interval}", "time.output_at=exact")

fail = []
if s_nxt["steps"] != s_one["steps"]:
    fail.append(f"next_step took {s_nxt['steps']} steps, the run without outputs {s_one['steps']}")
if nxt[-1] != {**one[-1]}:
    fail.append(f"the final rows differ:\n  next_step {nxt[-1]}\n  no output {one[-1]}")
if not s_exact["steps"] > s_nxt["steps"]:
    fail.append(f"exact took {s_exact['steps']} steps, not more than next_step's {s_nxt['steps']}")
times = [float(r["time"]) for r in nxt]
dts = [float(r["dt"]) for r in nxt]
if abs(times[-1] - duration) > 1e-12:
    fail.append(f"the last row is at t = {times[-1]}, not at the end {duration}")
# each instant k * interval: the first row at or past it is less than one step after it
k = 1
while k * interval < duration * (1 - 1e-9):
    tau = k * interval
    first = next(i for i, t in enumerate(times) if t >= tau * (1 - 1e-12))
    if not times[first] - tau < dts[first] * (1 + 1e-9):
        fail.append(f"instant {tau:g} s: first row at {times[first]:g} s, more than its step {dts[first]:g} s after it")
    k += 1
if any(b <= a for a, b in zip(times, times[1:])):
    fail.append("the rows' times do not increase")
print(f"steps: next_step {s_nxt['steps']}, no output {s_one['steps']}, exact {s_exact['steps']}; rows {len(nxt)}")
if fail:
    print("\n".join(fail))
    sys.exit(1)
print("output_at: next_step follows the run without outputs, bitwise")
