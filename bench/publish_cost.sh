#!/usr/bin/env bash
# Cost of DDS publishing with and without subscribers: sim_node --mode fast (as fast
# as possible, publishing every topic) on the steady-tow and Case 1 scenes, alone and with a
# subscriber process of every topic attached (bench/publish_cost_subscriber), against the same
# run offline (no DDS at all). Steps per second from sim_node's summary line; median of RUNS.
#   bench/publish_cost.sh [BUILD_DIR] [RUNS]        (default: build, 3)
# DDS domains 100-101 (tests/integration/README.md), config/cyclonedds.xml (loopback).
# Wall-clock numbers: run it on a quiet machine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
runs="${2:-3}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
node="$build/sim_node/app/sim_node"
sub="$build/bench/publish_cost_subscriber"
for x in "$node" "$sub"; do
  [ -x "$x" ] || { echo "build first: ./test.sh (missing $x)" >&2; exit 1; }
done
domain=100

# steps per second from "... N steps, S s simulated in W s (RTF ...)"
rate() { sed -nE 's/.* ([0-9]+) steps, .* simulated in ([0-9.]+) s.*/\1 \2/p' | awk '{printf "%.0f\n", $1 / $2}'; }
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

run_case() {  # label scene bodies duration
  local label="$1" scene="$2" bodies="$3" duration="$4"
  local off=() alone=() with=() i pid
  for ((i = 0; i < runs; ++i)); do
    off+=("$("$node" --scene "$scene" --mode offline --duration "$duration" | rate)")
    alone+=("$("$node" --scene "$scene" --mode fast --domain "$domain" --duration "$duration" | rate)")
    "$sub" --domain $((domain + 1)) --bodies "$bodies" --idle 2 >"$tmp/sub.txt" &
    pid=$!
    sleep 1  # the subscriber's readers exist before the node starts
    with+=("$("$node" --scene "$scene" --mode fast --domain $((domain + 1)) --duration "$duration" | rate)")
    wait "$pid"
    samples=$(sed -nE 's/.*: ([0-9]+) samples/\1/p' "$tmp/sub.txt")
  done
  local o a w
  o=$(printf '%s\n' "${off[@]}" | median)
  a=$(printf '%s\n' "${alone[@]}" | median)
  w=$(printf '%s\n' "${with[@]}" | median)
  awk -v l="$label" -v o="$o" -v a="$a" -v w="$w" -v s="$samples" 'BEGIN {
    printf "| %s | %d | %d (%.3f) | %d (%.3f) | %d |\n", l, o, a, a / o, w, w / o, s }'
}

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "| scene | offline steps/s | fast, no subscriber (ratio) | fast, 1 subscriber of every topic (ratio) | samples received |"
echo "|---|---|---|---|---|"
run_case "steady tow (1 sphere), 300 s" config/scenes/steady_tow.yaml towfish 300
run_case "Case 1 (2 vehicles), 100 s" config/scenes/case1_forward.yaml tow_vehicle,towfish 100
