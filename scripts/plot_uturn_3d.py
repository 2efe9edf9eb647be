#!/usr/bin/env python3
"""Draws the 3D view of the paper's U-turn (Case 2) for the README: both vehicles' tracks and
the cable at a few instants, coloured by tension as the 3D markers colour it.

    sim_node --scene config/scenes/case2_uturn.yaml --mode offline --csv DIR
    python3 scripts/plot_uturn_3d.py DIR [OUT.png] [--from S] [--to S] [--at S,S,...] [--dpi N]

DIR holds the CSV files of `sim_node --csv DIR` or `towsim_export FILE --csv DIR` (e.g. run.sh's
out/case2_uturn/; docs/command_line.md "Output files"). OUT defaults to DIR/uturn_3d.png; the
README's picture is docs/figures/case2_uturn_3d.png, drawn with the defaults. Needs matplotlib
(Debian: python3-matplotlib; run it with /usr/bin/python3 where the python3 on PATH lacks it).

The world frame of the CSV files is NED (x north, y east, z down); the view is drawn with north
and east in the horizontal plane and depth down, looked at from the south-west above the
surface. The tension colours follow the markers' legend (docs/frames.md "Markers"): blue at
0 N (and in compression), green at 2.5 kN, red at 5 kN and above, linear in between.
"""

import argparse
import os
import sys

try:
    import matplotlib
except ImportError:
    sys.exit("plot_uturn_3d: needs matplotlib (Debian: apt-get install python3-matplotlib, then "
             "run it with the system's python3, /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
from matplotlib.colors import LinearSegmentedColormap, Normalize  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402

sys.dont_write_bytecode = True  # no scripts/__pycache__ from the import below
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_cases as pc  # noqa: E402

TENSION_LEGEND_MAX = 5000.0  # [N] red from here on: the markers' kTensionLegendMax
# blue -> green -> red, linear in tension (the markers' TensionColor)
TENSION_MAP = LinearSegmentedColormap.from_list(
    "tension", [(0.0, (0, 0, 1)), (0.5, (0, 1, 0)), (1.0, (1, 0, 0))])
BODY_STYLE = {"tow": ("tab:olive", "tow vehicle"), "fish": ("tab:orange", "towfish")}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("dir", help="CSV files of one U-turn run")
    p.add_argument("out", nargs="?", help="PNG file (default DIR/uturn_3d.png)")
    p.add_argument("--from", dest="t_from", type=float, default=40.0,
                   help="start of the drawn tracks [s] (default 40: before the 55 s rudder)")
    p.add_argument("--to", dest="t_to", type=float, default=150.0,
                   help="end of the drawn tracks [s] (default 150: on the way back)")
    p.add_argument("--at", default="50,65,80,95,110,130,150",
                   help="times of the drawn cable shapes [s], comma separated")
    p.add_argument("--dpi", type=int, default=110)
    a = p.parse_args()
    try:
        a.at = [float(s) for s in a.at.split(",")]
    except ValueError:
        p.error("--at = %s: must be numbers separated by commas" % a.at)
    if not a.t_from < a.t_to:
        p.error("--from = %g, --to = %g: --from must be before --to" % (a.t_from, a.t_to))
    return a


def nearest(times, t):
    """the element of times closest to t"""
    return min(times, key=lambda s: abs(s - t))


def main():
    a = parse_args()
    run = pc.Run(a.dir)
    out = a.out or os.path.join(a.dir, "uturn_3d.png")
    fig = plt.figure(figsize=(10, 5.4))
    ax = fig.add_subplot(projection="3d")
    norm = Normalize(0.0, TENSION_LEGEND_MAX)
    drawn = []  # every point drawn, for the axis limits

    # tracks: x north, y east, up = -z (NED -> the drawn axes)
    for key, name in (("tow", run.tow), ("fish", run.fish)):
        cols = run.bodies[name]
        sel = [i for i, t in enumerate(cols["t"]) if a.t_from <= t <= a.t_to]
        color, label = BODY_STYLE[key]
        track = [(cols["x"][i], cols["y"][i], -cols["z"][i]) for i in sel]
        drawn += track
        ax.plot(*zip(*track), color=color, lw=1.4, label=label + " track")

    # cable shapes, each segment coloured by the tension at its first node
    for t in a.at:
        tc = nearest(run.cable_times, t)
        nodes = run.cable[tc]
        pts = [(x, y, -z) for (_, x, y, z, _) in nodes]
        drawn += pts
        segs = [[pts[i], pts[i + 1]] for i in range(len(pts) - 1)]
        tensions = [max(0.0, nodes[i][4]) for i in range(len(pts) - 1)]
        ax.add_collection3d(Line3DCollection(segs, colors=TENSION_MAP(norm(tensions)), lw=2.2))
        for key, name in (("tow", run.tow), ("fish", run.fish)):  # the bodies at that time
            cols = run.bodies[name]
            i = min(range(len(cols["t"])), key=lambda k: abs(cols["t"][k] - tc))
            ax.scatter([cols["x"][i]], [cols["y"][i]], [-cols["z"][i]],
                       color=BODY_STYLE[key][0], s=28 if key == "tow" else 18,
                       edgecolors="black", linewidths=0.5, depthshade=False)
        x, y, z = pts[0]
        ax.text(x, y, z + 6.0, "%g s" % tc, fontsize=8, ha="center")

    ax.set_xlabel("north x [m]")
    ax.set_ylabel("east y [m]")
    ax.set_zlabel("up -z [m]")
    ax.view_init(elev=22, azim=-62)
    ax.set_box_aspect((1.6, 0.75, 0.45), zoom=1.15)
    lo = [min(v) for v in zip(*drawn)]
    hi = [max(v) for v in zip(*drawn)]
    ax.set_xlim(lo[0] - 5.0, hi[0] + 5.0)
    ax.set_ylim(lo[1] - 5.0, hi[1] + 5.0)
    ax.set_zlim(lo[2] - 2.0, 0.0)
    sm = plt.cm.ScalarMappable(cmap=TENSION_MAP, norm=norm)
    cb = fig.colorbar(sm, ax=ax, orientation="horizontal", shrink=0.45, pad=0.0, aspect=40)
    cb.set_label("cable tension [N] (red: 5 kN and above)")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("Case 2, the U-turn (rudder 20 deg from 55 s until the heading reaches 170 deg):"
                 "\ntracks from %g to %g s, the cable at the times marked" % (a.t_from, a.t_to),
                 fontsize=10)
    fig.subplots_adjust(left=0.0, right=1.0, top=0.93, bottom=0.06)
    fig.savefig(out, dpi=a.dpi)
    print("plot_uturn_3d: wrote %s" % out)


if __name__ == "__main__":
    main()
