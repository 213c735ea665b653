#!/usr/bin/python3
"""Merges the output folders of several `ondine validate` runs of one level into one.

On a machine with idle cores, the long cases can run as separate processes
(`ondine validate --case A --out DIR1`, `--case B --out DIR2`, ...); this script
then writes DEST as if one `ondine validate --case A --case B` had run: the case
folders are copied, validation.json gets the runs and orders of every source (in
the order given), validation.md the table rows, APR comparison lines and orders
of every source, and the figures are drawn again by plot_validation.py.

usage: merge_validation.py DEST SRC [SRC ...]
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


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    dest, sources = argv[0], argv[1:]
    merged = {"level": None, "orders": {}, "runs": []}
    rows, compare, orders = [], [], []
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
        if twice:
            sys.exit(f"merge_validation.py: {path}: case(s) {', '.join(sorted(twice))} already in an earlier source")
        merged["runs"] += j["runs"]
        merged["orders"].update(j["orders"])
        r, c, o = parts(os.path.join(src, "validation.md"))
        rows += r
        compare += c
        orders += o
        for case in dict.fromkeys(run["case"] for run in j["runs"]):
            if os.path.isdir(os.path.join(src, case)):
                shutil.copytree(os.path.join(src, case), os.path.join(dest, case), dirs_exist_ok=True)
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
