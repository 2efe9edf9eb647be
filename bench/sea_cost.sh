#!/usr/bin/env bash
# What a JONSWAP sea costs Case 1 (docs/benchmarks.md, "The sea"): Case 1 (strong coupling, as
# shipped) calm against the same scene in a JONSWAP sea, Hs 2 m, Tp 8 s, gamma 3.3, head sea,
# 100 components, seed 1, 20 s ramp, bottomless (deep water).
#   1. instructions (callgrind, repeatable): STEPS steps of each (bench/feature_cost --profile
#      two_vehicles_strong / case1_waves), the stepping only; per step the whole, the wave
#      sampling at the cable nodes (StepSampler::SampleWaves) and at the vehicles
#      (SampleVehicleFlow), and the Newton iterations;
#   2. wall time: sim_node --mode offline --duration 100 of both scenes, alternated: ROUNDS
#      rounds of hyperfine (3 runs each after a warm-up), the ratio of the means per round.
#   bench/sea_cost.sh [BUILD_DIR] [STEPS] [ROUNDS]     (needs valgrind, hyperfine, python3)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
steps="${2:-2000}"
rounds="${3:-5}"
exe="$build/bench/feature_cost"
sim="$build/sim_node/app/sim_node"
for x in "$exe" "$sim"; do
  [ -x "$x" ] || { echo "build first: ./test.sh (no $x)" >&2; exit 1; }
done
for c in valgrind hyperfine python3; do
  command -v "$c" >/dev/null || { echo "$c not installed (apt-get install $c)" >&2; exit 1; }
done
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

for v in two_vehicles_strong case1_waves; do
  valgrind --tool=callgrind --callgrind-out-file="$out/$v.out" --toggle-collect='*ProfileSteps*' \
    "$exe" --profile "$v" "$steps" >"$out/$v.txt" 2>"$out/$v.log"
  callgrind_annotate --inclusive=yes "$out/$v.out" >"$out/$v.ann" 2>/dev/null
done

waves='environment.waves={jonswap: {hs: 2, tp: 8, gamma: 3.3, direction_deg: 180, components: 100, seed: 1}, ramp: 20}'
scene=config/scenes/case1_forward.yaml
for r in $(seq "$rounds"); do
  hyperfine -N --warmup 1 --runs 3 --export-json "$out/wall$r.json" \
    "$sim --scene $scene --mode offline --duration 100" \
    "$sim --scene $scene --mode offline --duration 100 --set '$waves'" >/dev/null 2>&1
done

python3 - "$out" "$steps" "$rounds" <<'EOF'
import json, re, statistics, sys
out, steps, rounds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])

def total(v):
    # "Collected : N" of the stepping (callgrind's log)
    return int(re.search(r"Collected : (\d+)", open(f"{out}/{v}.log").read()).group(1))

def inclusive(v, fragment):
    for line in open(f"{out}/{v}.ann"):
        if fragment in line:
            return int(line.split()[0].replace(",", ""))
    return 0

def newton(v):
    return int(re.search(r"(\d+) Newton", open(f"{out}/{v}.txt").read()).group(1))

calm, sea = "two_vehicles_strong", "case1_waves"
print(f"\ncallgrind, {steps} steps (h = 0.05 s), the stepping only\n")
print("| scene | Ir/step | ratio | Newton/step | SampleWaves Ir/step | SampleVehicleFlow Ir/step |")
print("|---|---|---|---|---|---|")
for v, name in ((calm, "Case 1, calm"), (sea, "Case 1, JONSWAP-100")):
    t = total(v)
    print(f"| {name} | {t/steps:,.0f} | {t/total(calm):.3f} | {newton(v)/steps:.2f} | "
          f"{inclusive(v, 'StepSampler::SampleWaves')/steps:,.0f} | "
          f"{inclusive(v, 'core::SampleVehicleFlow(')/steps:,.0f} |")
ratios, means = [], []
for r in range(1, rounds + 1):
    res = json.load(open(f"{out}/wall{r}.json"))["results"]
    means.append((res[0]["mean"], res[1]["mean"]))
    ratios.append(res[1]["mean"] / res[0]["mean"])
print(f"\nwall time, sim_node --mode offline --duration 100, {rounds} rounds of hyperfine "
      f"(3 runs each), alternated\n")
print(f"calm {statistics.median(m[0] for m in means):.3f} s, waves "
      f"{statistics.median(m[1] for m in means):.3f} s (medians of the rounds' means); ratio "
      f"median {statistics.median(ratios):.2f} (rounds: {', '.join(f'{x:.2f}' for x in ratios)})")
EOF
