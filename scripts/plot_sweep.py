#!/usr/bin/env python3
"""The results of a towsim sweep against two of its parameters: a family of curves and a heat map.

    python3 scripts/plot_sweep.py DIR [OUTDIR] [--x PARAMETER] [--family PARAMETER]
                                  [--results NAME,...] [--dpi N]

DIR is the folder of `towsim_sweep FILE --out DIR` (docs/sweeps.md): it reads DIR/results.csv
and DIR/columns.json (which columns are parameters and which results). For every result R it
writes into OUTDIR (default DIR/plots), each as PNG and SVG:

  R_curves.png/.svg   R against the x parameter (default the sweep's first parameter), one curve
                      per value of the family parameter (default the second), with a legend;
                      when more parameters vary, one curve per combination of all but x
  R_heatmap.png/.svg  R over x (columns) and the family parameter (rows), colour = value, each
                      cell labelled; only when no two cases share a cell (exactly the two
                      parameters vary), else it says why and draws none

Cases that failed are left out (their count is in the title; an empty cell of the heat map). A
result with `settled:` marks the cases that did not settle: hollow markers on the curves, a
cross in the heat map's cell. Numeric values are placed by value (sorted), others (vectors,
names) as categories in the order of the table. Needs python3 with matplotlib (Debian:
python3-matplotlib; /usr/bin/python3 where the python3 on PATH lacks it); draws off-screen.
"""

import argparse
import csv
import json
import math
import os
import sys

try:
    import matplotlib
