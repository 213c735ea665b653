#!/usr/bin/python3
"""`ondine validate --resume` (src/app/ValidateResume.hpp) on open_channel_2d (quick: two rungs,
open boundaries whose state a restart must carry):
 1. the validation run through, for reference;
 2. the same with --resume, stopped by SIGTERM in its second rung: exit status 143, the rung's
    checkpoint written, no report;
 3. --resume again: the first rung taken as it is, the second continued from its checkpoint;
    every figure equal to the uninterrupted run's within round-off (the checkpoint rebuilds the
    neighbour lists at another step than the reference, so not bitwise), the same step count,
    and wall/CPU seconds the sum over the two processes;
 4. --resume once more: nothing run, the same record, each rung's commit the one that ran it
    (validate_rung.json), not the report writer's;
 5. refusals (exit status 2, the file named): other overrides than the folder's, and a folder
    not written by --resume.
usage: check_validate_resume.py ONDINE OUT"""
import json, os, shutil, signal, subprocess, sys, time

ondine, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
case = ["validate", "--case", "open_channel_2d"]
rung = "open_channel_2d/res_20"


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def validate(folder, *extra):
    p = subprocess.run([ondine, *case, "--out", f"{out}/{folder}", *extra], capture_output=True, text=True)
    return p.returncode, p.stderr


def runs(folder):
    return {r["dir"]: r for r in json.load(open(f"{out}/{folder}/validation.json"))["runs"]}


rc, _ = validate("A")
if rc != 0:
    fail(f"reference validation: exit status {rc}")

# 2. stopped in the second rung, once it has written 3 output rows
log = open(f"{out}/stopped.log", "w")
p = subprocess.Popen([ondine, *case, "--out", f"{out}/B", "--resume"], stderr=log)
diag = f"{out}/B/{rung}/diagnostics.csv"
t0 = time.time()
while time.time() - t0 < 300:
    if os.path.exists(diag) and sum(1 for _ in open(diag)) >= 4:
        break
    if p.poll() is not None:
        fail(f"the validation ended (status {p.returncode}) before its second rung had 3 output rows")
    time.sleep(0.05)
else:
    fail("no output rows in the second rung after 300 s")
p.send_signal(signal.SIGTERM)
rc = p.wait()
log.close()
if rc != 143:
    fail(f"SIGTERM: exit status {rc}, expected 143: {open(out + '/stopped.log').read()[-400:]}")
if os.path.exists(f"{out}/B/validation.json"):
    fail("a stopped validation wrote validation.json")
first = json.load(open(f"{out}/B/{rung}/summary.json"))
if first["status"] != "interrupted" or not os.path.exists(f"{out}/B/{rung}/checkpoint.h5"):
    fail(f"the stopped rung: status {first['status']}, checkpoint {os.path.exists(out + '/B/' + rung + '/checkpoint.h5')}")
print(f"stopped at step {first['total_steps']} of the second rung, t = {first['simulated_time']:.4g} s, {first['wall_seconds']:.1f} s wall")

# 3. resumed
rc, err = validate("B", "--resume")
if rc != 0:
    fail(f"--resume: exit status {rc}: {err[-600:]}")
if "res_10 completed before" not in err or f"from {out}/B/{rung}/checkpoint.h5" not in err:
    fail(f"--resume did not take the first rung and continue the second: {err}")
a, b = runs("A"), runs("B")
worst = 0.0
for d, ra in a.items():
    rb = b[d]
    if rb["status"] != "completed" or rb["steps"] != ra["steps"] or rb["particles"] != ra["particles"]:
        fail(f"{d}: status {rb['status']}, steps {rb['steps']} / {ra['steps']}, particles {rb['particles']} / {ra['particles']}")
    if set(rb["errors"]) != set(ra["errors"]):
        fail(f"{d}: figures {sorted(rb['errors'])} against {sorted(ra['errors'])}")
    for k, va in ra["errors"].items():
        vb = rb["errors"][k]
        diff = abs(vb - va) / max(abs(va), 1e-9)  # absolute below 1e-9 (drifts of 1e-14 and counts of 0)
        worst = max(worst, diff)
        if diff > 1e-8:  # measured 7.6e-11
            fail(f"{d} {k}: {vb} resumed against {va}")
resumed = json.load(open(f"{out}/B/{rung}/summary.json"))
total = resumed["total_wall_seconds"]
if not resumed.get("restarted_from") or abs(total - (first["wall_seconds"] + resumed["wall_seconds"])) > 0.05 * total:
    fail(f"wall seconds since t = 0 {total} against {first['wall_seconds']} + {resumed['wall_seconds']}")
if abs(b[rung]["wall_seconds"] - total) > 1e-9 or b[rung]["cpu_seconds"] < first["cpu_seconds"]:
    fail(f"the record's wall/CPU seconds ({b[rung]['wall_seconds']}, {b[rung]['cpu_seconds']}) are not the totals")
print(f"resumed: figures within {worst:.2g} of the uninterrupted run's, steps equal, wall {total:.1f} s over two processes")

if len(b[rung].get("commits", [])) != 2:
    fail(f"the resumed rung's record lists commits {b[rung].get('commits')}, expected the two processes'")

# 4. nothing left to run; the record names the commit that ran each rung, not the one writing it
ident = f"{out}/B/open_channel_2d/res_10/validate_rung.json"
j = json.load(open(ident))
j["commits"] = ["0000000"]  # as if an older binary had run it
json.dump(j, open(ident, "w"))
rc, err = validate("B", "--resume")
c = runs("B")
if rc != 0 or err.count("taken as it is") != 2 or any(c[d]["errors"] != b[d]["errors"] for d in b):
    fail(f"a second --resume: exit status {rc}, {err}")
if c["open_channel_2d/res_10"]["commit"] != "0000000":
    fail(f"a rung taken as it is: the record's commit {c['open_channel_2d/res_10']['commit']}, not the one that ran it")

# 5. refusals
rc, err = validate("B", "--resume", "--flux", "riemann")
if rc != 2 or f"{out}/B/open_channel_2d/res_10/validate_rung.json: the rung in this folder ran with sets" not in err:
    fail(f"other overrides: exit status {rc}, {err}")
rc, err = validate("A", "--resume")
if rc != 2 or "holds output without validate_rung.json" not in err:
    fail(f"a folder not written by --resume: exit status {rc}, {err}")
print("refused: other overrides, a folder not written by --resume")
