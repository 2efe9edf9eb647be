#!/usr/bin/env bash
# SweepSlurm (ctest -R Slurm): towsim_sweep --slurm on a real one-machine Slurm cluster.
#
#   tests/integration/sweep_slurm_test.sh TOWSIM_SWEEP SWEEP_FILE
#
# Starts munged, slurmctld and slurmd (Debian's slurm-wlm and munge; scripts/setup.sh installs
# them for test.sh) with a generated slurm.conf, munge key, state and spool in a temporary
# folder, all inside a network namespace of its own (so the daemons' ports and traffic are
# private to the test; root needed, as in CI). Then runs the sweep locally and as one job array
# (--slurm), and checks that the two results.csv are equal apart from wall_s; then deletes one
# case's status and checks that --slurm --resume submits that case alone; then submits with
# --no-wait, waits for the job with squeue and checks that --collect gives the same table;
# then interrupts a sweep of longer cases (SIGINT) and checks that its job was cancelled. Every daemon is
# stopped and the folder removed when the script ends, also on failure (trap). Where Slurm
# cannot be started the test says why and FAILS.
set -euo pipefail

fail() { echo "SweepSlurm: FAIL: $*" >&2; exit 1; }

if [[ $# -ne 2 ]]; then fail "usage: $0 TOWSIM_SWEEP SWEEP_FILE"; fi
sweep_bin="$1"
sweep_file="$2"

# a network namespace of our own: loopback plus a veth pair with an address that exists only
# inside it (glibc's getaddrinfo with AI_ADDRCONFIG, which Slurm uses, finds no IPv4 address
# on a loopback-only host and then cannot resolve even 127.0.0.1)
if [[ "${TOWSIM_SLURM_NETNS:-}" != 1 ]]; then
  [[ "$(id -u)" == 0 ]] || fail "needs root (network namespace, Slurm daemons); CI runs as root"
  command -v unshare >/dev/null || fail "unshare not found (util-linux)"
  exec env TOWSIM_SLURM_NETNS=1 unshare -n bash "$0" "$@"
fi
ip link set lo up
ip link add towsim_s0 type veth peer name towsim_s1 || fail "cannot create a veth pair"
ip addr add 10.217.17.1/24 dev towsim_s0
ip link set towsim_s0 up
ip link set towsim_s1 up

for cmd in munged mungekey slurmctld slurmd sbatch squeue sinfo scancel; do
  command -v "$cmd" >/dev/null ||
    fail "$cmd not found: install slurm-wlm and munge (scripts/setup.sh does for test.sh)"
done

tmp="$(mktemp -d /tmp/towsim_slurm.XXXXXX)"
stop_daemon() {  # pid file
  [[ -s "$1" ]] || return 0
  local pid
  pid="$(cat "$1")"
  kill "$pid" 2>/dev/null || return 0
  for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.1; done
  kill -9 "$pid" 2>/dev/null || true
}
cleanup() {
  local code=$?
  stop_daemon "$tmp/slurmd.pid"
  stop_daemon "$tmp/slurmctld.pid"
  stop_daemon "$tmp/munge/munged.pid"
  if [[ $code != 0 ]]; then
    for log in "$tmp"/slurmctld.log "$tmp"/slurmd.log "$tmp"/munge/munged.log; do
      [[ -f "$log" ]] && { echo "--- $log (last lines)" >&2; tail -n 15 "$log" >&2; }
    done
  fi
  rm -rf "$tmp"
  exit "$code"
}
trap cleanup EXIT

# munge: a key of our own, its own socket
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool"
chmod 700 "$tmp/munge"
mungekey -c -k "$tmp/munge/munge.key" || fail "mungekey failed"
munged --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munge/munged.log" \
  --seed-file="$tmp/munge/munged.seed" || fail "munged did not start"

cpus="$(nproc)"
cat >"$tmp/slurm.conf" <<CONF
# one-machine cluster of tests/integration/sweep_slurm_test.sh
ClusterName=towsim
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$tmp/slurm.conf"
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" -N localhost || fail "slurmd did not start"

# the node must come up idle
for _ in $(seq 150); do
  state="$(sinfo -h -o %T 2>/dev/null || true)"
  [[ "$state" == idle ]] && break
  sleep 0.2
done
[[ "${state:-}" == idle ]] || fail "the Slurm node did not become idle (sinfo: '${state:-}')"
echo "SweepSlurm: one-machine Slurm cluster up ($cpus CPUs)"

# the reference: the same sweep, locally
t0=$(date +%s.%N)
"$sweep_bin" "$sweep_file" --out "$tmp/local" --workers 2 || fail "local sweep failed"
t1=$(date +%s.%N)
"$sweep_bin" "$sweep_file" --out "$tmp/slurm" --slurm || fail "towsim_sweep --slurm failed"
t2=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" -v c="$t2" -v n="$cpus" 'BEGIN {
  printf "SweepSlurm: 8 cases: local (2 workers) %.2f s, Slurm (%d CPUs) %.2f s: ", b - a, n, c - b
  printf "Slurm overhead %.2f s per case\n", (c - b - (b - a)) / 8 }'

# the tables agree apart from wall_s (column 5; the fields before it hold no commas here)
strip() { cut -d, -f1-4,6- "$1"; }
[[ "$(wc -l <"$tmp/slurm/results.csv")" == 9 ]] || fail "Slurm table has not 8 rows"
if ! diff <(strip "$tmp/local/results.csv") <(strip "$tmp/slurm/results.csv"); then
  fail "the Slurm table differs from the local one"
fi
[[ "$(grep -c ',ok,0,' "$tmp/slurm/results.csv")" == 8 ]] || fail "not every case ok"
[[ -s "$tmp/slurm/slurm/job_id" ]] || fail "no job_id"
[[ -f "$tmp/slurm/slurm/task_7.out" ]] || fail "no Slurm output of task 7"
# each case ran inside a Slurm task (its environment)
grep -q . "$tmp/slurm/case_0000/case_status.txt" || fail "no case_status.txt"

# --resume with one case missing: the array holds that case only
rm "$tmp/slurm/case_0003/case_status.txt"
"$sweep_bin" "$sweep_file" --out "$tmp/slurm" --slurm --resume 2>"$tmp/resume.err" ||
  { cat "$tmp/resume.err" >&2; fail "--slurm --resume failed"; }
grep -q "array 3 (1 cases)" "$tmp/resume.err" || { cat "$tmp/resume.err" >&2; fail "resume array"; }
diff <(strip "$tmp/local/results.csv") <(strip "$tmp/slurm/results.csv") ||
  fail "the table after --resume differs"
# --no-wait returns once submitted; --collect tabulates when the job has ended
"$sweep_bin" "$sweep_file" --out "$tmp/later" --slurm --no-wait >"$tmp/later.out" 2>&1 ||
  { cat "$tmp/later.out" >&2; fail "--slurm --no-wait failed"; }
grep -q -- "--collect" "$tmp/later.out" || { cat "$tmp/later.out" >&2; fail "--no-wait: no hint"; }
job="$(cat "$tmp/later/slurm/job_id")"
for _ in $(seq 600); do
  [[ -z "$(squeue -h -j "$job" 2>/dev/null)" ]] && break
  sleep 0.1
done
[[ -z "$(squeue -h -j "$job" 2>/dev/null)" ]] || fail "job $job did not end"
"$sweep_bin" "$sweep_file" --out "$tmp/later" --collect >/dev/null || fail "--collect failed"
diff <(strip "$tmp/local/results.csv") <(strip "$tmp/later/results.csv") ||
  fail "the table of --no-wait + --collect differs"
# SIGINT while the job runs: the job is cancelled (scancel), the sweep exits 130 with the
# cases finished so far in its table; 8 cases of the steady tow for 2000 s (~0.5 s each)
cat >"$tmp/long.yaml" <<YAML
scene: $(cd "$(dirname "$sweep_file")" && pwd)/../../../config/scenes/steady_tow.yaml
duration: 2000
parameters:
  cable.elements: [10, 11, 12, 13, 14, 15, 16, 17]
results:
  depth: {signal: towfish.depth}
YAML
"$sweep_bin" "$tmp/long.yaml" --out "$tmp/stop" --slurm >"$tmp/stop.out" 2>&1 &
stop_pid=$!
for _ in $(seq 300); do
  compgen -G "$tmp/stop/case_*/case_status.txt" >/dev/null && break
  sleep 0.1
done
kill -INT "$stop_pid"
stop_code=0
wait "$stop_pid" || stop_code=$?
[[ $stop_code == 130 ]] || { cat "$tmp/stop.out" >&2; fail "SIGINT: exit $stop_code, not 130"; }
stop_job="$(cat "$tmp/stop/slurm/job_id")"
[[ -z "$(squeue -h -j "$stop_job" 2>/dev/null)" ]] || fail "SIGINT: job $stop_job not cancelled"
stop_rows=$(($(wc -l <"$tmp/stop/results.csv") - 1))
((stop_rows >= 1 && stop_rows < 8)) || fail "SIGINT: $stop_rows rows in the table"
grep -q "$((8 - stop_rows)) not run" "$tmp/stop.out" || { cat "$tmp/stop.out" >&2; fail "summary"; }

echo "SweepSlurm: PASS (Slurm table equals the local one; --resume submitted case 3 alone;" \
  "--no-wait then --collect gives the same table; SIGINT cancels the job," \
  "$stop_rows of 8 cases finished before it are in the table)"
