#!/usr/bin/env bash
# Lockstep at the speed of the wire (docs/benchmarks.md, "Lockstep at the speed of the wire"):
#   1. the bare round trip of one lockstep step (bench/lockstep_pingpong: two processes, the
#      node's QoS, the odometry + status out and the commands back of one step, waitsets, no
#      physics): p50 and p99, with one controller process answering both vehicles and with two
#      (tow vehicle, towfish), RUNS runs of ROUNDS round trips each;
#   2. in the same run, Case 1 (100 s, 2000 steps, constant thrust 4500 N) offline and in
#      lockstep with one controller process (test_controller answering both vehicles) and with
#      two (test_controller --body tow_vehicle, --body towfish): the median wall time of one
#      step (offline: Step, from status.csv; lockstep: between consecutive answers of the
#      controller, from test_controller --stats);
#   3. the lockstep overhead (lockstep - offline) per step over the p50 round trip of the same
#      number of controllers.
# Medians over RUNS runs, the cases interleaved run by run. The LAST line is
#   lockstep overhead / round trip = R
# with R for one controller process (the line before it gives two). With --ddsperf it first
# runs Cyclone's own ddsperf ping / pong once (20 s) for comparison.
#
#   bench/run.sh lockstep [--ddsperf] [BUILD_DIR] [RUNS] [ROUNDS]    (default build, 5, 2000)
#
# DDS domains 152-156 (tests/integration/README.md), config/cyclonedds.xml (loopback). Run as
# root it re-runs itself in a private network namespace (unshare -n), so that nothing else on
# the machine shares its domains, and at nice -20 (TOWSIM_BENCH_NICE=0: not), so that the
# other work of a shared machine delays its wake-ups less. Wall-clock numbers.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ddsperf=0 counts=0
if [ "${1:-}" = "--ddsperf" ]; then ddsperf=1; shift; fi
if [ "${1:-}" = "--counts" ]; then counts=1; shift; fi
flag() { [ $ddsperf = 1 ] && echo --ddsperf; [ $counts = 1 ] && echo --counts; true; }
if [ "$(id -u)" = 0 ] && [ -z "${TOWSIM_PRIVATE_NET:-}" ] && command -v unshare >/dev/null; then
  exec env TOWSIM_PRIVATE_NET=1 unshare -n bash -c 'ip link set lo up && exec "$0" "$@"' \
    "${BASH_SOURCE[0]}" $(flag) "$@"
fi
# root: ahead of the other work on the machine (nice -20), unless TOWSIM_BENCH_NICE=0
if [ "$(id -u)" = 0 ] && [ "${TOWSIM_BENCH_NICE:-1}" != 0 ] && [ "$(nice)" != -20 ]; then
  exec nice -n -20 "${BASH_SOURCE[0]}" $(flag) "$@"
fi
build="${1:-${BUILD_DIR:-build}}"
runs="${2:-5}"
rounds="${3:-2000}"
cd "$root"
export CYCLONEDDS_URI="file://$root/config/cyclonedds.xml"
node="$build/sim_node/app/sim_node"
controller="$build/tests/integration/test_controller"
pingpong="$build/bench/lockstep_pingpong"
# TOWSIM_BENCH_BASELINE=FILE: another sim_node binary (an older tree's), run in lockstep beside
# this one in every run (same controllers), for a before/after comparison in one run
baseline="${TOWSIM_BENCH_BASELINE:-}"
for x in "$node" "$controller" "$pingpong" $baseline; do
  [ -x "$x" ] || { echo "build first: ./test.sh (missing $x)" >&2; exit 1; }
done
scene=config/scenes/case1_forward.yaml
thrust=4500   # [N], the same constant thrust offline (script) and in lockstep (controller)
duration=100  # [s] of simulated time: 2000 steps of 0.05 s
both=tow_vehicle,towfish

median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap cleanup EXIT

if [ $ddsperf = 1 ]; then
  command -v ddsperf >/dev/null || { echo "no ddsperf (Debian: cyclonedds-tools)" >&2; exit 1; }
  echo "== Cyclone's ddsperf ping / pong (domain 156, 20 s, default topic KS, waitset)"
  ddsperf -i 156 -D 22 pong waitset >/dev/null &
  pids=($!)
  ddsperf -i 156 -D 20 ping waitset | grep -E 'mean|rtt' | tail -3
  wait "${pids[0]}" || true
  pids=()
fi

