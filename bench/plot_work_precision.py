#!/usr/bin/env python3
"""Work-precision plots and Pareto fronts from bench/results/work_precision.csv.

    /usr/bin/python3 bench/plot_work_precision.py [CSV] [FIGDIR]

One figure per scene (docs/figures/work_precision_<scene>.png): error against cost (wall time
per simulated second, log-log), one line per method (integrator, coupling) through the time
steps, one panel per number of elements and error measure. Prints, per scene, the Pareto front
(no other run is both cheaper and more accurate in the towfish position) as a Markdown table.
"""

import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
POS_TARGET = 0.01  # towfish-track error target: 1 % of the cable length
ROOT = os.path.dirname(HERE)


def load(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            if r["ok"] != "1":
                continue
            for k in ("elements",):
                r[k] = int(r[k])
            for k in ("step", "wall_per_sim_s", "cpu_per_sim_s", "rtf", "newton_per_step",
                      "coupling_per_step", "pos_err_ref", "tension_err_ref", "pos_err_steady",
                      "tension_err_steady"):
                r[k] = float(r[k])
            rows.append(r)
    return rows


def method(r):
    return r["method"] + ("" if r["coupling"] == "none" else ", " + r["coupling"])


def sweep_rows(rows):
    """The swept runs: without the reference itself and its space check."""
    return [r for r in rows if r["note"] == ""]


def pareto(rows, keys):
    """Runs that no other run beats in cost and every error of `keys` at once."""
    pts = sweep_rows(rows)

    def dominates(a, b):
        no_worse = a["wall_per_sim_s"] <= b["wall_per_sim_s"] and all(a[k] <= b[k] for k in keys)
        better = a["wall_per_sim_s"] < b["wall_per_sim_s"] or any(a[k] < b[k] for k in keys)
        return no_worse and better

    front = [r for r in pts if not any(dominates(o, r) for o in pts)]
    return sorted(front, key=lambda r: r["wall_per_sim_s"])


def plot_scene(scene, rows, figdir):
    errs = [("pos_err_ref", "towfish position: max |p - p_ref| / L")]
    errs.append(("tension_err_ref", "top tension: RMS(T - T_ref) / RMS(T_ref)"))
    if any(not math.isnan(r["pos_err_steady"]) for r in rows):
        errs.append(("pos_err_steady", "final towfish offset vs steady solution / L"))
    elements = sorted({r["elements"] for r in sweep_rows(rows)})
    methods = sorted({method(r) for r in rows})
    fig, axes = plt.subplots(len(errs), len(elements), figsize=(4.2 * len(elements),
                                                                 3.4 * len(errs)),
                             squeeze=False, sharex=True)
    cmap = plt.get_cmap("tab10")
    for j, n in enumerate(elements):
        for i, (key, label) in enumerate(errs):
            ax = axes[i][j]
            for k, m in enumerate(methods):
                pts = sorted((r for r in sweep_rows(rows) if r["elements"] == n
                              and method(r) == m and r[key] > 0), key=lambda r: -r["step"])
                if not pts:
                    continue
                style = "--" if "staggered" in m else "-"
                ax.loglog([r["wall_per_sim_s"] for r in pts], [r[key] for r in pts], style,
                          marker="o", ms=3, color=cmap(k % 10), label=m)
                # label the steps on the first method only, to keep the panel readable
                if k == 0:
                    for r in pts:
                        ax.annotate("h=%g" % r["step"], (r["wall_per_sim_s"], r[key]),
                                    fontsize=6, xytext=(2, 2), textcoords="offset points")
            ax.grid(True, which="both", lw=0.3)
            if i == 0:
                ax.set_title("%s, %d elements" % (scene, n), fontsize=9)
            if j == 0:
                ax.set_ylabel(label, fontsize=7)
            if i == len(errs) - 1:
                ax.set_xlabel("wall time per simulated second [s]", fontsize=8)
    axes[0][0].legend(fontsize=6)
    fig.tight_layout()
    out = os.path.join(figdir, "work_precision_%s.png" % scene)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results",
                                                               "work_precision.csv")
    figdir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "figures")
    os.makedirs(figdir, exist_ok=True)
    rows = load(path)
    for scene in sorted({r["scene"] for r in rows}):
        sr = [r for r in rows if r["scene"] == scene]
        print("wrote", plot_scene(scene, sr, figdir))
        print()
        full = pareto(sr, ("pos_err_ref", "tension_err_ref"))
        within = [r for r in sr if r["pos_err_ref"] < POS_TARGET]
        front = pareto(within, ("tension_err_ref",))
        print("%s: %d runs on the Pareto front of (cost, towfish error, tension error); of the "
              "runs with towfish error < %g%% of L, those not beaten in both cost and tension "
              "error:" % (scene, len(full), 100 * POS_TARGET))
        print()
        print("| elements | h [s] | method | RTF | Newton/step | position err (% L) "
              "| tension err (%) |")
        print("|---|---|---|---|---|---|---|")
        for r in front:
            print("| %d | %g | %s | %.0f | %.2f | %.3g | %.3g |" % (
                r["elements"], r["step"], method(r), r["rtf"], r["newton_per_step"],
                100 * r["pos_err_ref"], 100 * r["tension_err_ref"]))
        print()


if __name__ == "__main__":
    main()
