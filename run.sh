#!/usr/bin/env bash
# run.sh — the main job, end to end over loopback DDS. Installs what is missing, builds, then
#   1. the steady tow scene offline (300 s, under a second; the verified reference of
#      docs/verification.md) with a short summary;
#   2. the paper's Case 2 U-turn (config/scenes/case2_uturn.yaml, 250 s) twice, side by side, as
#      separate processes on DDS: sim_node (realtime at TOWSIM_RATE x, default 50, waiting for
#      its controllers before the first step), the manoeuvre runner (thrust, 20 deg rudder from
#      55 s until the heading reaches 170 deg) and the towfish depth controller, once holding
#      the towfish's fins at zero (the paper's run) and once holding the towfish at 25 m;
#   3. each run is recorded by the node to out/<run>.mcap and exported to CSV with
#      towsim_export, the paper's figures and the 3D view of the turn (scripts/plot_uturn_3d.py)
#      are drawn into out/case2_uturn/figures/, and a
#      summary table is printed: steady speed, turning radii, towfish depth range, tensions, and
#      the towfish depth excursion with and without the depth controller.
# While the first U-turn runs, towsim_foxglove serves it live to Foxglove at
# ws://localhost:TOWSIM_FOXGLOVE_PORT (docs/foxglove.md; layout config/foxglove/towsim.json).
# It ends by itself (about 10 s after the build) and leaves no process behind: every process
# it starts is stopped on exit, also on Ctrl-C. Environment: TOWSIM_DOMAIN (DDS domain of the
# first run, the second uses +1; default 20), TOWSIM_RATE (default 50; 1 to watch in real
# time), TOWSIM_FOXGLOVE_PORT (default 8765), TOWSIM_SECURE=1: the DDS
# runs secured end to end (DDS Security, docs/security.md): scripts/security.sh makes the
# identities in out/security/ (the node; the manoeuvre runner may command the tow vehicle only,
# the depth controller the towfish only; the Foxglove bridge) and every process runs with
# --security.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/scripts/setup.sh" python3

bin="$TOWSIM_BUILD_DIR"
sim_node="$bin"/sim_node/app/sim_node
exporter="$bin"/sim_node/app/towsim_export
runner="$bin"/controllers/maneuver_runner
depth_ctl="$bin"/controllers/towfish_depth
foxglove="$bin"/sim_node/app/towsim_foxglove
foxglove_port="${TOWSIM_FOXGLOVE_PORT:-8765}"
domain="${TOWSIM_DOMAIN:-20}"
rate="${TOWSIM_RATE:-50}"
scene=config/scenes/case2_uturn.yaml
node_security=() runner_security=() depth_security=() foxglove_security=()
if [[ "${TOWSIM_SECURE:-0}" == 1 ]]; then
  rm -rf out/security
  scripts/security.sh out/security sim_node maneuver_runner:tow_vehicle towfish_depth:towfish \
    towsim_foxglove
  node_security=(--security out/security/sim_node)
  foxglove_security=(--security out/security/towsim_foxglove)
  runner_security=(--security out/security/maneuver_runner)
  depth_security=(--security out/security/towfish_depth)
fi

# every process started here is stopped when the script ends, however it ends
pids=()
bridge_pid=""
cleanup() {
  local pid
  for pid in "${pids[@]}" $bridge_pid; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}" $bridge_pid; do wait "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# a python3 with matplotlib for the figures: setup.sh installs Debian's python3-matplotlib, which
# belongs to /usr/bin/python3 (a python3 earlier on PATH, e.g. pyenv's, may lack it)
plot_python=""
for candidate in /usr/bin/python3 python3; do
  if command -v "$candidate" >/dev/null && "$candidate" -c "import matplotlib" 2>/dev/null; then
    plot_python="$candidate"
    break
  fi
done

echo "== 1. steady tow, offline"
out=out/steady_tow
mkdir -p "$out"
# the summary line of sim_node is kept in summary.txt for summarize.py (real-time factor)
"$sim_node" --scene config/scenes/steady_tow.yaml --mode offline --duration 300 --csv "$out" \
  | tee "$out/summary.txt"
python3 scripts/summarize.py "$out"

