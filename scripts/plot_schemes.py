#!/usr/bin/env python3
"""The validation cases side by side across schemes: error against wall time per case, one line
per `ondine validate` run (each run with its --flux and --transport), and a Markdown table.

usage: plot_schemes.py OUT DIR [DIR ...]
   each DIR an `ondine validate --flux F --transport T --out DIR` folder (its validation.json)

Writes OUT/schemes_<case>.png per case and OUT/schemes.md. The error of a case is each of its
bounded errors (the thresholds of ondine validate, without mass_drift and wall_leaks, which are
conservation checks); wall times are those of the runs as they were measured, so compare them
only between runs made in one sitting."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SKIP = {"mass_drift", "wall_leaks", "wall_crossings", "non_finite"}


def label(j):
    return "flux %s, transport %s" % (j.get("flux", "case"), j.get("transport", "case"))


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out, dirs = argv[1], argv[2:]
    os.makedirs(out, exist_ok=True)
    runs = []  # (label, run)
    for d in dirs:
        path = os.path.join(d, "validation.json")
        if not os.path.exists(path):
            sys.exit("plot_schemes.py: no %s (run ondine validate --out %s first)" % (path, d))
        j = json.load(open(path))
        runs += [(label(j), r) for r in j["runs"]]
    labels = list(dict.fromkeys(l for l, _ in runs))
    cases = list(dict.fromkeys(r["case"] for _, r in runs))
    md = ["| case | resolution | error | " + " | ".join(labels) + " |", "|---|---|---|" + "---|" * len(labels)]
    for case in cases:
        rs = [(l, r) for l, r in runs if r["case"] == case]
        metrics = sorted({k for _, r in rs for k in r.get("thresholds", {}) if k not in SKIP})
        if not metrics:
            continue
        fig, axes = plt.subplots(1, len(metrics), figsize=(5 * len(metrics), 3.8), squeeze=False)
        for ax, m in zip(axes[0], metrics):
            for l in labels:
                pts = sorted((r["wall_seconds"], r["errors"][m]) for ll, r in rs if ll == l and m in r.get("errors", {})
                             and r["errors"][m] > 0)
                if pts:
                    ax.loglog(*zip(*pts), "o-", label=l)
            bound = max((r["thresholds"][m] for _, r in rs if m in r.get("thresholds", {})), default=None)
            if bound:
                ax.axhline(bound, color="k", ls=":", lw=1, label="bound %g" % bound)
            ax.set_xlabel("wall time (s)")
            ax.set_ylabel(m)
            ax.set_title(case, fontsize=9)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=6)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "schemes_%s.png" % case), dpi=80)
        plt.close(fig)
        for res in sorted({r["resolution"] for _, r in rs}):
            for m in metrics:
                cells = []
                for l in labels:
                    hit = [r for ll, r in rs if ll == l and r["resolution"] == res]
                    if not hit:
                        cells.append("–")
                    elif hit[0].get("status") not in (None, "completed") and m not in hit[0].get("errors", {}):
                        cells.append(hit[0].get("status", "failed"))
                    else:
                        e = hit[0]["errors"].get(m)
                        ok = "" if hit[0].get("passed") else " **(fails)**"
                        cells.append(("%.3g" % e if e is not None else "–") + " in %.3g s" % hit[0]["wall_seconds"] + ok)
                md.append("| %s | %g | %s | %s |" % (case, res, m, " | ".join(cells)))
    open(os.path.join(out, "schemes.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main(sys.argv)
