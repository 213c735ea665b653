#!/usr/bin/env bash
# Runs the CUDA build of Ondine from a bundle (perf/gpu/bundle.sh) on a GPU machine, within
# a time budget, each step under its own time limit, and packs what the steps wrote:
#   perf/gpu/check.sh BUNDLE OUT_DIR BUDGET_S [STEP...]
# Steps (in the order given; default: info smoke test2 bench unit pairbench):
#   info      the GPU (nvidia-smi) and `ondine --version`
#   smoke     the shipped 2D dam break (cases/dam_break_2d.yaml), timed
#   test2     `ondine validate --case spheric_test2_3d --level full` (dx = 0.05, 0.04 m)
#   fine      `ondine validate --case fine_spheric_test2_3d --level full` (dx = 0.03, 0.02 m)
#   thesis    `ondine validate --case fine_spheric_test2_3d_thesis --level full` (dx = 0.015, 0.01 m)
#   profile   SPHERIC Test 2 at dx = 0.03 m to 0.6 s with --profile (each kernel's time)
#   bench     perf/ondine_bench --quick (the pair rate)
#   unit      the unit tests (ondine_tests "[unit]")
#   pairbench the hand-written OpenMP pair loop on the machine's cores (the yardstick)
#   validate:NAME[,LIMIT[,ARG...]]  `ondine validate --case NAME --level full ARG...` (limit LIMIT s,
#             default 150), e.g. validate:apr_cylinder_re100_2d,540,--variant,apr_lts (the refined
#             cylinder with local time stepping alone)
#   case:NAME,FILE,ARG,...  `ondine run FILE` with these arguments (commas for spaces) (limit 150 s)
#   run:NAME,ARG,...  SPHERIC Test 2 with these `ondine run` arguments (commas for spaces),
#             e.g. run:dx015,--set,discretisation.dx=0.015 (limit 150 s)
#   long:NAME,LIMIT,FILE,ARG,...  `ondine run FILE` with these arguments under LIMIT seconds
#   resume:NAME,LIMIT,FILE,ARG,...  as long:, but in /tmp/ondine-gpu-keep/NAME, which a later call
#             on the same (warm) machine keeps: stopped at LIMIT by SIGTERM (a clean stop writes a
#             checkpoint; 60 s allowed for it), it continues from that checkpoint at the next call
#             (`--restart`), so a run longer than one call goes over several
# OUT_DIR gets log.txt, steps.json (each step's status and seconds) and results.tar.gz
# (the runs' JSON, CSV and figures, no snapshots).
set -u
bundle=${1:?usage: check.sh BUNDLE OUT_DIR BUDGET_S [STEP...]}
out=${2:?}
budget=${3:?}
shift 3
steps=("$@")
[ ${#steps[@]} -eq 0 ] && steps=(info smoke test2 bench unit pairbench)
cd "$(dirname "$0")/../.."
start=$(date +%s)
mkdir -p "$out"
log="$out/log.txt"
work=/tmp/ondine-gpu
rm -rf "$work"; mkdir -p "$work/runs"
tar -C "$work" -xJf "$bundle" || { echo "check.sh: cannot unpack $bundle" | tee -a "$log"; exit 1; }
export LD_LIBRARY_PATH="$work/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# Open MPI from the bundle: its components and messages, one process without mpirun
export OMPI_MCA_mca_base_component_path="$work/ompi" OPAL_PKGLIBDIR="$work/ompi" OPAL_PKGDATADIR="$work/share/openmpi"
export OMPI_MCA_ess_singleton_isolated=1 OMPI_MCA_pml=ob1 OMPI_MCA_btl=self,vader
export PMIX_MCA_mca_base_component_path="$work/pmix"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export CUDA_CACHE_MAXSIZE=4294967296
bin="$work/bin"
echo "{" > "$out/steps.json"
first=1
record() {  # name status seconds
  [ $first -eq 1 ] || echo "," >> "$out/steps.json"
  first=0
  printf '  "%s": {"status": %s, "seconds": %s}' "$1" "$2" "$3" >> "$out/steps.json"
}
grace=5  # seconds between SIGTERM and SIGKILL at a step's limit
step() {  # name limit command...
  local name=$1 limit=$2; shift 2
  local left=$(( budget - ($(date +%s) - start) - 15 - grace ))
  [ $left -lt $limit ] && limit=$left
  if [ $limit -lt 5 ]; then echo "== $name: skipped (budget)" >> "$log"; record "$name" '"skipped"' 0; return; fi
  echo "== $name (limit ${limit} s): $*" >> "$log"
  local t0=$(date +%s.%N)
  timeout -k "$grace" "$limit" "$@" >> "$log" 2>&1
  local rc=$? t1=$(date +%s.%N)
  local dt=$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b-a}')
  echo "== $name: exit $rc in $dt s" >> "$log"
  record "$name" "$rc" "$dt"
}
for s in "${steps[@]}"; do
  case $s in
    info)
      step info 30 bash -c "nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv; nproc; cat $work/commit; $bin/ondine --version" ;;
    smoke)
      step smoke 90 "$bin/ondine" run cases/dam_break_2d.yaml --out "$work/runs/dam_break_2d" --quiet ;;
    test2)
      step test2 150 "$bin/ondine" validate --case spheric_test2_3d --level full --out "$work/runs/test2" ;;
    fine)
      step fine 120 "$bin/ondine" validate --case fine_spheric_test2_3d --level full --out "$work/runs/fine" ;;
    thesis)
      step thesis 420 "$bin/ondine" validate --case fine_spheric_test2_3d_thesis --level full --out "$work/runs/thesis" ;;
    profile)
      step profile 90 "$bin/ondine" run cases/spheric_test2_3d.yaml --set discretisation.dx=0.03 --set time.duration=0.6 \
        --profile --out "$work/runs/profile_dx0.03" --quiet ;;
    bench)
      step bench 90 "$bin/ondine_bench" --quick --out "$work/runs/bench.json" ;;
    unit)
      [ -x "$bin/ondine_tests" ] && step unit 120 "$bin/ondine_tests" "[unit]" --reporter compact ;;
    pairbench)
      if [ -f "$work/pairbench.cpp" ]; then
        step pairbench 60 bash -c "g++ -O3 -march=native -fopenmp $work/pairbench.cpp -o $work/pairbench && \
          for r in 1 2 3; do OMP_NUM_THREADS=\$(nproc) OMP_PROC_BIND=spread OMP_PLACES=threads $work/pairbench 300 20; done \
          | tee $work/runs/pairbench.jsonl"
      fi ;;
    validate:*)
      IFS=, read -r -a args <<< "${s#validate:}"
      step "${args[0]}" "${args[1]:-150}" "$bin/ondine" validate --case "${args[0]}" --level full --out "$work/runs/${args[0]}" "${args[@]:2}" ;;
    case:*)
      IFS=, read -r -a args <<< "${s#case:}"
      step "${args[0]}" 150 "$bin/ondine" run "${args[1]}" --quiet --out "$work/runs/${args[0]}" "${args[@]:2}" ;;
    run:*)
      IFS=, read -r -a args <<< "${s#run:}"
      step "${args[0]}" 150 "$bin/ondine" run cases/spheric_test2_3d.yaml --quiet --out "$work/runs/${args[0]}" "${args[@]:1}" ;;
    long:*)
      IFS=, read -r -a args <<< "${s#long:}"
      step "${args[0]}" "${args[1]}" "$bin/ondine" run "${args[2]}" --quiet --out "$work/runs/${args[0]}" "${args[@]:3}" ;;
    resume:*)
      IFS=, read -r -a args <<< "${s#resume:}"
      keep=/tmp/ondine-gpu-keep/${args[0]}
      mkdir -p "$keep"
      again=()
      [ -f "$keep/checkpoint.h5" ] && again=(--restart "$keep/checkpoint.h5")
      grace=60 step "${args[0]}" "${args[1]}" "$bin/ondine" run "${args[2]}" --quiet --out "$keep" "${args[@]:3}" "${again[@]}"
      mkdir -p "$work/runs/${args[0]}"
      find "$keep" -maxdepth 1 -type f \( -name '*.json' -o -name '*.csv' \) -exec cp {} "$work/runs/${args[0]}/" \; ;;
    *) echo "check.sh: unknown step $s" >> "$log" ;;
  esac
done
echo "}" >> "$out/steps.json"
(cd "$work/runs" && find . -type f \( -name '*.json' -o -name '*.csv' -o -name '*.md' -o -name '*.png' -o -name '*.jsonl' \) \
  -size -20M | tar -czf "$out/results.tar.gz" -T -)
echo "check.sh: done in $(( $(date +%s) - start )) s" >> "$log"
