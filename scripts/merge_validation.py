#!/usr/bin/python3
"""Merges the output folders of `ondine validate` runs, and the recorded report, into one.

The record (docs/validation/validation.json) holds every run the docs quote, each with its
level (quick or full), the scheme asked (flux, transport: "case" for the case file's) and the one
it resolved to, the commit and the threads. New runs join it this way:

    build/ondine validate --case duct_3d --level full --out out/v/duct
    build/ondine validate --level quick --flux riemann --out out/v/riemann
    scripts/merge_validation.py --replace out/record docs/validation out/v/duct out/v/riemann
    scripts/plot_validation.py out/record . --docs docs/validation.md

A source is any folder with a validation.json: an `ondine validate` output (its case folders are
copied, so the figures can show their solutions) or a record (its runs have no folders; their
per-case figures are kept as they are). Runs are grouped by (case, flux, transport, level): a
group found in a later source replaces the same group of the earlier ones with --replace, and is
an error without it. DEST gets validation.json (the runs, sorted by case in the order first met;
`orders` per case and scheme) and validation.md (the table, the APR comparisons and the orders,
made from the JSON), and the figures (plot_validation.py).

usage: merge_validation.py [--replace] DEST SRC [SRC ...]
"""
import json
import os
import shutil
import subprocess
import sys

FLUX = {"delta_sph": "δ-SPH", "riemann": "Riemann (Leduc)", "riemann_vila": "Riemann (Vila)"}
TRANSPORT = {"lagrangian": "", "shifting": " + shifting", "ale": " + ALE", "ale_free": " + ALE (free)"}


def scheme_label(run):
    """The scheme a run resolved to, as the report names it (δ-SPH + shifting, Riemann (Vila) + ALE, ...)."""
    s = run.get("scheme") or {}
    return FLUX.get(s.get("flux"), "?") + TRANSPORT.get(s.get("transport"), "")


def group(run):
    return (run["case"], run.get("flux", "case"), run.get("transport", "case"), run.get("level", "full"))


def order_key(case, flux, transport):
    return case if (flux, transport) == ("case", "case") else f"{case} [{flux}, {transport}]"


def fmt(v):
    """4 significant digits, as `ondine validate` prints its figures."""
    return f"{v:.4g}"


def errors_text(run):
    e, th = run["errors"], run.get("thresholds", {})
    t = "" if run.get("status") == "completed" else f"**{run.get('status')}** {run.get('message', '')}; "
    for name, bound in sorted(th.items()):
        v = e.get(name)
        t += f"{name} {fmt(v) if v is not None else 'missing'}" + ("" if v is not None and v <= bound else f" (> {fmt(bound)})") + "; "
    for name in run.get("shown", []):
        if name in e:
            t += f"{name} {fmt(e[name])} (not bounded); "
    return t + run.get("note", "")


def report_md(record, figures):
    runs = record["runs"]
    md = ["# Validation (the record)", "",
          "| case | scheme | level | resolution | particles | steps | threads | wall s | particle-steps/s | errors | passed |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        md.append(f"| {r['case']} | {scheme_label(r)} | {r.get('level', 'full')} | {fmt(r['resolution'])}"
                  + (f" ({r['variant']})" if r.get("variant") else "")
                  + f" | {r['particles']} | {r['steps']} | {r.get('threads', '?')} | {fmt(r['wall_seconds'])} | "
                  f"{fmt(r.get('particle_steps_per_second', 0))} | {errors_text(r)} | {'yes' if r['passed'] else '**no**'} |")
    md.append("")
    ratios = ("near_wall_error_over_fine", "wall_time_over_fine", "cpu_time_over_fine", "probe_pressure_difference_vs_fine")
    for r in runs:
        if r.get("variant") and r["variant"] != "fine" and any(k in r["errors"] for k in ratios):
            md += [f"{r['case']} / {r['variant']} ({scheme_label(r)}, {r.get('level', 'full')}) against fine: "
                   + " ".join(f"{k} {fmt(r['errors'][k])};" for k in ratios if k in r["errors"]), ""]
    md += ["Observed orders (two finest resolutions):", ""]
    for key, errs in record["orders"].items():
        md += [f"- {key} / {name}: {fmt(order)}" for name, order in errs.items()]
    md += ["", figures]
    return "\n".join(md)


def write_atomically(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main(argv):
    replace = "--replace" in argv
    argv = [a for a in argv if a != "--replace"]
    if len(argv) < 2:
        sys.exit(__doc__)
    dest, sources = argv[0], argv[1:]
    runs, orders = [], {}
    case_order = []  # cases in the order first met: a replaced case keeps its place
    os.makedirs(dest, exist_ok=True)
    for src in sources:
        path = os.path.join(src, "validation.json")
        if not os.path.exists(path):
            sys.exit(f"merge_validation.py: {path}: no such file (did that validate run finish?)")
        try:
            j = json.load(open(path))
        except json.JSONDecodeError as e:
            sys.exit(f"merge_validation.py: {path}: not JSON ({e})")
        new = []
        for run in j["runs"]:  # a validate output's runs take its level and scheme when they lack their own
            run.setdefault("level", j.get("level", "full"))
            run.setdefault("flux", j.get("flux", "case"))
            run.setdefault("transport", j.get("transport", "case"))
            new.append(run)
        twice = {group(r) for r in new} & {group(r) for r in runs}
        if twice and not replace:
            sys.exit(f"merge_validation.py: {path}: run group(s) {sorted(twice)} already in an earlier source (--replace to replace them)")
        if twice:
            runs = [r for r in runs if group(r) not in twice]
            for case, flux, transport, _ in twice:
                orders.pop(order_key(case, flux, transport), None)
            print(f"merge_validation.py: {path} replaces {', '.join(f'{c} [{f}, {t}, {lv}]' for c, f, t, lv in sorted(twice))}")
        for run in new:
            if run["case"] not in case_order:
                case_order.append(run["case"])
        runs += new
        orders.update(j.get("orders", {}))
        for case in dict.fromkeys(r["case"] for r in new):
            if os.path.isdir(os.path.join(src, case)) and os.path.abspath(src) != os.path.abspath(dest):
                shutil.copytree(os.path.join(src, case), os.path.join(dest, case), dirs_exist_ok=True)
    place = {c: k for k, c in enumerate(case_order)}
    runs.sort(key=lambda r: place[r["case"]])  # stable: each case's rungs keep their order
    levels = sorted({r["level"] for r in runs})
    record = {"level": levels[0] if len(levels) == 1 else "mixed", "orders": orders, "runs": runs}
    write_atomically(os.path.join(dest, "validation.json"), json.dumps(record, indent=2, sort_keys=True) + "\n")
    src_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    subprocess.run(["/usr/bin/python3", os.path.join(src_dir, "scripts", "plot_validation.py"), dest, src_dir], check=True)
    write_atomically(os.path.join(dest, "validation.md"), report_md(record, open(os.path.join(dest, "figures.md")).read()))
    failed = [f"{r['case']}/{r.get('variant') or r['resolution']} [{scheme_label(r)}, {r['level']}]" for r in runs if not r["passed"]]
    print(f"merge_validation.py: {len(runs)} runs into {dest}; failed: {', '.join(failed) or 'none'}")


if __name__ == "__main__":
    main(sys.argv[1:])
