#!/usr/bin/env python3
"""Checks the load on the walls point by point beside the snapshots (io/WallFieldWriter.hpp)
of a finished run: every snapshot has its walls/<case>_NNNNNN.h5 at the same time, indexed in
<case>_walls.xmf; on each wall, sum(area x traction) equals that wall's pressure + viscous
force in walls.csv at that time (relative 1e-9 of the largest force); and, for a still tank
(--hydrostatic RHO G H TOL), the wall pressure on the floor (y = 0 in 2D, z = 0 in 3D, away
from the corners) is within TOL of rho g H, the same at every point up to TOL.
Usage: check_wall_field.py OUTDIR CASE [--hydrostatic RHO G H TOL]"""
import csv, os, re, struct, subprocess, sys, tempfile

def dataset(path, name):
    with tempfile.NamedTemporaryFile(suffix=".bin") as t:
        subprocess.run(["h5dump", "-d", "/" + name, "-b", "LE", "-o", t.name, path], check=True, stdout=subprocess.DEVNULL)
        b = open(t.name, "rb").read()
    return struct.unpack("<%dd" % (len(b) // 8), b)

def attribute(path, name):
    out = subprocess.run(["h5dump", "-a", "/" + name, path], check=True, capture_output=True, text=True).stdout
    return float(re.search(r"\(0\): ([-0-9.eE+]+)", out).group(1))

def main():
    out, case = sys.argv[1], sys.argv[2]
    hydro = None
    if len(sys.argv) > 3 and sys.argv[3] == "--hydrostatic":
        hydro = [float(v) for v in sys.argv[4:8]]
    snaps = sorted(f for f in os.listdir(out) if re.fullmatch(re.escape(case) + r"_\d{6}\.h5", f))
    walls = sorted("walls/" + f for f in os.listdir(os.path.join(out, "walls")) if re.fullmatch(re.escape(case) + r"_\d{6}\.h5", f))
    errors = []
    if len(snaps) != len(walls) or not walls:
        errors.append("%d snapshots but %d wall files" % (len(snaps), len(walls)))
    index = open(os.path.join(out, case + "_walls.xmf")).read()
    rows = list(csv.DictReader(open(os.path.join(out, "walls.csv"))))
    names = [k[: -len(".pressure_fx")] for k in rows[0] if k.endswith(".pressure_fx")]
    for s, w in zip(snaps, walls):
        p = os.path.join(out, w)
        t = attribute(p, "time")
        if abs(t - attribute(os.path.join(out, s), "time")) > 1e-12:
            errors.append("%s: time %g differs from its snapshot's" % (w, t))
        if w not in index:
            errors.append("%s is not in the index" % w)
        row = min(rows, key=lambda r: abs(float(r["time"]) - t))
        area, wall, tr = dataset(p, "area"), dataset(p, "wall"), dataset(p, "traction")
        pos, pres = dataset(p, "position"), dataset(p, "pressure")
        scale = max(abs(float(v)) for k, v in row.items() if "_f" in k) or 1.0
        for k, name in enumerate(names):
            for c, axis in enumerate("xyz"):
                key = "%s.pressure_f%s" % (name, axis)
                if key not in row:
                    continue
                csv_f = float(row[key]) + float(row["%s.viscous_f%s" % (name, axis)])
                field_f = sum(area[q] * tr[3 * q + c] for q in range(len(area)) if int(round(wall[q])) == k)
                if abs(field_f - csv_f) > 1e-9 * scale:
                    errors.append("%s t=%g wall %s F%s: points %.12g, walls.csv %.12g" % (w, t, name, axis, field_f, csv_f))
        if hydro and w == walls[-1]:
            rho, g, H, tol = hydro
            up = 2 if any(k.endswith(".pressure_fz") for k in rows[0]) else 1  # 3D: z is up
            floor = [pres[q] for q in range(len(pres)) if abs(pos[3 * q + up]) < 1e-12
                     and 0.1 < pos[3 * q] < 0.9 and (up == 1 or 0.1 < pos[3 * q + 1] < 0.9)]
            ref = rho * g * H
            bad = [v for v in floor if abs(v - ref) > tol * ref]
            print("check_wall_field: %s: floor pressure %.1f to %.1f Pa against rho g H = %.1f"
                  % (w, min(floor or [0]), max(floor or [0]), ref))
            if not floor or bad:
                errors.append("%s: %d floor points, %d off rho g H = %.1f by more than %g (e.g. %s)"
                              % (w, len(floor), len(bad), ref, tol, bad[:3]))
    for e in errors:
        print("check_wall_field:", e)
    print("check_wall_field: %d files, %s" % (len(walls), "ok" if not errors else "%d errors" % len(errors)))
    sys.exit(1 if errors else 0)

main()
