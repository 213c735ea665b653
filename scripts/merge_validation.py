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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_validation import primary_error, scheme_label  # noqa: E402

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


def schemes_md(runs):
    """Per accuracy case run at the quick level with several schemes: its first error and wall time
    at each resolution, one column per scheme (the quick level's runs, made in one sitting so
    that their times compare)."""
    runs = [r for r in runs if r.get("level") == "quick" and not r.get("variant")]
    cases = [c for c in dict.fromkeys(r["case"] for r in runs) if not c.startswith(("stability", "apr_"))]
    labels = list(dict.fromkeys(scheme_label(r) for r in runs if r["case"] in cases))
    md = []
    for case in cases:
        rs = [r for r in runs if r["case"] == case]
        if len({scheme_label(r) for r in rs}) < 2 or not primary_error(rs):
            continue
        name = primary_error(rs)
        for res in sorted({r["resolution"] for r in rs}):
            cells = []
            for lab in labels:
                at = [r for r in rs if scheme_label(r) == lab and r["resolution"] == res and name in r["errors"]]
                cells.append(f"{fmt(at[0]['errors'][name])} in {fmt(at[0]['wall_seconds'])} s" if at else "")
            md.append(f"| {case} | {fmt(res)} | {name} | " + " | ".join(cells) + " |")
    if not md:
        return []
    return (["Schemes side by side, quick level (each case's first bounded error and the run's wall time; "
             "each run's date and threads are in validation.json):", "",
             "| case | resolution | error | " + " | ".join(labels) + " |", "|---|---|---|" + "---|" * len(labels)] + md + [""])


def where(run):
    """What the run's times were measured on: the GPU's name, else the host's threads."""
    device = run.get("device", "host")
    return device if device != "host" else run.get("threads", "?")


def report_md(record, figures):
    runs = record["runs"]
    md = ["# Validation (the record)", "",
          "| case | scheme | level | resolution | particles | steps | threads or GPU | wall s | particle-steps/s | errors | passed |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        md.append(f"| {r['case']} | {scheme_label(r)} | {r.get('level', 'full')} | {fmt(r['resolution'])}"
                  + (f" ({r['variant']})" if r.get("variant") else "")
                  + f" | {r['particles']} | {r['steps']} | {where(r)} | {fmt(r['wall_seconds'])} | "
                  f"{fmt(r.get('particle_steps_per_second', 0))} | {errors_text(r)} | {'yes' if r['passed'] else '**no**'} |")
    md.append("")
    md += schemes_md(runs)
    ratios = ("near_wall_error_over_fine", "wall_time_over_fine", "cpu_time_over_fine", "probe_pressure_difference_vs_fine",
              "cpu_time_over_global_step")
    for r in runs:
        if r.get("variant") and r["variant"] != "fine" and any(k in r["errors"] for k in ratios):
            md += [f"{r['case']} / {r['variant']} ({scheme_label(r)}, {r.get('level', 'full')}) against fine: "
                   + " ".join(f"{k} {fmt(r['errors'][k])};" for k in ratios if k in r["errors"]), ""]
    md += ["Observed orders (two finest resolutions):", ""]
    for key, errs in sorted(record["orders"].items()):
        md += [f"- {key} / {name}: {fmt(order)}" for name, order in errs.items()]
    md += ["", figures]
    return "\n".join(md)


def write_atomically(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def copy_run(src, dest, run):
    """Copies a run's folders (and its contrast run's) from SRC to DEST. The folders of a validate
    output are named by case and resolution only, so runs of another scheme or level go to
    <case>/<level>_<flux>_<transport>/... in DEST, and their `dir` says so."""
    _, flux, transport, level = group(run)
    for key in ("dir", "contrast_dir"):
        if key not in run or not os.path.isdir(os.path.join(src, run[key])):
            continue
        case, rest = run[key].split("/", 1)
        to = run[key] if (flux, transport, level) == ("case", "case", "full") else f"{case}/{level}_{flux}_{transport}/{rest}"
        shutil.copytree(os.path.join(src, run[key]), os.path.join(dest, to), dirs_exist_ok=True)
        run[key] = to


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
        if os.path.abspath(src) != os.path.abspath(dest):
            for run in new:
                copy_run(src, dest, run)
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