# --counts: what one lockstep step costs each process, from the kernel's counters (perf stat:
# syscall tracepoints and context switches, every thread of the process): the difference
# between a run of 4000 and one of 2000 steps, over 2000, so that start-up and discovery cancel
events=syscalls:sys_enter_sendmsg,syscalls:sys_enter_recvmsg,syscalls:sys_enter_futex
events+=,syscalls:sys_enter_clock_nanosleep,syscalls:sys_enter_pselect6,context-switches
counted() {  # label outfile cmd...
  local label="$1" out="$2"; shift 2
  perf stat -x, -o "$out" -e "$events" -- "$@" >/dev/null 2>&1
}
counts_case() {  # label controller-commands (each "name|cmd ...", run beside the node)
  local label="$1"; shift
  local steps c d n
  for steps in 2000 4000; do
    d=$((steps / 20))
    counted node "$tmp/node.$steps" "$node" --scene "$scene" --mode lockstep --domain 156 \
      --duration "$d" --set 'script=[]' &
    local np=$! cps=() i=0
    for c in "$@"; do
      counted "ctl$i" "$tmp/ctl$i.$steps" bash -c "${c#*|}" &
      cps+=($!)
      i=$((i + 1))
    done
    for p in "${cps[@]}"; do wait "$p" || true; done
    wait "$np" || true
  done
  local names=(node) files=(node) i=0
  for c in "$@"; do names+=("${c%%|*}"); files+=("ctl$i"); i=$((i + 1)); done
  for ((i = 0; i < ${#files[@]}; ++i)); do
    awk -F, -v who="${names[i]}" -v label="$label" '
      FNR == NR && $3 != "" { a[$3] = $1; next }
      $3 != "" { d[$3] = ($1 - a[$3]) / 2000 }
      END {
        printf "| %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f |\n", label, who,
          d["syscalls:sys_enter_sendmsg"], d["syscalls:sys_enter_recvmsg"],
          d["syscalls:sys_enter_futex"], d["context-switches"],
          d["syscalls:sys_enter_clock_nanosleep"] + d["syscalls:sys_enter_pselect6"]
      }' "$tmp/${files[i]}.2000" "$tmp/${files[i]}.4000"
  done
}
if [ $counts = 1 ]; then
  command -v perf >/dev/null || { echo "--counts needs perf (Debian: linux-perf)" >&2; exit 1; }
  tmp="$(mktemp -d)"
  trap 'rm -rf "$tmp"' EXIT
  hello="$build/controllers/hello_controller"
  depth="$build/controllers/towfish_depth"
  echo "per lockstep step of Case 1 (perf stat, (4000 steps - 2000 steps) / 2000):"
  echo "| controllers | process | sendmsg | recvmsg | futex | context switches | sleeps (nanosleep, pselect) |"
  echo "|---|---|---|---|---|---|---|"
  counts_case "test_controller (both bodies)" \
    "test_controller|$controller --domain 156 --command tow_vehicle@0=$thrust,0,0"
  counts_case "hello_controller + towfish_depth --hold" \
    "hello_controller|$hello 156 $thrust 0" \
    "towfish_depth|$depth --domain 156 --body towfish --hold"
  exit 0
fi

# "test_controller: 1999 steps in 0.701 s: ..., 350.6 us/step (median 301.2 us)" -> "301.2 350.6"
per_step() { sed -nE 's/.* ([0-9.]+) us\/step \(median ([0-9.]+) us\)/\2 \1/p'; }
# "... round trip p50 31.2 us p99 58.0 us" -> "31.2 58.0"
rtt() { sed -nE 's/.*round trip p50 ([0-9.]+) us p99 ([0-9.]+) us/\1 \2/p'; }

pingpong_case() {  # domain pongs... (each pong: its bodies) -> "p50 p99"
  local domain="$1"; shift
  local n=$# b
  pids=()
  for b in "$@"; do
    "$pingpong" pong --domain "$domain" --bodies "$b" &
    pids+=($!)
  done
  "$pingpong" ping --domain "$domain" --bodies "$both" --pongs "$n" --rounds "$rounds" | tee -a "$tmp/pingpong.txt" | rtt
  for p in "${pids[@]}"; do wait "$p"; done
  pids=()
}

lockstep_case() {  # node domain bodies-per-controller... -> "median mean" us/step (controller 1)
  local node="$1" domain="$2"; shift 2
  local b i=0
  "$node" --scene "$scene" --mode lockstep --domain "$domain" --duration "$duration" \
    --set 'script=[]' >"$tmp/node.txt" &
  pids=($!)
  local cpids=()
  for b in "$@"; do
    local only=() command=(--command "tow_vehicle@0=$thrust,0,0")
    [ "$b" = all ] || only=(--body "$b")
    [ "$b" = all ] || [ "$b" = tow_vehicle ] || command=()  # the towfish: zeros, as offline
    "$controller" --domain "$domain" "${only[@]}" "${command[@]}" --stats >"$tmp/controller$i.txt" &
    cpids+=($!)
    i=$((i + 1))
  done
  for p in "${cpids[@]}"; do wait "$p"; done
  wait "${pids[0]}"
  pids=()
  per_step <"$tmp/controller0.txt"
}

# the median and the mean wall time of one offline step (Step alone: status.csv's wall_us of
# every step, output at 20 Hz) -> "median mean"
offline_case() {
  rm -rf "$tmp/offline"
  "$node" --scene "$scene" --mode offline --duration "$duration" --csv "$tmp/offline" \
    --set time.output_rate=20 --set "script=[{at: 0, body: tow_vehicle, thrust: $thrust}]" \
    >/dev/null
  echo "$(tail -n +3 "$tmp/offline/status.csv" | cut -d, -f5 | median)" \
    "$(tail -n +3 "$tmp/offline/status.csv" | awk -F, '{s += $5} END {printf "%.1f", s / NR}')"
}

tmp="$(mktemp -d)"
trap 'cleanup; rm -rf "$tmp"' EXIT
p1=() q1=() p2=() q2=() off=() l1=() l2=() offm=() l1m=() l2m=() b1=() b2=()
echo "== $runs runs: ping-pong ($rounds round trips), Case 1 offline and lockstep ($duration s, thrust $thrust N)"
for ((r = 0; r < runs; ++r)); do
  read -r a b < <(pingpong_case 152 "$both")
  p1+=("$a") q1+=("$b")
  read -r a b < <(pingpong_case 153 tow_vehicle towfish)
  p2+=("$a") q2+=("$b")
  read -r a b < <(offline_case)
  off+=("$a") offm+=("$b")
  read -r a b < <(lockstep_case "$node" 154 all)
  l1+=("$a") l1m+=("$b")
  read -r a b < <(lockstep_case "$node" 155 tow_vehicle towfish)
  l2+=("$a") l2m+=("$b")
  echo "run $((r + 1)): round trip p50 ${p1[r]} / ${p2[r]} us; per step, median (mean): offline ${off[r]} (${offm[r]}) us, lockstep ${l1[r]} (${l1m[r]}) / ${l2[r]} (${l2m[r]}) us (1 / 2 controllers)"
  if [ -n "$baseline" ]; then
    read -r a b < <(lockstep_case "$baseline" 154 all)
    b1+=("$a")
    read -r a b < <(lockstep_case "$baseline" 155 tow_vehicle towfish)
    b2+=("$a")
    echo "       baseline node $baseline: lockstep median ${b1[r]} / ${b2[r]} us"
  fi
done
head -1 "$tmp/pingpong.txt" | sed -E 's/; .*//'
tail -1 "$tmp/pingpong.txt" | sed -E 's/; .*//'
m() { printf '%s\n' "$@" | median; }
P1=$(m "${p1[@]}") Q1=$(m "${q1[@]}") P2=$(m "${p2[@]}") Q2=$(m "${q2[@]}")
OFF=$(m "${off[@]}") L1=$(m "${l1[@]}") L2=$(m "${l2[@]}")
OFFM=$(m "${offm[@]}") L1M=$(m "${l1m[@]}") L2M=$(m "${l2m[@]}")
B1="" B2=""
[ -z "$baseline" ] || { B1=$(m "${b1[@]}"); B2=$(m "${b2[@]}"); }
awk -v p1="$P1" -v q1="$Q1" -v p2="$P2" -v q2="$Q2" -v off="$OFF" -v l1="$L1" -v l2="$L2" \
  -v offm="$OFFM" -v l1m="$L1M" -v l2m="$L2M" -v b1="$B1" -v b2="$B2" 'BEGIN {
  printf "per step: the median step (the mean step in brackets); overhead = lockstep - offline\n"
  printf "| controllers | round trip p50 [us] | p99 [us] | offline [us/step] | lockstep [us/step] | overhead [us/step] | overhead / round trip p50 |\n"
  printf "|---|---|---|---|---|---|---|\n"
  printf "| 1 | %.1f | %.1f | %.1f (%.1f) | %.1f (%.1f) | %.1f (%.1f) | %.2f (%.2f) |\n", p1, q1, off, offm, l1, l1m, l1 - off, l1m - offm, (l1 - off) / p1, (l1m - offm) / p1
  printf "| 2 | %.1f | %.1f | %.1f (%.1f) | %.1f (%.1f) | %.1f (%.1f) | %.2f (%.2f) |\n", p2, q2, off, offm, l2, l2m, l2 - off, l2m - offm, (l2 - off) / p2, (l2m - offm) / p2
  if (b1 != "") {
    printf "| 1, baseline node | | | | %.1f | %.1f | %.2f |\n", b1, b1 - off, (b1 - off) / p1
    printf "| 2, baseline node | | | | %.1f | %.1f | %.2f |\n", b2, b2 - off, (b2 - off) / p2
  }
  printf "two controllers: lockstep overhead / round trip = %.2f\n", (l2 - off) / p2
  printf "lockstep overhead / round trip = %.2f\n", (l1 - off) / p1
}'
