#!/usr/bin/env bash
# The node's fast-mode step rate with a Foxglove client that never reads, against none
# (docs/foxglove.md "Bounds", docs/benchmarks.md "A stalled Foxglove client"): Case 1,
# sim_node --mode fast --foxglove 0 for DURATION simulated seconds, steps per wall second
# from the summary line of
#   none        no client
#   idle        a client that did the handshake and reads nothing (bench/stalled_foxglove_client.py)
#   subscribed  a client subscribed to every channel that reads nothing
# alternated, RUNS runs each, the median and the ratio to `none`. Needs python3. Domain 106.
#   bench/foxglove_stall.sh [BUILD_DIR] [RUNS] [DURATION]     (default: build, 5, 3000)
# Wall-clock numbers: run it on a quiet machine, inside `unshare -n` beside other users.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
runs="${2:-5}"
duration="${3:-3000}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
node="$build/sim_node/app/sim_node"
client="$root/bench/stalled_foxglove_client.py"
[ -x "$node" ] || { echo "build first: ./test.sh (missing $node)" >&2; exit 1; }
tmp="$(mktemp -d)"
pids=()
cleanup() {
  local p
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT

# steps per wall second of the summary line "...: fast, N steps, S s simulated in W s ..."
rate() { sed -nE 's/.*fast, ([0-9]+) steps, .* simulated in ([0-9.]+) s.*/\1 \2/p' "$1" |
  awk '{printf "%.0f\n", $1 / $2}'; }
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

declare -A rates
for ((i = 0; i < runs; ++i)); do
  for mode in none idle subscribe; do
    "$node" --scene config/scenes/case1_forward.yaml --mode fast --duration "$duration" \
      --domain 106 --foxglove 0 >"$tmp/node.out" 2>"$tmp/node.err" &
    pids=($!)
    if [ "$mode" != none ]; then
      until grep -q "Foxglove at" "$tmp/node.out"; do sleep 0.01; done
      port=$(sed -nE 's/.*Foxglove at ws:\/\/127.0.0.1:([0-9]+).*/\1/p' "$tmp/node.out")
      python3 "$client" "$port" "$mode" >"$tmp/client.out" &
      pids+=($!)
    fi
    wait "${pids[0]}"
    [ "$mode" != none ] && { kill -TERM "${pids[1]}"; wait "${pids[1]}" 2>/dev/null || true; }
    pids=()
    r=$(rate "$tmp/node.out")
    rates[$mode]+="$r "
    echo "run $i $mode: $r steps/s" >&2
  done
done
none=$(echo ${rates[none]} | tr ' ' '\n' | median)
echo "Case 1, sim_node --mode fast --foxglove 0, $duration s simulated, median of $runs runs:"
for mode in none idle subscribe; do
  m=$(echo ${rates[$mode]} | tr ' ' '\n' | median)
  awk -v m="$mode" -v r="$m" -v n="$none" \
    'BEGIN {printf "  %-10s %6d steps/s  ratio to none %.3f\n", m, r, r / n}'
done
