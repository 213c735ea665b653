#!/usr/bin/env python3
"""Checks diagnostics.csv's potential_energy and summary.json's mechanical_energy_ratio.

  check_energy.py free_fall RUN G TOL
      a block in free fall (no walls, no pressure): every row's E_k = 1/2 M (g t)^2 and
      E_p = E_p(0) - E_k (energy conserved), and mechanical_energy_ratio = 1, each within TOL
      relative to E_p(0)
  check_energy.py same_start RUN_A RUN_B TOL
      the first rows' potential energies of two runs agree within TOL relative (a refined run
      against its uniform start: a mother and its daughters must not both count)
Exits 1 with a message naming the row and the figure that fails.
"""
import csv
import json
import sys


def rows(run):
    with open(run + "/diagnostics.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def fail(msg):
    print("check_energy.py: " + msg)
    sys.exit(1)


def free_fall(run, g, tol):
    r = rows(run)
    if len(r) < 2:
        fail(f"{run}/diagnostics.csv has {len(r)} rows; expected at least 2")
    e0 = r[0]["potential_energy"]
    if e0 == 0:
        fail(f"{run}/diagnostics.csv: potential_energy is 0 in the first row")
    for row in r:
        ek = 0.5 * row["mass"] * (g * row["time"]) ** 2
        if abs(row["kinetic_energy"] - ek) > tol * abs(e0):
            fail(f"t = {row['time']}: kinetic_energy {row['kinetic_energy']} against 1/2 M (g t)^2 = {ek}")
        if abs(row["potential_energy"] - (e0 - ek)) > tol * abs(e0):
            fail(f"t = {row['time']}: potential_energy {row['potential_energy']} against E_p(0) - E_k = {e0 - ek}")
    ratio = json.load(open(run + "/summary.json"))["errors"].get("mechanical_energy_ratio")
    if ratio is None or abs(ratio - 1) > tol:
        fail(f"mechanical_energy_ratio {ratio} against 1")
    print(f"{len(r)} rows: E_k and E_p as in free fall within {tol} of E_p(0); mechanical_energy_ratio {ratio}")


def same_start(a, b, tol):
    ea, eb = rows(a)[0]["potential_energy"], rows(b)[0]["potential_energy"]
    if abs(ea - eb) > tol * abs(eb):
        fail(f"first-row potential_energy {ea} ({a}) against {eb} ({b})")
    print(f"first-row potential_energy {ea} and {eb}")


if __name__ == "__main__":
    a = sys.argv[1:]
    if len(a) == 4 and a[0] == "free_fall":
        free_fall(a[1], float(a[2]), float(a[3]))
    elif len(a) == 4 and a[0] == "same_start":
        same_start(a[1], a[2], float(a[3]))
    else:
        fail("usage: check_energy.py free_fall RUN G TOL | same_start RUN_A RUN_B TOL")
