#!/usr/bin/env bash
# network_cost.sh [BUILD_DIR]: what a network costs against its cables alone
# (docs/benchmarks.md "Networks"). Instructions of Simulation::Step (valgrind --tool=callgrind:
# exact on a noisy machine) over 20 s of a steady two-part tow (bench/network_cost/two_part.yaml)
# against its main cable alone with the depressor plus its tether alone with the towfish
# (main_alone.yaml + tether_alone.yaml), and of the two cables in one scene sharing no body
# (two_apart.yaml) against the same sum. Prints the instructions per step and the ratios.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-$here/../build}"
driver="$build/bench/step_driver"
[[ -x "$driver" ]] || { echo "network_cost: no $driver (cmake --build $build --target step_driver)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "network_cost: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
count() {  # instructions of Simulation::Step* over 20 s of scene $1
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" \
    --toggle-collect='towsim::core::Simulation::Step*' "$driver" "$here/network_cost/$1.yaml" 20 \
    >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
  awk '/^(summary|totals):/ {print $2; exit}' "$tmp/cg.out"
}
steps=400
two=$(count two_part); main=$(count main_alone); tether=$(count tether_alone); apart=$(count two_apart)
sum=$((main + tether))
printf '%-28s %14s\n' scene "instr/step"
for s in two_part:$two main_alone:$main tether_alone:$tether two_apart:$apart; do
  printf '%-28s %14d\n' "${s%%:*}" $(( ${s##*:} / steps ))
done
awk -v t="$two" -v a="$apart" -v s="$sum" 'BEGIN {
  printf "two_part / (main_alone + tether_alone) = %.3f (target <= 1.10)\n", t / s
  printf "two_apart / (main_alone + tether_alone) = %.3f (target <= 1.00)\n", a / s }'
