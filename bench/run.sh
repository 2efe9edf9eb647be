#!/usr/bin/env bash
# Runs the benchmarks (after ./test.sh or ./run.sh has built them into build/).
#   bench/run.sh [ARGS]     Google Benchmark of the shipped cable scenes (cable_bench ARGS)
#   bench/run.sh sweep      accuracy against run time (~3-6 min): writes
#                           bench/results/work_precision.csv, draws
#                           docs/figures/work_precision_*.png and prints the Pareto fronts
#   bench/run.sh targets    the shipped scenes at their own settings: real-time factor and the
#                           towfish-track error against a run 4x finer (the accuracy targets of docs/benchmarks.md)
#   bench/run.sh startup [SIM_NODE] [ARGS]
#                           sim_node offline as a whole process against its stepping loop in
#                           process (Case 1, 100 s, 10 pairs; ~5 s): both RTFs and their ratio
#                           (docs/benchmarks.md, "Start-up"); SIM_NODE defaults to the build's sim_node
#   bench/run.sh lockstep [--ddsperf] [BUILD_DIR] [RUNS] [ROUNDS]
#                           the bare round trip of one lockstep step against the lockstep
#                           overhead per step (bench/lockstep.sh; ~1 min; last line
#                           "lockstep overhead / round trip = R")
# BUILD_DIR=dir selects another build directory.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
need() { [ -x "$build/bench/$1" ] || { echo "build first: ./test.sh (no $build/bench/$1)" >&2; exit 1; }; }
case "${1:-}" in
  sweep)
    need work_precision
    "$build/bench/work_precision" --out bench/results/work_precision.csv
    /usr/bin/python3 bench/plot_work_precision.py bench/results/work_precision.csv docs/figures
    ;;
  targets)
    need work_precision
    exec "$build/bench/work_precision" --targets
    ;;
  startup)
    need startup_cost
    shift
    sim_node="$build/sim_node/app/sim_node"
    if [[ $# -gt 0 && "$1" != --* ]]; then sim_node="$1"; shift; fi
    exec "$build/bench/startup_cost" "$sim_node" "$@"
    ;;
  lockstep)
    need lockstep_pingpong
    shift
    BUILD_DIR="$build" exec bench/lockstep.sh "$@"
    ;;
  *)
    need cable_bench
    exec "$build/bench/cable_bench" --benchmark_counters_tabular=true "$@"
    ;;
esac
