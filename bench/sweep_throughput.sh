#!/usr/bin/env bash
# Local sweep throughput (docs/sweeps.md "Measured"): towsim_sweep on 16 cases of Case 1 with 1
# and 2 workers, for a long case (300 s simulated) and a short one (2 s); per case the process
# wall time (wall_s: start, scene load, initial state, run, CSV) against the stepping loop
# alone (run_wall_s, sim_node's summary line), the difference being the per-case overhead.
#   bench/sweep_throughput.sh [BUILD_DIR]          (default: build)
# Offline: no DDS. Wall-clock numbers: run it on a quiet machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
sweep="$build/sim_node/app/towsim_sweep"
[ -x "$sweep" ] || { echo "build first: ./test.sh (missing $sweep)" >&2; exit 1; }
tmp="$(mktemp -d /tmp/towsim_sweep_bench.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT

echo "| case length | workers | cases | sweep wall [s] | cases/min | wall_s per case [s] | run_wall_s [s] | overhead per case [s] |"
echo "|---|---|---|---|---|---|---|---|"
for duration in 300 2; do
  cat >"$tmp/sweep_$duration.yaml" <<YAML
scene: $root/config/scenes/case1_forward.yaml
duration: $duration
parameters:
  environment.water_density: {from: 1020, to: 1035, step: 1}
results:
  run_wall_s: {signal: run_wall_s}
YAML
  for workers in 1 2; do
    out="$tmp/out_${duration}_$workers"
    "$sweep" "$tmp/sweep_$duration.yaml" --out "$out" --workers "$workers" >/dev/null 2>&1
    # "...; 16 run in 5.2 s (1 worker, 184.6 cases/min)"
    read -r ran wall per_min < <(sed -nE '1s/.*; ([0-9]+) run in ([0-9.]+) s \(.*, ([0-9.]+) cases\/min\)/\1 \2 \3/p' "$out/summary.txt")
    # results.csv: wall_s is column 5, run_wall_s the last
    read -r case_wall run_wall < <(awk -F, 'NR > 1 { w += $5; r += $NF; n++ } END { printf "%.3f %.3f\n", w / n, r / n }' "$out/results.csv")
    overhead=$(awk -v a="$case_wall" -v b="$run_wall" 'BEGIN { printf "%.3f", a - b }')
    echo "| ${duration} s | $workers | $ran | $wall | $per_min | $case_wall | $run_wall | $overhead |"
  done
done
