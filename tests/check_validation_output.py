#!/usr/bin/env python3
"""Checks the report of `ondine validate` (usage: check_validation_output.py DIR [REQUIREMENT...]):
every case has its figure, linked from validation.md; every run has its
diagnostics; and each profile.csv holds the solution the errors were computed
from: velocity_l2 (Poiseuille, Couette), pressure_linf (hydrostatic) and
max_speed_decay_error (Taylor-Green) recomputed from it match validation.json.
Each REQUIREMENT is one more bound on the report:
  order:CASE:ERROR:MIN     the observed order of ERROR between CASE's two finest rungs is >= MIN
  max:CASE:DX:ERROR:MAX    ERROR of CASE's run at DX is < MAX"""
import csv
import json
import os
import sys

out = sys.argv[1]
report = json.load(open(f"{out}/validation.json"))
runs = report["runs"]
md = open(f"{out}/validation.md").read()
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def close(a, b, what):
    # 1e-4: the solver interpolates the analytic profile in a 1001-point table; the CSV has 8 digits
    check(abs(a - b) <= 1e-4 * max(abs(b), 1e-12), f"{what}: {a} from profile.csv, {b} in validation.json")


check(len(runs) > 0, "no runs")
for case in {r["case"] for r in runs}:
    check(os.path.getsize(f"{out}/{case}.png") > 1000 if os.path.exists(f"{out}/{case}.png") else False, f"{case}.png")
    check(f"]({case}.png)" in md, f"{case}.png not linked from validation.md")
for r in runs:
    d = os.path.join(out, r["dir"])
    check(os.path.exists(d + "/diagnostics.csv"), d + "/diagnostics.csv")
    e = r["errors"]
    if os.path.exists(d + "/profile.csv"):
        p = columns(d + "/profile.csv")
        if "u_exact" in p:  # L2 over particles of u - u_exact
            num = sum((u - x) ** 2 for u, x in zip(p["u"], p["u_exact"]))
            close((num / sum(x * x for x in p["u_exact"])) ** 0.5, e["velocity_l2"], d + " velocity_l2")
        elif "p_exact" in p:  # deeper than 3 dx, over rho g H (g = 9.81 in the cases; H = z + p_exact / (rho g))
            rgh = r["rho0"] * 9.81 * (p["z"][0] + p["p_exact"][0] / (r["rho0"] * 9.81))
            worst = max(abs(a - b) for a, b in zip(p["p"], p["p_exact"]) if b >= 3 * r["dx"] * r["rho0"] * 9.81)
            close(worst / rgh, e["pressure_linf"], d + " pressure_linf")
        elif "max_speed_exact" in p:
            close(abs(p["max_speed"][-1] - p["max_speed_exact"][-1]) / p["max_speed_exact"][-1], e["max_speed_decay_error"],
                  d + " max_speed_decay_error")
for req in sys.argv[2:]:
    kind, *a = req.split(":")
    if len(a) != {"order": 3, "max": 4}.get(kind, -1):
        check(False, f"requirement {req}: expected order:CASE:ERROR:MIN or max:CASE:DX:ERROR:MAX")
    elif kind == "order":
        case, error, low = a
        got = report["orders"].get(case, {}).get(error)
        check(got is not None and got >= float(low), f"{case} {error} order {got}, asked >= {low}")
        print(f"check_validation_output.py: {case} {error} order {got} (>= {low})")
    elif kind == "max":
        case, dx, error, high = a
        got = [r["errors"].get(error) for r in runs if r["case"] == case and abs(r["dx"] - float(dx)) <= 1e-9 * float(dx)]
        check(len(got) == 1 and got[0] is not None and got[0] < float(high), f"{case} at dx {dx}: {error} {got}, asked < {high}")
        print(f"check_validation_output.py: {case} at dx {dx}: {error} {got} (< {high})")
if failures:
    sys.exit("check_validation_output.py: " + "; ".join(failures))
print(f"check_validation_output.py: {len(runs)} runs checked")
