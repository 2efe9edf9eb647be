#!/usr/bin/env bash
# Instruction counts (callgrind: repeatable on a noisy machine) of each feature_cost variant:
# 400 steps of the steady-tow scene with one feature taken out (bench/feature_cost.cc), only the
# stepping collected. Prints a Markdown table: instructions per step and per Newton iteration,
# and the calls and inclusive instructions of the functions that implement each load term, so
# that an omitted term shows as never called.
#   bench/feature_cost_callgrind.sh [BUILD_DIR] [STEPS]     (needs valgrind, python3)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
steps="${2:-400}"
exe="$build/bench/feature_cost"
[ -x "$exe" ] || { echo "build first: ./test.sh (or cmake --build $build --target feature_cost)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "valgrind not installed (apt-get install valgrind)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

variants=(all_loads no_gravity no_buoyancy no_drag no_added_mass no_bending no_loads no_body
          two_vehicles_staggered current_profile case3_calm_bottomless case3_calm case3_waves
          case3_waves_per_iteration)
for v in "${variants[@]}"; do
  valgrind --tool=callgrind --callgrind-out-file="$out/$v.out" --toggle-collect='*ProfileSteps*' \
    --toggle-collect='*ProfileEvaluate*' \
    "$exe" --profile "$v" "$steps" >"$out/$v.txt" 2>"$out/$v.log"
done

python3 - "$out" "$steps" "${variants[@]}" <<'EOF'
import re, sys
out, steps, variants = sys.argv[1], int(sys.argv[2]), sys.argv[3:]

# the functions that implement each feature (towsim::core), by a fragment of their name
FUNCS = [("Evaluate", "System::Evaluate"),
         ("InternalForce", "AncfElement::InternalForce"),
         ("ElementLoadResidual", "ElementLoadResidual"),
         ("UniformLoad", "core::UniformLoad"),
         ("CableDrag", "core::CableDrag"),
         ("NormalProjector", "core::NormalProjector"),
         ("AddedMassTangentDerivative", "AddedMassTangentDerivative"),
         ("Factor", "BlockTridiagonal::Factor"),
         ("AdvanceVehicle", "core::AdvanceVehicle")]

def parse(path):
    """total Ir, and per function (by name) calls and inclusive Ir"""
    names, total = {}, 0
    calls, incl, self_ = {}, {}, {}
    pair = {}  # (caller, callee) -> inclusive Ir
    fn = cfn = None
    pending_calls = None
    def name(kind, text):
        m = re.match(r"\((\d+)\)(?: (.*))?", text)
        key = (kind, m.group(1))
        if m.group(2): names[m.group(1)] = m.group(2)
        return names.get(m.group(1), m.group(1))
    for line in open(path, errors="replace"):
        line = line.rstrip("\n")
        if line.startswith("fn="):
            fn = name("fn", line[3:])
        elif line.startswith("cfn="):
            cfn = name("fn", line[4:])
        elif line.startswith("cfi=") or line.startswith("cfl="):
            pass
        elif line.startswith("calls="):
            pending_calls = int(line[6:].split()[0])
        elif line and (line[0].isdigit() or line[0] in "+-*"):
            parts = line.split()
            if len(parts) < 2: continue
            ir = int(parts[1])
            if pending_calls is not None:
                calls[cfn] = calls.get(cfn, 0) + pending_calls
                incl[cfn] = incl.get(cfn, 0) + ir  # inclusive cost of the call
                pair[(fn, cfn)] = pair.get((fn, cfn), 0) + ir
                pending_calls = None
            else:
                self_[fn] = self_.get(fn, 0) + ir
                total += ir
        elif line.startswith("summary:") or line.startswith("totals:"):
            pass
    # the fixed-state evaluations (ProfileEvaluate*) are not part of the stepping totals
    ev = {k: sum(v for (f, c), v in pair.items() if k in f and "System::Evaluate" in c)
          for k in ("ProfileEvaluateJacobian", "ProfileEvaluateResidual")}
    total -= sum(s for f, s in self_.items() if "ProfileEvaluate" in f)
    total -= sum(ev.values())
    return total, calls, incl, ev

def find(d, frag):
    s = 0
    for k, v in d.items():
        if frag in k and "(" in k or k.endswith(frag):
            if frag in k: s += v
    return s

rows = {}
for v in variants:
    total, calls, incl, ev = parse(f"{out}/{v}.out")
    newton = int(re.search(r"(\d+) Newton", open(f"{out}/{v}.txt").read()).group(1))
    rows[v] = (total, newton, {f: (find(calls, frag), find(incl, frag)) for f, frag in FUNCS}, ev)

base_total, base_newton, _, base_ev = rows[variants[0]]
print(f"\ncallgrind: one evaluation of the residual and Newton matrix (J) or the residual alone (R),")
print(f"at the state reached after {steps} steps, averaged over {steps} calls\n")
print("| variant | Ir per J evaluation | ratio | Ir per R evaluation | ratio |")
print("|---|---|---|---|---|")
for v in variants:
    ev = rows[v][3]
    j, r = ev["ProfileEvaluateJacobian"] / steps, ev["ProfileEvaluateResidual"] / steps
    bj, br = base_ev["ProfileEvaluateJacobian"] / steps, base_ev["ProfileEvaluateResidual"] / steps
    print(f"| {v} | {j:,.0f} | {j/bj:.3f} | {r:,.0f} | {r/br:.3f} |")
print(f"\ncallgrind, {steps} steps each (instructions collected in the stepping only)\n")
print("| variant | Ir/step | ratio | Newton/step | Ir/Newton iteration | ratio |")
print("|---|---|---|---|---|---|")
for v in variants:
    total, newton, _, _ = rows[v]
    print(f"| {v} | {total/steps:,.0f} | {total/base_total:.3f} | {newton/steps:.2f} | "
          f"{total/newton:,.0f} | {(total/newton)/(base_total/base_newton):.3f} |")
print("\ncalls (inclusive Ir per call) of the functions behind each feature, stepping and")
print("fixed-state evaluations together\n")
print("| variant | " + " | ".join(f for f, _ in FUNCS) + " |")
print("|---|" + "---|" * len(FUNCS))
for v in variants:
    _, _, f, _ = rows[v]
    cells = []
    for name, _ in FUNCS:
        c, ir = f[name]
        cells.append("0" if c == 0 else f"{c:,} ({ir/c:,.0f})")
    print(f"| {v} | " + " | ".join(cells) + " |")
EOF
