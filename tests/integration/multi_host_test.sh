#!/usr/bin/env bash
# MultiHostLockstep (ctest -R MultiHost): sim_node and its controllers on two "hosts".
#
#   tests/integration/multi_host_test.sh SIM_NODE MANEUVER_RUNNER TOWFISH_DEPTH
#
# Two network namespaces joined by a veth pair, with addresses that exist only inside them
# (10.218.17.1 and 10.218.17.2), stand for the simulator host and a vehicle computer. sim_node
# runs Case 1 in lockstep in the first, the manoeuvre runner (4165 N, rudder 0) and the towfish
# depth controller (--hold) in the second, all with config/cyclonedds_two_hosts.xml (unicast,
# no multicast). The trajectory (bodies.csv) must be byte-identical to the same run on loopback
# (config/cyclonedds.xml, all processes in one namespace), and the DDS traffic must have crossed
# the veth pair. Then the link drops for 1 s during a realtime run: both vehicles go to the
# failsafe and the controllers drive again when it is back. Domains 160 (two hosts), 161
# (loopback), 162 (link drop). Needs root (ip netns); CI runs as root.
# The namespaces are removed when the script ends, also on failure (trap).
set -euo pipefail

fail() { echo "MultiHostLockstep: FAIL: $*" >&2; exit 1; }
[[ $# -eq 3 ]] || fail "usage: $0 SIM_NODE MANEUVER_RUNNER TOWFISH_DEPTH"
sim_node="$1"; runner="$2"; depth="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
scene="$root/config/scenes/case1_forward.yaml"
duration=30      # [s] simulated: 600 steps of 0.05 s
timeout_s=60     # [s] a run that takes longer has hung

[[ "$(id -u)" == 0 ]] || fail "needs root for ip netns (CI runs as root)"
command -v ip >/dev/null || fail "ip (iproute2) not found"

sim_ns="towsim_mh_sim_$$"
ctl_ns="towsim_mh_ctl_$$"
ref_ns="towsim_mh_ref_$$"
tmp="$(mktemp -d /tmp/towsim_multi_host.XXXXXX)"
pids=()
cleanup() {
  local code=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  for ns in "$sim_ns" "$ctl_ns" "$ref_ns"; do ip netns del "$ns" 2>/dev/null || true; done
  if [[ $code != 0 ]]; then
    for log in "$tmp"/*.err; do
      [[ -s "$log" ]] && { echo "--- $log" >&2; tail -n 5 "$log" >&2; }
    done
  fi
  rm -rf "$tmp"
  exit "$code"
}
trap cleanup EXIT

# the two hosts and the link between them
ip netns add "$sim_ns" || fail "cannot create a network namespace"
ip netns add "$ctl_ns"
ip netns add "$ref_ns"
ip link add towsim_mh0 netns "$sim_ns" type veth peer name towsim_mh1 netns "$ctl_ns" ||
  fail "cannot create the veth pair"
ip -n "$sim_ns" addr add 10.218.17.1/24 dev towsim_mh0
ip -n "$ctl_ns" addr add 10.218.17.2/24 dev towsim_mh1
for ns in "$sim_ns" "$ctl_ns" "$ref_ns"; do ip -n "$ns" link set lo up; done
ip -n "$sim_ns" link set towsim_mh0 up
ip -n "$ctl_ns" link set towsim_mh1 up

two_hosts="file://$root/config/cyclonedds_two_hosts.xml"
loopback="file://$root/config/cyclonedds.xml"
# runs "$@" in namespace $1 with the environment of the following NAME=value words
in_ns() { local ns="$1"; shift; ip netns exec "$ns" env "$@"; }

# waits for the pids given, each within the timeout; fails naming the one that did not end
wait_all() {
  local deadline=$((SECONDS + timeout_s))
  for pid in "$@"; do
    while kill -0 "$pid" 2>/dev/null; do
      ((SECONDS < deadline)) || fail "a process (pid $pid) did not end within ${timeout_s} s"
      sleep 0.05
    done
    wait "$pid" || fail "a process (pid $pid) exited with $?"
  done
}

# run: tag, namespace of the node, namespace of the controllers, domain, URI, addresses
run_case1() {
  local tag="$1" node_ns="$2" ctl="$3" domain="$4" uri="$5" node_env=("${@:6:2}") ctl_env=("${@:8:2}")
  in_ns "$ctl" CYCLONEDDS_URI="$uri" "${ctl_env[@]}" \
    "$runner" --thrust 4165 --rudder-deg 0 --domain "$domain" \
    >"$tmp/$tag.runner.out" 2>"$tmp/$tag.runner.err" &
  local runner_pid=$!
  pids+=("$runner_pid")
  in_ns "$ctl" CYCLONEDDS_URI="$uri" "${ctl_env[@]}" \
    "$depth" --hold --domain "$domain" >"$tmp/$tag.depth.out" 2>"$tmp/$tag.depth.err" &
  local depth_pid=$!
  pids+=("$depth_pid")
  in_ns "$node_ns" CYCLONEDDS_URI="$uri" "${node_env[@]}" \
    "$sim_node" --scene "$scene" --mode lockstep --duration "$duration" --domain "$domain" \
    --set 'script=[]' --csv "$tmp/$tag" >"$tmp/$tag.node.out" 2>"$tmp/$tag.node.err" &
  local node_pid=$!
  pids+=("$node_pid")
  wait_all "$node_pid" "$runner_pid" "$depth_pid"
  # every step answered by the controllers: no failsafe, no lockstep timeout
  grep -q "failsafes 0," "$tmp/$tag.node.out" || fail "$tag: a failsafe: $(cat "$tmp/$tag.node.out")"
  grep -q "lockstep timeouts 0," "$tmp/$tag.node.out" ||
    fail "$tag: lockstep timeouts: $(cat "$tmp/$tag.node.out")"
}

rx_before="$(ip netns exec "$ctl_ns" cat /sys/class/net/towsim_mh1/statistics/rx_bytes)"
run_case1 two_hosts "$sim_ns" "$ctl_ns" 160 "$two_hosts" \
  TOWSIM_DDS_ADDRESS=10.218.17.1 TOWSIM_DDS_PEER=10.218.17.2 \
  TOWSIM_DDS_ADDRESS=10.218.17.2 TOWSIM_DDS_PEER=10.218.17.1
rx_after="$(ip netns exec "$ctl_ns" cat /sys/class/net/towsim_mh1/statistics/rx_bytes)"
run_case1 loopback "$ref_ns" "$ref_ns" 161 "$loopback" X=1 Y=1 X=1 Y=1

# the traffic went over the link: at least one status and odometry message per step
crossed=$((rx_after - rx_before))
steps=$((duration * 20))
((crossed > steps * 200)) || fail "only $crossed bytes crossed the veth link for $steps steps"
rows="$(grep -c towfish "$tmp/two_hosts/bodies.csv" || true)"
((rows == 301)) || fail "bodies.csv of the two-host run has $rows towfish rows, expected 301"
cmp "$tmp/two_hosts/bodies.csv" "$tmp/loopback/bodies.csv" ||
  fail "the trajectory across two hosts differs from the loopback one"
# the link drops (hardware in the loop, docs/hardware_in_the_loop.md): realtime at 4x with the
# controllers across the link, which goes down for 1 s of wall time (4 s of sim time, 8 times
# publish.command_timeout) from 1 s on: both vehicles fall back to the failsafe, the run goes
# on, and the controllers take over again when the link is back
in_ns "$ctl_ns" CYCLONEDDS_URI="$two_hosts" TOWSIM_DDS_ADDRESS=10.218.17.2 TOWSIM_DDS_PEER=10.218.17.1 \
  "$runner" --thrust 4165 --rudder-deg 0 --domain 162 >"$tmp/drop.runner.out" 2>"$tmp/drop.runner.err" &
drop_runner=$!; pids+=("$drop_runner")
in_ns "$ctl_ns" CYCLONEDDS_URI="$two_hosts" TOWSIM_DDS_ADDRESS=10.218.17.2 TOWSIM_DDS_PEER=10.218.17.1 \
  "$depth" --hold --domain 162 >"$tmp/drop.depth.out" 2>"$tmp/drop.depth.err" &
drop_depth=$!; pids+=("$drop_depth")
in_ns "$sim_ns" CYCLONEDDS_URI="$two_hosts" TOWSIM_DDS_ADDRESS=10.218.17.1 TOWSIM_DDS_PEER=10.218.17.2 \
  "$sim_node" --scene "$scene" --mode realtime --rate 4 --duration 16 --domain 162 \
  --wait-for-controllers --set 'script=[]' --csv "$tmp/drop" >"$tmp/drop.node.out" 2>"$tmp/drop.node.err" &
drop_node=$!; pids+=("$drop_node")
# the run starts when both controllers have answered (--wait-for-controllers)
for _ in $(seq 200); do [[ -s "$tmp/drop/bodies.csv" ]] && break; sleep 0.05; done
sleep 1
ip -n "$ctl_ns" link set towsim_mh1 down
sleep 1
ip -n "$ctl_ns" link set towsim_mh1 up
wait_all "$drop_node" "$drop_runner" "$drop_depth"
drop_summary="$(cat "$tmp/drop.node.out")"
failsafes="$(sed -n 's/.*failsafes \([0-9]*\),.*/\1/p' <<<"$drop_summary")"
((failsafes >= 2)) || fail "link down: expected both vehicles in failsafe, summary: $drop_summary"
echo "MultiHostLockstep: link dropped for 1 s: $drop_summary"
# the towing vehicle's surge speed u (bodies.csv column 9) every 2 s of sim time
awk -F, '$2 == "tow_vehicle" && ($1 * 10) % 20 == 0 { printf "  t = %s s: u = %.3f m/s\n", $1, $9 }' \
  "$tmp/drop/bodies.csv"
# thrust is back: with zero thrust (failsafe) u could only fall, drag slowing the vehicle;
# from t = 10 s to 16 s it rises by more than 0.5 m/s (about 1.7 m/s measured)
rise="$(awk -F, '$2 == "tow_vehicle" && $1 == 10 { a = $9 } $2 == "tow_vehicle" && $1 == 16 { b = $9 }
  END { print (b - a > 0.5) ? "yes" : "no" }' "$tmp/drop/bodies.csv")"
[[ "$rise" == yes ]] || fail "link back: the towing vehicle does not accelerate again"

echo "MultiHostLockstep: PASS ($steps lockstep steps across the veth link, $crossed bytes" \
  "received by the controller host; bodies.csv identical to loopback)"
