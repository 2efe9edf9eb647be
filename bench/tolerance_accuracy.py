#!/usr/bin/env python3
"""The Newton tolerance against the discretisation error, on every shipped scene.

    /usr/bin/python3 bench/tolerance_accuracy.py [--build DIR] [--sim-node PATH]
        [--out DIR] [--table FILE] [--scenes a,b,...] [--scene-files A.yaml,B.yaml,...]
        [--duration S]
        [--tolerances 1e-4,1e-5,...] [--truth 1e-12] [--factor 4] [--ref-limit S]
        [--ratio 0.10] [--set KEY=VALUE ...]

For each scene of config/scenes/*.yaml (or --scenes, or the files of --scene-files, e.g.
bench/reference_scenes/*.yaml: the reference tests' cases, named by their file names), over the first --duration seconds (default
60, or the scene's own duration if shorter), offline (sim_node --mode offline --csv DIR):

  truth       the scene's own elements and step h at integrator.tolerance = --truth (1e-12); if
              that run fails (a static solve whose residual cannot reach it in double
              precision), at 10x that, up to 1e-10, said in the table
  reference   --factor (4) times the elements of every cable and h / --factor, at truth's
              tolerance (or 10x looser, up to 1e-10, where it fails there); if it still fails
              or takes longer than --ref-limit wall seconds, 2x the elements and h / 2 at
              truth's tolerance
  T           the scene's own elements and h at each tolerance T of --tolerances

and the two measures of docs/benchmarks.md ("Newton tolerance against discretisation error"),
at the output times the two runs share:

  track       max over the bodies and time of |p - p_other| [m] (bodies.csv); a scene without
              bodies: max over the cable nodes at the same arc length (node i of the run, node
              factor * i of the reference) of the first cable's CSV
  tension     max over time of |T_top - T_top_other| / max over time of |T_top_other|, T_top the
              tension of node 0 of the first cable (cable.csv, or <c>.csv of the scene's first
              cable in cables:)

The discretisation error is truth against reference; the solver error at T is run T against
truth; their ratio per measure is the share of the solver in the error. Printed as a Markdown
table (and written to --table, default out/tolerance_accuracy/table.md) with the Newton
iterations mean of sim_node's summary line and each run's wall time, then the loosest tolerance
at which every scene's ratio is <= --ratio (0.10) on both measures. A run that fails (exit != 0)
is recorded in the table ("exit 3"), not fatal. Python 3, standard library only. sim_node:
--sim-node, else DIR/sim_node/app/sim_node (--build, default build/ of this checkout).
Network scenes (cables:) get their finer elements by --set cables.<name>.elements=N.
"""

import argparse
import csv
import glob
import math
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_TOLERANCES = "1e-4,1e-5,1e-6,1e-7,1e-8"


def fail(message):
    sys.exit(f"tolerance_accuracy: {message}")


# ---------------------------------------------------------------------------------------------
# The scene file: its name, step, cables and their element counts (read as text: the standard
# library has no YAML reader, and the shipped scenes write these keys in two simple forms).

class Scene:
    def __init__(self, path):
        self.path = path
        with open(path) as f:
            self.lines = f.read().splitlines()
        self.name = os.path.splitext(os.path.basename(path))[0]
        self.step = self._time_key("step")
        self.duration = self._time_key("duration")
        self.network = any(line.startswith("cables:") for line in self.lines)
        self.has_bodies = any(line.startswith("bodies:") for line in self.lines)
        self.cables = self._cables()  # [(name, elements)], scene order
        if not self.cables:
            fail(f"{path}: no cable with elements found")

    def _time_key(self, key):
        for i, line in enumerate(self.lines):
            m = re.match(r"^time:\s*\{(.*)\}", line)
            if m:
                k = re.search(rf"\b{key}:\s*([0-9.eE+-]+)", m.group(1))
                if k:
                    return float(k.group(1))
            if re.match(r"^time:\s*(#.*)?$", line):
                for sub in self.lines[i + 1:]:
                    if sub and not sub.startswith(" "):
                        break
                    k = re.match(rf"^\s+{key}:\s*([0-9.eE+-]+)", sub)
                    if k:
                        return float(k.group(1))
        fail(f"{self.path}: time.{key} not found")

    def _block(self, key):
        """the lines below a top-level `key:` up to the next top-level key"""
        out, inside = [], False
        for line in self.lines:
            if line.startswith(key + ":"):
                inside = True
                continue
            if inside and line and not line.startswith((" ", "#")):
                break
            if inside:
                out.append(line)
        return out

    def _cables(self):
        if not self.network:
            for line in self._block("cable"):
                m = re.match(r"^  elements:\s*(\d+)", line)
                if m:
                    return [("cable", int(m.group(1)))]
            return []
        cables, name = [], None
        for line in self._block("cables"):
            m = re.match(r"^  ([A-Za-z_][A-Za-z0-9_]*):\s*(#.*)?$", line)
            if m:
                name = m.group(1)
                continue
            m = re.match(r"^    elements:\s*(\d+)", line)
            if m and name:
                cables.append((name, int(m.group(1))))
        return cables

    def element_sets(self, factor):
        """--set arguments giving every cable factor times its elements"""
        if not self.network:
            return ["--set", f"cable.elements={self.cables[0][1] * factor}"]
        args = []
        for name, n in self.cables:
            args += ["--set", f"cables.{name}.elements={n * factor}"]
        return args

    def top_cable_csv(self):
        return "cable.csv" if not self.network else f"{self.cables[0][0]}.csv"


