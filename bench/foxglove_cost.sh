#!/usr/bin/env bash
# Cost of the 3D markers and of the Foxglove bridge for the node (docs/foxglove.md): Case 1,
# 100 s, sim_node --mode fast, the mean step wall time (Step + publishing, status.csv wall_us
# at 10 Hz) of
#   offline            no DDS at all (the reference)
#   alone              fast, nobody subscribed (markers every step: publish.markers=0)
#   bridge, no client  fast, towsim_foxglove running, no WebSocket client
#   bridge + client    fast, towsim_foxglove with one client subscribed to every channel
#                      (tests/foxglove_js/subscribe_all.mjs; the node starts paused and the
#                      client resumes it once subscribed)
#   --foxglove         the same two with the server inside the node (sim_node --foxglove 0)
# Median of RUNS runs each. Needs `npm ci` in tests/foxglove_js. Domains 102-105.
#   bench/foxglove_cost.sh [BUILD_DIR] [RUNS]        (default: build, 3)
# Wall-clock numbers: run it on a quiet machine, inside `unshare -n` beside other users.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
runs="${2:-3}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
node="$build/sim_node/app/sim_node"
bridge="$build/sim_node/app/towsim_foxglove"
client="$root/tests/foxglove_js/subscribe_all.mjs"
for x in "$node" "$bridge"; do
  [ -x "$x" ] || { echo "build first: ./test.sh (missing $x)" >&2; exit 1; }
done
[ -d "$root/tests/foxglove_js/node_modules" ] || { echo "run npm ci in tests/foxglove_js" >&2; exit 1; }
scene=config/scenes/case1_forward.yaml
args=(--scene "$scene" --duration 100 --set publish.markers=0)
tmp="$(mktemp -d)"
pids=()
cleanup() {
  local p
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT

# mean wall_us of status.csv rows after t = 0
mean_us() { awk -F, 'NR > 2 {s += $5; n++} END {printf "%.1f\n", s / n}' "$1/status.csv"; }
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

off=() alone=() idle=() with=() in_idle=() in_with=()
for ((i = 0; i < runs; ++i)); do
  "$node" "${args[@]}" --mode offline --csv "$tmp/off" >/dev/null
  off+=("$(mean_us "$tmp/off")")
  "$node" "${args[@]}" --mode fast --domain 102 --csv "$tmp/alone" >/dev/null
  alone+=("$(mean_us "$tmp/alone")")

  "$bridge" --domain 102 --port 0 --quiet >"$tmp/bridge.out" &
  pids=($!)
  "$node" "${args[@]}" --mode fast --domain 102 --csv "$tmp/idle" >/dev/null
  idle+=("$(mean_us "$tmp/idle")")
  kill -TERM "${pids[0]}"; wait "${pids[0]}" || true

  "$bridge" --domain 103 --port 0 --quiet >"$tmp/bridge.out" &
  pids=($!)
  "$node" "${args[@]}" --mode fast --domain 103 --paused --csv "$tmp/with" >/dev/null &
  pids+=($!)
  until grep -q serving "$tmp/bridge.out"; do sleep 0.05; done
  url=$(sed -nE 's/.*serving (ws:[^ ]+) .*/\1/p' "$tmp/bridge.out")
  node "$client" "$url" 1 >"$tmp/client.out"
  wait "${pids[1]}"
  kill -TERM "${pids[0]}"; wait "${pids[0]}" || true
  pids=()
  with+=("$(mean_us "$tmp/with")")
  messages=$(sed -nE 's/subscribe_all: ([0-9]+) messages.*/\1/p' "$tmp/client.out")

  "$node" "${args[@]}" --mode fast --domain 104 --foxglove 0 --csv "$tmp/in_idle" >/dev/null
  in_idle+=("$(mean_us "$tmp/in_idle")")
  "$node" "${args[@]}" --mode fast --domain 105 --foxglove 0 --paused --csv "$tmp/in_with" \
    >"$tmp/node.out" &
  pids=($!)
  until grep -q "Foxglove at" "$tmp/node.out"; do sleep 0.05; done
  url=$(sed -nE 's/.*Foxglove at (ws:[^ ]+).*/\1/p' "$tmp/node.out")
  node "$client" "$url" 1 >"$tmp/client.out"
  wait "${pids[0]}"
  pids=()
  in_with+=("$(mean_us "$tmp/in_with")")
  in_messages=$(sed -nE 's/subscribe_all: ([0-9]+) messages.*/\1/p' "$tmp/client.out")
done
o=$(printf '%s\n' "${off[@]}" | median)
a=$(printf '%s\n' "${alone[@]}" | median)
b=$(printf '%s\n' "${idle[@]}" | median)
w=$(printf '%s\n' "${with[@]}" | median)
ii=$(printf '%s\n' "${in_idle[@]}" | median)
iw=$(printf '%s\n' "${in_with[@]}" | median)
echo "| case | mean step wall time [us] | ratio to fast, nobody subscribed |"
echo "|---|---|---|"
awk -v o="$o" -v a="$a" -v b="$b" -v w="$w" -v m="$messages" -v ii="$ii" -v iw="$iw" \
    -v im="$in_messages" 'BEGIN {
  printf "| offline (no DDS; Step only) | %.1f | |\n", o
  printf "| fast, nobody subscribed (markers every step) | %.1f | 1.000 |\n", a
  printf "| fast, towsim_foxglove, no client | %.1f | %.3f |\n", b, b / a
  printf "| fast, towsim_foxglove, 1 client on every channel (%d messages) | %.1f | %.3f |\n", m, w, w / a
  printf "| fast, sim_node --foxglove, no client | %.1f | %.3f |\n", ii, ii / a
  printf "| fast, sim_node --foxglove, 1 client on every channel (%d messages) | %.1f | %.3f |\n", im, iw, iw / a }'
