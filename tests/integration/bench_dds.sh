#!/usr/bin/env bash
# bench_dds.sh — the DDS node's benchmark (a measurement, not a test):
#   1. lockstep steps per second with one controller (test_controller) on the Case 1 scene,
#      against the offline steps per second of the same run (same thrust, same trajectory);
#   2. realtime step lateness p50 / p99 / max at 100 Hz (Case 1 with time.step = 0.01);
#   3. the node's peak resident memory (VmHWM) in that realtime run.
#
#   tests/integration/bench_dds.sh [BUILD_DIR] [RUNS]      (default: build, 5)
#
# Uses DDS domain 60 and config/cyclonedds.xml (loopback). Run it on a quiet machine: the
# numbers are wall-clock times.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-build}"
runs="${2:-5}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
node="$build/tests/integration/dds_sim_node"  # becomes $build/sim_node/app/sim_node
controller="$build/tests/integration/test_controller"
offline="$build/sim_node/app/sim_node"
scene=config/scenes/case1_forward.yaml
thrust=4500   # [N], the same constant thrust in both runs
domain=60
duration=100  # [s] of simulated time, 2000 steps of 0.05 s

echo "== lockstep vs offline: $scene, $duration s, thrust $thrust N, $runs runs each"
for ((i = 0; i < runs; ++i)); do
  "$offline" --scene "$scene" --mode offline --duration "$duration" \
    --set "script=[{at: 0, body: tow_vehicle, thrust: $thrust}]" |
    sed -E 's/.* ([0-9]+) steps, .* simulated in ([0-9.]+) s.*/offline  \1 \2/' |
    awk '{printf "offline   %6.0f steps/s  %6.1f us/step\n", $2 / $3, 1e6 * $3 / $2}'
done
for ((i = 0; i < runs; ++i)); do
  "$node" --scene "$scene" --mode lockstep --domain "$domain" --duration "$duration" \
    --set 'script=[]' >/dev/null &
  pid=$!
  "$controller" --domain "$domain" --command "tow_vehicle@0=$thrust,0,0" --stats |
    awk '{printf "lockstep  %6.0f steps/s  %6.1f us/step\n", $7, $9}'
  wait "$pid"
done

echo "== realtime at 100 Hz (time.step = 0.01), 30 s, with the controller answering every step"
"$node" --scene "$scene" --mode realtime --domain "$domain" --duration 30 \
  --set time.step=0.01 --set 'script=[]' >/tmp/towsim_bench_rt.out &
pid=$!
"$controller" --domain "$domain" --command "tow_vehicle@0=$thrust,0,0" >/dev/null &
cpid=$!
sleep 28
grep -E 'VmHWM|VmRSS' "/proc/$pid/status"
wait "$pid"
wait "$cpid" || true
sed -E 's/.*(lateness .*)/\1/' /tmp/towsim_bench_rt.out
grep -o 'overruns [0-9]*' /tmp/towsim_bench_rt.out