# ---------------------------------------------------------------------------------------------
# Runs

class Run:
    def __init__(self, code, csv_dir, newton, wall):
        self.code, self.csv_dir, self.newton, self.wall = code, csv_dir, newton, wall

    @property
    def ok(self):
        return self.code == 0


def run_sim(sim_node, scene, out_dir, duration, tolerance, factor, log, extra=()):
    args = [sim_node, "--mode", "offline", "--scene", scene.path, "--duration", f"{duration:g}",
            "--csv", out_dir, "--set", f"integrator.tolerance={tolerance:g}"]
    for setting in extra:
        args += ["--set", setting]
    if factor != 1:
        args += ["--set", f"time.step={scene.step / factor:.12g}"] + scene.element_sets(factor)
    os.makedirs(out_dir, exist_ok=True)
    start = time.monotonic()
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    with open(out_dir + ".log", "w") as f:
        f.write(" ".join(args) + "\n" + p.stdout + p.stderr)
    m = re.search(r"Newton iterations mean ([0-9.]+)", p.stdout)
    newton = float(m.group(1)) if m else float("nan")
    print(f"  {os.path.basename(out_dir):>18}: exit {p.returncode}, {wall:6.2f} s, "
          f"Newton {newton:.2f}", file=log, flush=True)
    return Run(p.returncode, out_dir, newton, wall)


def run_loosening(sim_node, scene, out, name, duration, tolerance, factor, log):
    """run_sim at `tolerance`, else 10x looser up to 1e-10 (a static solve whose residual
    cannot reach it in double precision): (run, its tolerance, a note of the failed ones)."""
    run = run_sim(sim_node, scene, os.path.join(out, name), duration, tolerance, factor, log)
    note = ""
    while not run.ok and tolerance < 1e-10 * 1.001:
        note = f" ({tolerance:g}: exit {run.code})"
        tolerance *= 10
        run = run_sim(sim_node, scene, os.path.join(out, f"{name}_{tolerance:g}"), duration,
                      tolerance, factor, log)
    return run, tolerance, note


# ---------------------------------------------------------------------------------------------
# Measures

def time_key(text):
    return round(float(text), 6)


def read_bodies(path):
    """{(t, body): (x, y, z)}"""
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            out[(time_key(row["t"]), row["body"])] = (
                float(row["x"]), float(row["y"]), float(row["z"]))
    return out


def read_cable(path):
    """{(t, node): (x, y, z, tension)}"""
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            out[(time_key(row["t"]), int(row["node"]))] = (
                float(row["x"]), float(row["y"]), float(row["z"]), float(row["tension"]))
    return out


def measures(scene, run_dir, other_dir, node_factor):
    """(track [m], tension [relative]) of run_dir against other_dir; node i of run_dir is node
    node_factor * i of other_dir"""
    cable_run = read_cable(os.path.join(run_dir, scene.top_cable_csv()))
    cable_other = read_cable(os.path.join(other_dir, scene.top_cable_csv()))
    if scene.has_bodies:
        b_run = read_bodies(os.path.join(run_dir, "bodies.csv"))
        b_other = read_bodies(os.path.join(other_dir, "bodies.csv"))
        pairs = [(p, b_other[k]) for k, p in b_run.items() if k in b_other]
    else:
        pairs = [(v[:3], cable_other[(t, node_factor * n)][:3])
                 for (t, n), v in cable_run.items() if (t, node_factor * n) in cable_other]
    if not pairs:
        fail(f"no common output times in {run_dir} and {other_dir}")
    track = max(math.dist(a, b) for a, b in pairs)
    tops = [(v[3], cable_other[(t, 0)][3]) for (t, n), v in cable_run.items()
            if n == 0 and (t, 0) in cable_other]
    scale = max(abs(b) for _, b in tops)
    tension = max(abs(a - b) for a, b in tops) / scale
    return track, tension


