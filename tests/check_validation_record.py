#!/usr/bin/env python3
"""The docs against the record: every validation case that docs/validation.md names in a table
row, or asks for with `--case NAME`, has at least one recorded run in validation.json, and
every recorded run is of a case `ondine validate` knows and carries what the report promises
(level, scheme, dx, particles, steps, wall time, errors, thresholds, passed).

usage: check_validation_record.py DOC.md RECORD.json CATALOGUE
CATALOGUE: the output of `ondine validate --list` (name group case-file per line), or the
ondine binary to ask for it. Exit 1, naming each line and case, when the two disagree."""
import json
import re
import subprocess
import sys

FIELDS = ("case", "level", "flux", "transport", "scheme", "dx", "particles", "steps", "wall_seconds", "errors", "thresholds", "passed")


def catalogue(arg):
    try:
        text = open(arg).read() if arg.endswith(".txt") else subprocess.run([arg, "validate", "--list"], check=True,
                                                                          capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        sys.exit(f"check_validation_record.py: cannot read the catalogue from {arg}: {e}")
    names = {line.split()[0] for line in text.splitlines() if line.strip()}
    if not names:
        sys.exit(f"check_validation_record.py: {arg}: no validation case listed")
    return names


def named_cases(doc_text, names):
    """(line number, case) for each catalogue case a table row names or a `--case NAME` asks for."""
    found = []
    word = re.compile(r"(?<![A-Za-z0-9_])(" + "|".join(sorted(map(re.escape, names), key=len, reverse=True)) + r")(?![A-Za-z0-9_])")
    for n, line in enumerate(doc_text.split("\n"), 1):
        hits = set(word.findall(line)) if line.lstrip().startswith("|") else set()
        hits |= {m for m in re.findall(r"--case ([A-Za-z0-9_]+)", line) if m in names}
        found += [(n, case) for case in sorted(hits)]
    return found


def problems(doc_path, record_path, names):
    try:
        runs = json.load(open(record_path))["runs"]
    except (OSError, ValueError, KeyError) as e:
        return [f"{record_path}: not a validation record ({e})"]
    try:
        doc_text = open(doc_path).read()
    except OSError as e:
        return [f"{doc_path}: cannot read it ({e.strerror})"]
    recorded = {r.get("case") for r in runs}
    out = []
    for n, case in named_cases(doc_text, names):
        if case not in recorded:
            out.append(f"{doc_path}:{n} names case '{case}', which has no recorded run in {record_path}")
    for k, r in enumerate(runs):
        if r.get("case") not in names:
            out.append(f"{record_path}: run {k} is of case '{r.get('case')}', which `ondine validate --list` does not know")
        missing = [f for f in FIELDS if f not in r]
        if missing:
            out.append(f"{record_path}: run {k} ({r.get('case')}, {r.get('dir')}) lacks {', '.join(missing)}")
    return out


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    found = problems(argv[0], argv[1], catalogue(argv[2]))
    if found:
        print("\n".join(found))
        sys.exit(1)
    print(f"check_validation_record.py: every case {argv[0]} names has a recorded run in {argv[1]}")


if __name__ == "__main__":
    main(sys.argv[1:])
