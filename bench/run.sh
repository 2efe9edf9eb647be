#!/usr/bin/env bash
# Runs the benchmarks (after ./test.sh or ./run.sh has built them).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/bench/cable_bench ] || { echo "build first: ./test.sh" >&2; exit 1; }
exec build/bench/cable_bench --benchmark_counters_tabular=true "$@"
