#!/usr/bin/env bash
# Recording overhead benchmark for docs/recording.md (not a test): sim_node in fast mode (no
# subscriber, so without --record nothing is serialized) with and without --record, the same
# scene, alternating, N runs each. Per run: the median of the node's own step time (status.csv
# wall_us: the step and its publication, which is where recording adds its work), robust
# against the other processes of a shared machine; prints those and the ratio of their
# medians. Uses DDS domain 89 and the loopback configuration.
#   tests/integration/recording_bench.sh [BUILD_DIR] [SCENE] [DURATION] [N]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build}
scene=${2:-$here/config/scenes/case1_forward.yaml}
duration=${3:-100}
runs=${4:-5}
export CYCLONEDDS_URI=file://$here/config/cyclonedds.xml
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
per_step() {  # median wall_us of status.csv in $1 (rows after t = 0)
  tail -n +3 "$1/status.csv" | cut -d, -f5 | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
plain=() recorded=()
for i in $(seq "$runs"); do
  "$build/sim_node/app/sim_node" --scene "$scene" --mode fast --domain 89 \
    --duration "$duration" --csv "$tmp/plain" > /dev/null
  plain+=("$(per_step "$tmp/plain")")
  "$build/sim_node/app/sim_node" --scene "$scene" --mode fast --domain 89 \
    --duration "$duration" --csv "$tmp/rec" --record "$tmp/run.mcap" --overwrite > /dev/null 2>&1
  recorded+=("$(per_step "$tmp/rec")")
done
size=$(stat -c %s "$tmp/run.mcap")
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
mp=$(median "${plain[@]}"); mr=$(median "${recorded[@]}")
echo "scene $(basename "$scene"), --duration $duration, fast mode, $runs runs each"
echo "without --record: ${plain[*]} us/step (median $mp)"
echo "with --record:    ${recorded[*]} us/step (median $mr), file $((size / 1024)) KiB"
awk -v a="$mp" -v b="$mr" 'BEGIN {printf "overhead: %.1f us/step, ratio %.3f\n", b - a, b / a}'
