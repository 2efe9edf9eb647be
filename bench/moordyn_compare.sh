#!/usr/bin/env bash
# towsim against MoorDyn v2 on the steady tow: error and whole-process time, pair by pair
# (docs/benchmarks.md, "Against MoorDyn", where the MoorDyn build is described).
#   bench/moordyn_compare.sh MOORDYN_PREFIX [ROUNDS]
# MOORDYN_PREFIX: a MoorDyn install (include/moordyn/MoorDyn2.h, lib/libmoordyn.so).
# SIDE_BY_SIDE=1 in the environment: only both codes' end states with the same drag
# coefficients (MoorDyn 100 segments, towsim 80 elements; seconds, no hyperfine).
# ROUNDS (default 5): hyperfine rounds per pair, the order swapped every round; RUNS=R in the
# environment sets the runs per command and round (default 5). Needs build/sim_node/app/sim_node
# (BUILD_DIR=dir for another build), cc, hyperfine, python3. Work files go to WORK_DIR
# (default a new directory under /tmp, removed at the end); the tables go to stdout and
# bench/results/moordyn_compare.csv (+ _grid.csv). About 10 min with ROUNDS 5.
# Not part of ./test.sh: it needs a MoorDyn build, which CI does not have.
set -euo pipefail
usage() { echo "usage: bench/moordyn_compare.sh MOORDYN_PREFIX [ROUNDS]" >&2; exit 2; }
[[ $# -ge 1 && $# -le 2 ]] || usage
prefix=$1
# absolute, since the script changes to the repository below
if [[ -d "$prefix" ]]; then prefix=$(cd "$prefix" && pwd); fi
rounds=${2:-5}
runs=${RUNS:-5}
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "moordyn_compare: ROUNDS = $rounds: must be an integer >= 1" >&2; exit 2; }
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "moordyn_compare: RUNS = $runs: must be an integer >= 1" >&2; exit 2; }
header="$prefix/include/moordyn/MoorDyn2.h"
libdir=""
for d in "$prefix/lib" "$prefix/lib64"; do
  if [[ -e "$d/libmoordyn.so" ]]; then libdir=$d; break; fi
done
[[ -f "$header" ]] || { echo "moordyn_compare: MOORDYN_PREFIX = $prefix: no $header (install MoorDyn there: docs/benchmarks.md, \"Against MoorDyn\")" >&2; exit 2; }
[[ -n "$libdir" ]] || { echo "moordyn_compare: MOORDYN_PREFIX = $prefix: no lib/libmoordyn.so or lib64/libmoordyn.so" >&2; exit 2; }
tools="cc python3"
[[ -n "${SIDE_BY_SIDE:-}" ]] || tools+=" hyperfine"
for tool in $tools; do
  command -v "$tool" >/dev/null || { echo "moordyn_compare: $tool not found (apt-get install ${tool/cc/gcc})" >&2; exit 2; }
done
cd "$(dirname "$0")/.."
sim_node="${BUILD_DIR:-build}/sim_node/app/sim_node"
[[ -x "$sim_node" ]] || { echo "moordyn_compare: no $sim_node: build first (./run.sh or ./test.sh)" >&2; exit 2; }

if [[ -n "${WORK_DIR:-}" ]]; then
  work=$WORK_DIR
  [[ "$work" == /* ]] || work="$OLDPWD/$work"  # as given, from where the script was started
  mkdir -p "$work"
else
  work=$(mktemp -d /tmp/moordyn_compare.XXXXXX)
  trap 'rm -rf "$work"' EXIT
fi
cc -O2 -std=c11 -Wall -Wextra -Werror -I"$prefix/include" -o "$work/moordyn_driver" \
  bench/moordyn_driver.c -L"$libdir" -lmoordyn -Wl,-rpath,"$libdir" -lm
echo "MoorDyn: $prefix ($(readlink -f "$libdir/libmoordyn.so")); towsim: $sim_node ($(git rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "machine: $(nproc) cores, $(uname -srm), load average $(cut -d' ' -f1-3 /proc/loadavg), $(date -u '+%Y-%m-%d %H:%M UTC')"
# SIDE_BY_SIDE=1: only the two codes' end states with the same drag coefficients (seconds)
python3 bench/moordyn_compare.py --driver "$work/moordyn_driver" --sim-node "$sim_node" \
  --work "$work" --rounds "$rounds" --runs "$runs" ${SIDE_BY_SIDE:+--side-by-side}
echo "load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