except ImportError:
    sys.exit("plot_sweep: needs matplotlib (Debian: apt-get install python3-matplotlib, then run "
             "it with the system's python3, /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)


def number(text):
    """the float of `text`, or None if it is not a finite number"""
    try:
        x = float(text)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def axis_values(values):
    """the distinct values in plotting order, and a function value -> position"""
    distinct = list(dict.fromkeys(values))
    if distinct and all(number(v) is not None for v in distinct):
        distinct.sort(key=number)
        return distinct, number, True
    return distinct, distinct.index, False


def read_sweep(folder):
    table = os.path.join(folder, "results.csv")
    columns = os.path.join(folder, "columns.json")
    for f in (table, columns):
        if not os.path.isfile(f):
            sys.exit(f"plot_sweep: {f} not found: DIR must be the --out folder of towsim_sweep")
    with open(columns) as fh:
        meta = json.load(fh)
    with open(table, newline="") as fh:
        rows = list(csv.DictReader(fh))
    return meta, rows


def label(name, value):
    return f"{name} = {value}"


def plot_curves(result, rows, x_name, others, out, dpi):
    """R against x, one curve per combination of `others` (parameter names)"""
    ok = [r for r in rows if r["status"] == "ok" and number(r[result["name"]]) is not None]
    failed = sum(1 for r in rows if r["status"] != "ok")
    xs, x_pos, x_numeric = axis_values([r[x_name] for r in rows])
    groups = {}
    for r in ok:
        groups.setdefault(tuple(r[p] for p in others), []).append(r)
    keys = list(groups)
    if others:
        # the family in the order of its values
        orders = [axis_values([r[p] for r in rows]) for p in others]
        keys.sort(key=lambda k: tuple(o[1](v) for o, v in zip(orders, k)))
    settled_column = result.get("settled_column")
    fig, ax = plt.subplots(figsize=(7.0, 4.5))
    unsettled_any = False
    for k, key in enumerate(keys):
        members = sorted(groups[key], key=lambda r: x_pos(r[x_name]))
        x = [x_pos(r[x_name]) for r in members]
        y = [float(r[result["name"]]) for r in members]
        text = ", ".join(label(p, v) for p, v in zip(others, key)) or result["name"]
        color = plt.get_cmap("tab10")(k % 10)
        ax.plot(x, y, "-", color=color, label=text)
        for xi, yi, r in zip(x, y, members):
            unsettled = settled_column is not None and r.get(settled_column) == "0"
            unsettled_any = unsettled_any or unsettled
            ax.plot([xi], [yi], "o", color=color, markersize=6,
                    markerfacecolor="none" if unsettled else color)
    if unsettled_any:
        ax.plot([], [], "o", color="black", markerfacecolor="none",
                label="not settled (hollow)")
    if not x_numeric:
        ax.set_xticks(range(len(xs)))
        ax.set_xticklabels(xs, rotation=20)
    ax.set_xlabel(x_name)
    what = result["signal"] + (f", {result['stat']}" if result.get("stat") else "")
    ax.set_ylabel(f"{result['name']} ({what})")
    title = f"{result['name']} against {x_name}"
    if failed:
        title += f" ({failed} failed case(s) not shown)"
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    if keys and (others or unsettled_any):
        ax.legend(title=None if not others else ", ".join(others), fontsize=8)
    fig.tight_layout()
    return save(fig, out, f"{result['name']}_curves", dpi)


def plot_heatmap(result, rows, x_name, y_name, out, dpi):
    xs, x_pos, x_numeric = axis_values([r[x_name] for r in rows])
    ys, y_pos, y_numeric = axis_values([r[y_name] for r in rows])
    cells = {}
    for r in rows:
        key = (r[x_name], r[y_name])
        if key in cells:
            print(f"plot_sweep: {result['name']}: no heat map: several cases at {x_name} = "
                  f"{key[0]}, {y_name} = {key[1]} (more parameters vary; choose with --x and "
                  "--family)")
            return []
        cells[key] = r
    settled_column = result.get("settled_column")
    grid = [[math.nan] * len(xs) for _ in ys]
    marks = []
    for (xv, yv), r in cells.items():
        i, j = ys.index(yv), xs.index(xv)
        value = number(r[result["name"]]) if r["status"] == "ok" else None
        if value is not None:
            grid[i][j] = value
            if settled_column is not None and r.get(settled_column) == "0":
                marks.append((j, i))
    fig, ax = plt.subplots(figsize=(1.2 * len(xs) + 3.0, 0.6 * len(ys) + 2.5))
    image = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis")
    cbar = fig.colorbar(image, ax=ax)
    what = result["signal"] + (f", {result['stat']}" if result.get("stat") else "")
    cbar.set_label(f"{result['name']} ({what})")
    finite = [v for row in grid for v in row if not math.isnan(v)]
    mid = (min(finite) + max(finite)) / 2 if finite else 0.0
    for i, row in enumerate(grid):
        for j, v in enumerate(row):
            text = "failed" if math.isnan(v) and (xs[j], ys[i]) in cells else (
                "" if math.isnan(v) else f"{v:.4g}")
            ax.text(j, i, text, ha="center", va="center", fontsize=8,
                    color="white" if (not math.isnan(v) and v < mid) else "black")
    for j, i in marks:
        ax.plot([j + 0.38], [i + 0.3], "x", color="red", markersize=9, mew=1.5)
    if marks:
        ax.plot([], [], "x", color="red", label="not settled")
        ax.legend(loc="upper left", bbox_to_anchor=(0, -0.18), fontsize=8, frameon=False)
    ax.set_xticks(range(len(xs)))
    ax.set_xticklabels(xs)
    ax.set_yticks(range(len(ys)))
    ax.set_yticklabels(ys)
    ax.set_xlabel(x_name)
    ax.set_ylabel(y_name)
    ax.set_title(f"{result['name']} over {x_name} and {y_name}")
    fig.tight_layout()
    return save(fig, out, f"{result['name']}_heatmap", dpi)


def save(fig, out, stem, dpi):
    written = []
    for ext in ("png", "svg"):
        path = os.path.join(out, f"{stem}.{ext}")
        fig.savefig(path, dpi=dpi)
        written.append(path)
    plt.close(fig)
    return written


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", help="the sweep's folder (towsim_sweep --out DIR)")
    ap.add_argument("outdir", nargs="?", help="where the plots go (default DIR/plots)")
    ap.add_argument("--x", help="the parameter on the x axis (default the first)")
    ap.add_argument("--family", help="one curve per value of it; the heat map's rows "
                    "(default the second parameter)")
    ap.add_argument("--results", help="comma-separated result names (default all)")
    ap.add_argument("--dpi", type=int, default=120)
    args = ap.parse_args()

    meta, rows = read_sweep(args.dir)
    parameters = [p["name"] for p in meta["parameters"]]
    results = meta["results"]
    if args.results:
        wanted = args.results.split(",")
        unknown = [w for w in wanted if w not in [r["name"] for r in results]]
        if unknown:
            sys.exit(f"plot_sweep: --results: no result named {', '.join(unknown)} (results: "
                     f"{', '.join(r['name'] for r in results)})")
        results = [r for r in results if r["name"] in wanted]
    if not results:
        sys.exit("plot_sweep: the sweep has no results to plot (results: in the sweep file)")
    for flag, name in (("--x", args.x), ("--family", args.family)):
        if name is not None and name not in parameters:
            sys.exit(f"plot_sweep: {flag} {name}: not a parameter of the sweep (parameters: "
                     f"{', '.join(parameters)})")
    x_name = args.x or parameters[0]
    rest = [p for p in parameters if p != x_name]
    family = args.family or (rest[0] if rest else None)
    if family == x_name:
        sys.exit("plot_sweep: --x and --family name the same parameter")
    # the curves: one per combination of every other parameter that varies, family first
    varying = [p for p in rest if len({r[p] for r in rows}) > 1 or p == family]
    others = ([family] if family else []) + [p for p in varying if p != family]
    out = args.outdir or os.path.join(args.dir, "plots")
    os.makedirs(out, exist_ok=True)
    written = []
    for result in results:
        written += plot_curves(result, rows, x_name, others, out, args.dpi)
        if family:
            written += plot_heatmap(result, rows, x_name, family, out, args.dpi)
    for path in written:
        print(path)


if __name__ == "__main__":
    main()