# one Case 2 run on DDS: run_uturn NAME DOMAIN DEPTH_CONTROLLER_ARGS...
# starts the node and both controllers in the background; logs in out/NAME.log/
run_uturn() {
  local name="$1" dom="$2"
  shift 2
  local logs="out/$name.log"
  rm -rf "$logs" "out/$name.mcap"
  mkdir -p "$logs"
  "$sim_node" --scene "$scene" --mode realtime --rate "$rate" --wait-for-controllers \
    --duration 250 --set 'script=[]' --domain "$dom" --record "out/$name.mcap" \
    "${node_security[@]}" >"$logs/sim_node.out" 2>"$logs/sim_node.err" &
  pids+=($!)
  "$runner" --body tow_vehicle --thrust 4165 --rudder-deg 20 --start 55 --until-yaw-deg 170 \
    --domain "$dom" "${runner_security[@]}" >"$logs/maneuver_runner.out" 2>"$logs/maneuver_runner.err" &
  pids+=($!)
  "$depth_ctl" --body towfish "$@" --domain "$dom" "${depth_security[@]}" \
    >"$logs/towfish_depth.out" 2>"$logs/towfish_depth.err" &
  pids+=($!)
}

# waits for the processes of one run (node first); prints the node's summary; fails loudly
finish_uturn() {
  local name="$1" node_pid="$2" runner_pid="$3" depth_pid="$4"
  local logs="out/$name.log" rc=0
  wait "$node_pid" || rc=$?
  if ((rc != 0)); then
    echo "run.sh: error: sim_node ($name) exited with $rc:" >&2
    cat "$logs/sim_node.err" >&2
    exit 1
  fi
  for pid in "$runner_pid" "$depth_pid"; do
    rc=0
    wait "$pid" || rc=$?
    if ((rc != 0)); then
      echo "run.sh: error: a controller of $name exited with $rc; see $logs/" >&2
      cat "$logs"/*.err >&2
      exit 1
    fi
  done
  echo "[$name] $(tail -n 1 "$logs/sim_node.out")"
}

echo
echo "== 2. Case 2 U-turn over DDS: sim_node + maneuver_runner + towfish_depth, twice" \
     "(realtime x$rate, domains $domain and $((domain + 1))$([[ ${#node_security[@]} -gt 0 ]] &&
     echo ", DDS Security: identities in out/security/"))"
# the live view of the first run (a port in use only costs the live view: see its log)
mkdir -p out
"$foxglove" --domain "$domain" --port "$foxglove_port" --quiet "${foxglove_security[@]}" \
  >out/towsim_foxglove.out 2>out/towsim_foxglove.err &
bridge_pid=$!
echo "Foxglove: open ws://localhost:$foxglove_port while the first run lasts" \
     "(layout: config/foxglove/towsim.json; docs/foxglove.md)"
run_uturn case2_uturn "$domain" --hold
run_uturn case2_uturn_depth_control "$((domain + 1))" --depth 25
finish_uturn case2_uturn "${pids[0]}" "${pids[1]}" "${pids[2]}"
finish_uturn case2_uturn_depth_control "${pids[3]}" "${pids[4]}" "${pids[5]}"
pids=()
kill -TERM "$bridge_pid" 2>/dev/null || true
wait "$bridge_pid" 2>/dev/null || true
bridge_pid=""

echo
echo "== 3. recordings -> CSV -> figures and summary"
for name in case2_uturn case2_uturn_depth_control; do
  rm -rf "out/$name"
  "$exporter" "out/$name.mcap" --csv "out/$name" >/dev/null
done
"$exporter" out/case2_uturn.mcap --info
out=out/case2_uturn
if [[ -n "$plot_python" ]]; then
  "$plot_python" scripts/plot_paper.py "$out" "$out/figures" >/dev/null
  "$plot_python" scripts/plot_uturn_3d.py "$out" "$out/figures/uturn_3d.png" >/dev/null
  echo "figures (Park & Kim Figs. 14-20, and the 3D view uturn_3d.png): $out/figures/"
else
  echo "note: no python3 with matplotlib found; figures skipped" \
       "(apt-get install python3-matplotlib, then: /usr/bin/python3 scripts/plot_paper.py $out)"
fi
echo
python3 scripts/paper_cases.py --summary "$out"
echo
python3 scripts/paper_cases.py --depth-control "$out" out/case2_uturn_depth_control
