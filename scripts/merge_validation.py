#!/usr/bin/python3
"""Merges the output folders of several `ondine validate` runs of one level into one.

On a machine with idle cores, the long cases can run as separate processes
(`ondine validate --case A --out DIR1`, `--case B --out DIR2`, ...); this script
then writes DEST as if one `ondine validate --case A --case B` had run: the case
folders are copied, validation.json gets the runs and orders of every source (in
the order given), validation.md the table rows, APR comparison lines and orders
of every source, and the figures are drawn again by plot_validation.py.

usage: merge_validation.py [--replace] DEST SRC [SRC ...]
--replace: a case found in a later source replaces the same case of the earlier ones
(its runs, table rows, comparison lines and orders; to re-run some cases of a report);
without it a case in two sources is an error.
Then `scripts/plot_validation.py DEST . --docs docs/validation.md` puts DEST into the report.
"""
import json
import os
import shutil
import subprocess
import sys


def parts(md_path):
    """(table rows, APR comparison lines, order lines) of a validation.md written by ondine validate."""
    rows, compare, orders = [], [], []
    section = "head"
    for line in open(md_path).read().split("\n"):
        if line.startswith("## Figures"):
            break
        if line.startswith("Observed orders"):
            section = "orders"
        elif section == "orders" and line.startswith("- "):
            orders.append(line)
        elif line.startswith("| ") and not line.startswith("| case |"):
            rows.append(line)
        elif " against fine:" in line:
            compare.append(line)
    return rows, compare, orders


def of(line):
    """The case a table row, comparison line or order line is about."""
    return line.lstrip("|- ").split(" ")[0].split("/")[0]


def main(argv):
    replace = "--replace" in argv
    argv = [a for a in argv if a != "--replace"]
    if len(argv) < 2:
        sys.exit(__doc__)
    dest, sources = argv[0], argv[1:]
    merged = {"level": None, "orders": {}, "runs": []}
    rows, compare, orders = [], [], []
    case_order = []  # cases in the order first met: a replaced case keeps its place
    os.makedirs(dest, exist_ok=True)
    for src in sources:
        path = os.path.join(src, "validation.json")
        if not os.path.exists(path):
            sys.exit(f"merge_validation.py: {path}: no such file (did that validate run finish?)")
        j = json.load(open(path))
        if merged["level"] not in (None, j["level"]):
            sys.exit(f"merge_validation.py: {path}: level '{j['level']}', expected '{merged['level']}' like the others")
        merged["level"] = j["level"]
        twice = {r["case"] for r in j["runs"]} & {r["case"] for r in merged["runs"]}
        if twice and not replace:
            sys.exit(f"merge_validation.py: {path}: case(s) {', '.join(sorted(twice))} already in an earlier source")
        for run in j["runs"]:
            if run["case"] not in case_order:
                case_order.append(run["case"])
        if twice:  # drop the earlier sources' entries of these cases
            merged["runs"] = [r for r in merged["runs"] if r["case"] not in twice]
            merged["orders"] = {k: v for k, v in merged["orders"].items() if k not in twice}
            rows = [x for x in rows if of(x) not in twice]
            compare = [x for x in compare if of(x) not in twice]
            orders = [x for x in orders if of(x) not in twice]
            for case in twice:
                shutil.rmtree(os.path.join(dest, case), ignore_errors=True)
            print(f"merge_validation.py: {path} replaces {', '.join(sorted(twice))}")
        merged["runs"] += j["runs"]
        merged["orders"].update(j["orders"])
        r, c, o = parts(os.path.join(src, "validation.md"))
        rows += r
        compare += c
        orders += o
        for case in dict.fromkeys(run["case"] for run in j["runs"]):
            if os.path.isdir(os.path.join(src, case)):
                shutil.copytree(os.path.join(src, case), os.path.join(dest, case), dirs_exist_ok=True)
    place = {c: k for k, c in enumerate(case_order)}
    merged["runs"].sort(key=lambda r: place[r["case"]])  # stable: each case's rungs keep their order
    rows.sort(key=lambda x: place.get(of(x), len(place)))
    compare.sort(key=lambda x: place.get(of(x), len(place)))
    orders.sort(key=lambda x: place.get(of(x), len(place)))
    with open(os.path.join(dest, "validation.json.tmp"), "w") as f:
        json.dump(merged, f, indent=2)
        f.write("\n")
    os.replace(os.path.join(dest, "validation.json.tmp"), os.path.join(dest, "validation.json"))
    src_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    subprocess.run(["/usr/bin/python3", os.path.join(src_dir, "scripts", "plot_validation.py"), dest, src_dir], check=True)
    md = [f"# Validation ({merged['level']})", "",
          "| case | resolution | particles | steps | wall s | particle-steps/s | errors | passed |",
          "|---|---|---|---|---|---|---|---|"] + rows + [""]
    for line in compare:
        md += [line, ""]
    md += ["Observed orders (two finest resolutions):", ""] + orders + [""]
    md.append(open(os.path.join(dest, "figures.md")).read())
    with open(os.path.join(dest, "validation.md.tmp"), "w") as f:
        f.write("\n".join(md))
    os.replace(os.path.join(dest, "validation.md.tmp"), os.path.join(dest, "validation.md"))
    failed = [f"{r['case']}/{r.get('variant') or r['resolution']}" for r in merged["runs"] if not r["passed"]]
    print(f"merge_validation.py: {len(merged['runs'])} runs into {dest}; failed: {', '.join(failed) or 'none'}")


if __name__ == "__main__":
    main(sys.argv[1:])
