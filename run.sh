#!/usr/bin/env bash
# run.sh — the main job: installs what is missing, builds, then
#   1. simulates the steady tow scene offline for 300 s (CSV in out/steady_tow/) and prints a
#      short summary (the verified reference case of the README, under a second);
#   2. simulates the paper's Case 2, the U-turn (config/scenes/case2_uturn.yaml, 250 s; CSV in
#      out/case2_uturn/), draws the paper's figures into out/case2_uturn/figures/ and prints the
#      summary table of scripts/paper_cases.py (steady speed, turning radii, towfish depth,
#      tensions; docs/paper_cases.md explains the numbers).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/scripts/setup.sh" python3

sim_node="$TOWSIM_BUILD_DIR"/sim_node/app/sim_node

# a python3 with matplotlib for the figures: setup.sh installs Debian's python3-matplotlib, which
# belongs to /usr/bin/python3 (a python3 earlier on PATH, e.g. pyenv's, may lack it)
plot_python=""
for candidate in /usr/bin/python3 python3; do
  if command -v "$candidate" >/dev/null && "$candidate" -c "import matplotlib" 2>/dev/null; then
    plot_python="$candidate"
    break
  fi
done

out=out/steady_tow
mkdir -p "$out"
# the summary line of sim_node is kept in summary.txt for summarize.py (real-time factor)
"$sim_node" --scene config/scenes/steady_tow.yaml --mode offline --duration 300 --csv "$out" \
  | tee "$out/summary.txt"
python3 scripts/summarize.py "$out"

echo
out=out/case2_uturn
rm -rf "$out"
mkdir -p "$out"
"$sim_node" --scene config/scenes/case2_uturn.yaml --mode offline --csv "$out" \
  | tee "$out/summary.txt"
if [[ -n "$plot_python" ]]; then
  "$plot_python" scripts/plot_paper.py "$out" "$out/figures" >/dev/null
  echo "figures (Park & Kim Figs. 14-20): $out/figures/"
else
  echo "note: no python3 with matplotlib found; figures skipped" \
       "(apt-get install python3-matplotlib, then: /usr/bin/python3 scripts/plot_paper.py $out)"
fi
python3 scripts/paper_cases.py --summary "$out"
