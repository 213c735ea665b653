#!/usr/bin/env bash
# The CUDA build (make cuda) on this machine: where no CUDA device is usable, --version and
# --help answer, and a run stops with one line that names the CPU build, exit status 2,
# no output folder. Skipped where the CUDA build was not made or a device is present.
set -uo pipefail
cd "$(dirname "$0")/.."
ondine=build-cuda/ondine
[ -x "$ondine" ] || { echo "check_cuda_build: no $ondine (make cuda skipped): nothing to check"; exit 0; }
if command -v nvidia-smi > /dev/null && nvidia-smi -L > /dev/null 2>&1; then
  echo "check_cuda_build: a CUDA device is present: run the tests on it instead"; exit 0
fi
fail() { echo "check_cuda_build: FAIL: $*"; exit 1; }
"$ondine" --version > /dev/null 2>&1 || fail "--version without a device"
"$ondine" --help > /dev/null 2>&1 || fail "--help without a device"
out=$(mktemp -d)/run
"$ondine" run cases/dam_break_2d.yaml --out "$out" 2> "$out.err"; rc=$?
[ $rc -eq 2 ] || fail "a run without a device: exit status $rc, expected 2 ($(head -3 "$out.err"))"
grep -q "needs a CUDA device" "$out.err" && grep -q "build/ondine is the CPU build" "$out.err" || fail "message: $(cat "$out.err")"
[ "$(wc -l < "$out.err")" -eq 1 ] || fail "more than one line: $(cat "$out.err")"
[ ! -e "$out" ] || fail "a refused run left $out"
echo "check_cuda_build: without a device, $ondine answers --version and --help and refuses a run: $(cat "$out.err")"
rm -rf "$(dirname "$out")"