# ---------------------------------------------------------------------------------------------

def fmt(x, digits=2):
    if x is None:
        return "-"
    if isinstance(x, str):
        return x
    if math.isnan(x):
        return "nan"
    return f"{x:.{digits}e}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory")
    ap.add_argument("--sim-node", help="sim_node to run (default BUILD/sim_node/app/sim_node)")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "tolerance_accuracy"),
                    help="CSV directories and logs of the runs")
    ap.add_argument("--table", help="Markdown table file (default OUT/table.md)")
    ap.add_argument("--scenes", help="comma-separated scene names (default every shipped scene)")
    ap.add_argument("--scene-files", help="comma-separated scene file paths (instead of --scenes)")
    ap.add_argument("--duration", type=float, default=60.0, help="simulated seconds per run")
    ap.add_argument("--tolerances", default=DEFAULT_TOLERANCES)
    ap.add_argument("--truth", type=float, default=1e-12, help="tolerance of truth and reference")
    ap.add_argument("--factor", type=int, default=4, help="reference: factor x elements, h/factor")
    ap.add_argument("--ref-limit", type=float, default=120.0,
                    help="wall seconds above which the reference falls back to 2x / h/2")
    ap.add_argument("--set", action="append", metavar="KEY=VALUE",
                    help="a scene override for the runs at each tolerance (not the truth or the "
                         "reference), e.g. integrator.force_tolerance=1e-3; repeatable")
    ap.add_argument("--ratio", type=float, default=0.10, help="largest solver / discretisation")
    a = ap.parse_args()

    sim_node = a.sim_node or os.path.join(a.build, "sim_node", "app", "sim_node")
    if not os.access(sim_node, os.X_OK):
        fail(f"no sim_node at {sim_node} (build it: cmake --build {a.build} --target sim_node, "
             "or give --sim-node)")
    tolerances = [float(t) for t in a.tolerances.split(",")]
    if a.scenes and a.scene_files:
        fail("give --scenes or --scene-files, not both")
    if a.scene_files:
        paths = [os.path.abspath(p) for p in a.scene_files.split(",") if p]
        for p in paths:
            if not os.path.isfile(p):
                fail(f"--scene-files: no scene file {p}")
        names = [os.path.splitext(os.path.basename(p))[0] for p in paths]
        if len(set(names)) != len(names):
            fail("--scene-files: two files with the same name (the runs' directories and the "
                 "table's rows are named by it)")
    elif a.scenes:
        paths = [os.path.join(ROOT, "config", "scenes", s + ".yaml") for s in a.scenes.split(",")]
    else:
        paths = sorted(glob.glob(os.path.join(ROOT, "config", "scenes", "*.yaml")))
    scenes = [Scene(p) for p in paths]
    log = sys.stderr

    summary, rows = [], []
    passing = {t: True for t in tolerances}
    for scene in scenes:
        duration = min(a.duration, scene.duration)
        out = os.path.join(a.out, scene.name)
        print(f"{scene.name} ({duration:g} s):", file=log, flush=True)
        # truth: --truth, else 10x looser up to 1e-10 (a static solve may not reach the
        # tightest residual in double precision); the reference at the same tolerance
        truth, truth_tol, truth_note = run_loosening(sim_node, scene, out, "truth", duration,
                                                     a.truth, 1, log)
        factor = a.factor
        # the reference at truth's tolerance, else 10x looser up to 1e-10 (its finer elements
        # carry more round-off: the static start of a cable on the seabed stalls at a residual
        # of about 1e-8 N), else at half the refinement
        ref, ref_tol, ref_tol_note = run_loosening(sim_node, scene, out, f"ref{factor}x",
                                                   duration, truth_tol, factor, log)
        ref_note = f"{factor}x el., h/{factor}"
        if (not ref.ok or ref.wall > a.ref_limit) and factor > 2:
            why = f"exit {ref.code}" if not ref.ok else f"{ref.wall:.0f} s"
            factor = 2
            ref_tol, ref_tol_note = truth_tol, ""
            ref = run_sim(sim_node, scene, os.path.join(out, "ref2x"), duration, ref_tol, 2,
                          log)
            ref_note = f"2x el., h/2 ({a.factor}x: {why})"
        ref_note = f"{ref_note}; tolerance {truth_tol:g}{truth_note}"
        if ref_tol != truth_tol:
            ref_note += f", reference {ref_tol:g}{ref_tol_note}"
        disc = None
        if truth.ok and ref.ok:
            disc = measures(scene, truth.csv_dir, ref.csv_dir, factor)
        els = "+".join(str(n) for _, n in scene.cables)
        summary.append([scene.name, f"{duration:g}", f"{els} el., h {scene.step:g} s", ref_note,
                        disc, truth, ref])
        loosest = None
        for t in tolerances:
            run = run_sim(sim_node, scene, os.path.join(out, f"tol{t:g}"), duration, t, 1, log,
                          a.set or ())
            solver = ratio = None
            ok = False
            if run.ok and truth.ok:
                solver = measures(scene, run.csv_dir, truth.csv_dir, 1)
                if disc:
                    ratio = tuple(s / d if d > 0 else float("inf") for s, d in zip(solver, disc))
                    ok = all(r <= a.ratio for r in ratio)
            if not ok:
                passing[t] = False
            elif loosest is None:
                loosest = t
            rows.append([scene.name, t, run, solver, ratio, ok])
        summary[-1].append(loosest)

    lines = []
    lines.append(f"sim_node: {sim_node}; truth and reference at tolerance {a.truth:g}; "
                 f"ratio limit {a.ratio:g}" +
                 (f"; runs at each tolerance with {', '.join(a.set)}" if a.set else ""))
    lines.append("")
    lines.append("| scene | duration [s] | discretisation | reference | track [m] | tension "
                 "| Newton/step truth, ref | wall [s] truth, ref | loosest T with both ratios "
                 f"<= {a.ratio:g} |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for name, duration, disc_text, ref_note, disc, truth, ref, loosest in summary:
        if disc is None:
            failed = "truth" if not truth.ok else "reference"
            code = truth.code if not truth.ok else ref.code
            track = tension = f"{failed} exit {code}"
        else:
            track, tension = fmt(disc[0]), fmt(disc[1])
        lines.append(f"| `{name}` | {duration} | {disc_text} | {ref_note} | {track} | {tension} "
                     f"| {truth.newton:.2f}, {ref.newton:.2f} | {truth.wall:.2f}, {ref.wall:.2f} "
                     f"| {fmt(loosest, 0) if loosest else 'none'} |")
    lines.append("")
    lines.append("| scene | tolerance | solver track [m] | solver tension | ratio track "
                 "| ratio tension | Newton/step | wall [s] |")
    lines.append("|---|---|---|---|---|---|---|---|")
    for name, t, run, solver, ratio, ok in rows:
        if not run.ok:
            cells = [f"exit {run.code}"] * 4
        elif solver is None:
            cells = ["-"] * 4
        else:
            mark = (lambda r: f"**{r:.3f}**" if r > a.ratio else f"{r:.3f}")
            cells = [fmt(solver[0]), fmt(solver[1]),
                     mark(ratio[0]) if ratio else "-", mark(ratio[1]) if ratio else "-"]
        lines.append(f"| `{name}` | {t:g} | " + " | ".join(cells) +
                     f" | {run.newton:.2f} | {run.wall:.2f} |")
    lines.append("")
    # the ratios at a glance: one row per scene, track / tension per tolerance
    lines.append("| ratio solver / discretisation (track / tension) | " +
                 " | ".join(f"{t:g}" for t in tolerances) + " |")
    lines.append("|---|" + "---|" * len(tolerances))
    for scene in scenes:
        cells = []
        for name, t, run, solver, ratio, ok in rows:
            if name != scene.name:
                continue
            if not run.ok:
                cells.append(f"exit {run.code}")
            elif ratio is None:
                cells.append("-")
            else:
                cell = f"{ratio[0]:.2g} / {ratio[1]:.2g}"
                cells.append(cell if ok else f"**{cell}**")
        lines.append(f"| `{scene.name}` | " + " | ".join(cells) + " |")
    lines.append("")
    ok_all = [t for t in tolerances if passing[t]]
    if ok_all:
        loosest = max(ok_all)
        tighter_fail = [t for t in tolerances if t < loosest and not passing[t]]
        lines.append(f"Loosest tolerance with every scene's ratio <= {a.ratio:g} on both measures: "
                     f"**{loosest:g}**" +
                     (f" (but not at {', '.join(f'{t:g}' for t in tighter_fail)})"
                      if tighter_fail else ""))
    else:
        lines.append(f"No tolerance of {a.tolerances} keeps every scene's ratio <= {a.ratio:g}.")
    text = "\n".join(lines) + "\n"
    print(text)
    table = a.table or os.path.join(a.out, "table.md")
    os.makedirs(os.path.dirname(os.path.abspath(table)), exist_ok=True)
    with open(table, "w") as f:
        f.write(text)
    print(f"written to {table}", file=log)


if __name__ == "__main__":
    main()
