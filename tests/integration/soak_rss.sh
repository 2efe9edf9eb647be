#!/usr/bin/env bash
# soak_rss.sh — resident memory of a 400 Hz realtime node and its controller over time (a
# measurement, not a test; docs/faults.md "The soak's memory growth"):
#   the Case 1 scene at rate 20 (h = 0.05 s: 400 steps/s), test_controller answering every
#   status; VmRSS of both every 10 s, then the node's summary line. With `--massif`, the
#   controller runs under valgrind massif instead (its live heap over time: ms_print FILE).
#
#   tests/integration/soak_rss.sh [BUILD_DIR] [SECONDS] [--massif]   (default: build, 180)
#
# Uses DDS domain 138 and config/cyclonedds.xml (loopback); run it inside `unshare -n` on a
# shared machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-build}"
seconds="${2:-180}"
massif="${3:-}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
tmp="$(mktemp -d)"
node_pid=""
controller_pid=""
cleanup() {
  [ -n "$node_pid" ] && kill -INT "$node_pid" 2>/dev/null || true
  [ -n "$controller_pid" ] && kill "$controller_pid" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
"$build/sim_node/app/sim_node" --scene config/scenes/case1_forward.yaml --mode realtime \
  --rate 20 --domain 138 --set 'script=[]' > "$tmp/node.out" 2>&1 &
node_pid=$!
controller=("$build/tests/integration/test_controller" --domain 138 --timeout 600)
if [ "$massif" = "--massif" ]; then
  controller=(valgrind --tool=massif --time-unit=ms --massif-out-file=massif.soak.out
              "${controller[@]}")
fi
"${controller[@]}" > "$tmp/controller.out" 2>&1 &
controller_pid=$!
echo "t_s node_rss_kB controller_rss_kB"
for t in $(seq 0 10 "$seconds"); do
  echo "$t $(awk '/VmRSS/ {print $2}' /proc/$node_pid/status) \
$(awk '/VmRSS/ {print $2}' /proc/$controller_pid/status)"
  sleep 10
done
kill -INT "$node_pid"
wait "$node_pid" || true
wait "$controller_pid" || true
node_pid=""
controller_pid=""
tail -1 "$tmp/node.out"
[ "$massif" = "--massif" ] && echo "massif output: massif.soak.out (ms_print massif.soak.out)"
