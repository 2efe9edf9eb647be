#!/usr/bin/env bash
# Cost of DDS Security (docs/security.md; a measurement, not a test): the node and one
# controller (tests/integration/test_controller) without security, with signed payloads
# (governance data_protection_kind SIGN, the default of scripts/security.sh) and with
# encrypted payloads (--encrypt: ENCRYPT), in one run of this script, variants interleaved:
#   1. lockstep: Case 1, 100 s simulated (2000 steps of 0.05 s), the controller's us/step;
#      median of RUNS;
#   2. realtime at 100 Hz (time.step = 0.01), 20 s, the controller answering every step: the
#      node's step lateness p50 / p99 / max and overruns.
#   bench/security_cost.sh [BUILD_DIR] [RUNS]        (default: build, 5)
# DDS domains 150-151 (tests/integration/README.md), config/cyclonedds.xml (loopback); run it
# inside `unshare -n` on a shared machine. Wall-clock numbers: run it on a quiet machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
runs="${2:-5}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
node="$build/sim_node/app/sim_node"
controller="$build/tests/integration/test_controller"
for x in "$node" "$controller"; do
  [ -x "$x" ] || { echo "build first: ./test.sh (missing $x)" >&2; exit 1; }
done
scene=config/scenes/case1_forward.yaml
thrust=4500

keys="$(mktemp -d /tmp/towsim_security_cost.XXXXXX)"
trap 'rm -rf "$keys"' EXIT
scripts/security.sh "$keys/sign" sim_node ctl:tow_vehicle,towfish
scripts/security.sh --encrypt "$keys/encrypt" sim_node ctl:tow_vehicle,towfish

# security_args VARIANT WHO -> the --security option of WHO (sim_node or ctl)
security_args() { [[ "$1" == none ]] || echo "--security $keys/$1/$2"; }
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

variants=(none sign encrypt)
declare -A lockstep
echo "== lockstep: $scene, 100 s (2000 steps), thrust $thrust N, median of $runs runs"
for ((i = 0; i < runs; ++i)); do
  for v in "${variants[@]}"; do
    # shellcheck disable=SC2046
    "$node" --scene "$scene" --mode lockstep --domain 150 --duration 100 --set 'script=[]' \
      $(security_args "$v" sim_node) >/dev/null &
    pid=$!
    # "test_controller: 1999 steps in 0.701 s: 2852 steps/s, 350.6 us/step"
    # shellcheck disable=SC2046
    us=$("$controller" --domain 150 --command "tow_vehicle@0=$thrust,0,0" --stats \
      $(security_args "$v" ctl) | awk '{print $9}')
    wait "$pid"
    lockstep[$v]+="$us "
  done
done
lowest() { sort -n | head -n 1; }
for v in "${variants[@]}"; do
  m=$(tr ' ' '\n' <<<"${lockstep[$v]}" | grep . | median)
  base=$(tr ' ' '\n' <<<"${lockstep[none]}" | grep . | median)
  lo=$(tr ' ' '\n' <<<"${lockstep[$v]}" | grep . | lowest)
  base_lo=$(tr ' ' '\n' <<<"${lockstep[none]}" | grep . | lowest)
  printf "lockstep  %-8s median %7.1f us/step (x%.2f), min %7.1f (x%.2f)   runs: %s\n" "$v" "$m" \
    "$(awk -v a="$m" -v b="$base" 'BEGIN {print a / b}')" "$lo" \
    "$(awk -v a="$lo" -v b="$base_lo" 'BEGIN {print a / b}')" "${lockstep[$v]}"
done

echo "== realtime at 100 Hz (time.step = 0.01), 20 s, the controller answering every step"
for v in "${variants[@]}"; do
  # shellcheck disable=SC2046
  "$node" --scene "$scene" --mode realtime --domain 151 --duration 20 --set time.step=0.01 \
    --set 'script=[]' --wait-for-controllers $(security_args "$v" sim_node) \
    >"$keys/rt_$v.out" &
  pid=$!
  # shellcheck disable=SC2046
  "$controller" --domain 151 --command "tow_vehicle@0=$thrust,0,0" \
    $(security_args "$v" ctl) >/dev/null
  wait "$pid"
  printf "realtime  %-8s %s, %s\n" "$v" \
    "$(grep -o 'lateness .*' "$keys/rt_$v.out")" "$(grep -o 'overruns [0-9]*' "$keys/rt_$v.out")"
done
