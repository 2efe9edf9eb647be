#!/usr/bin/env bash
# BenchLockstepReportsTheRatio: bench/run.sh lockstep end to end, briefly (bench/lockstep.sh
# BUILD 1 200: one run, 200 round trips per ping-pong, Case 1 offline and in lockstep with one
# and with two controllers). A measurement is not judged (benchmarks never gate the tests);
# what is checked: it exits 0, the ping-pong exchanged the node's messages of one step at their
# CDR sizes, both rows of the table are there, and the last line is the one a check reads.
#   bench_lockstep_test.sh LOCKSTEP_SH BUILD_DIR          (domains 152-155, docs/benchmarks.md)
set -euo pipefail
script="$1" build="$2"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
rc=0
TOWSIM_BENCH_NICE=0 "$script" "$build" 1 200 >"$out" 2>&1 || rc=$?
cat "$out"
fail() { echo "FAIL: $1"; exit 1; }
[ "$rc" = 0 ] || fail "bench/lockstep.sh exited $rc"
# nav_msgs/Odometry in XCDR1 (4-byte encapsulation): stamp 8, frame_id "world_ned" 4+10,
# child_frame_id "tow_vehicle_frd" (aligned to 4) 4+16, pose (aligned to 8) 7 doubles,
# covariance 36, twist 6, covariance 36: 4 + 44 + 4 (padding) + 85 * 8 = 732 bytes
grep -q "out 2 x odom 732 B + status [0-9]* B, back 2 x command [0-9]* B" "$out" ||
  fail "ping-pong line: not the node's messages of one step"
grep -qE '^\| 1 \| [0-9.]+ \| [0-9.]+ \| ' "$out" || fail "no one-controller row"
grep -qE '^\| 2 \| [0-9.]+ \| [0-9.]+ \| ' "$out" || fail "no two-controller row"
tail -n 1 "$out" | grep -qE '^lockstep overhead / round trip = -?[0-9]+\.[0-9]+$' ||
  fail "last line: $(tail -n 1 "$out")"
echo "PASS"
