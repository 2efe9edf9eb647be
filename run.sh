#!/usr/bin/env bash
# run.sh — the main job: installs what is missing, builds, then simulates the steady tow
# scene offline for 300 s, writes CSV to out/steady_tow/ and prints a short summary.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/scripts/setup.sh" python3

out=out/steady_tow
mkdir -p "$out"
# the summary line of sim_node is kept in summary.txt for summarize.py (real-time factor)
"$TOWSIM_BUILD_DIR"/sim_node/app/sim_node --scene config/scenes/steady_tow.yaml \
  --mode offline --duration 300 --csv "$out" | tee "$out/summary.txt"
python3 scripts/summarize.py "$out"
