#!/usr/bin/env python3
"""Draws the figures of Park & Kim (Case 1: Figs. 8-13, Case 2: Figs. 14-20) from a sim_node run.

    python3 scripts/plot_paper.py DIR [OUTDIR] [--tow NAME] [--fish NAME] [--every S]

DIR holds the CSV files of `sim_node --csv DIR` (DESIGN §5); the PNG files go to OUTDIR
(default DIR). Needs python3 and matplotlib (Debian: python3-matplotlib); draws off-screen.

  cable_shape.png        cable in the x-z plane every --every seconds (Fig. 8), depth down
  linear_velocity.png    u, v, w of both bodies, body frame (Figs. 9, 15)
  angular_velocity.png   p, q, r of both bodies [deg/s] (Figs. 10, 16)
  euler_angles.png       roll, pitch, yaw of both bodies [deg] (Figs. 11, 17)
  force_<body>.png       force and moment the cable exerts on the body, body frame
                         (Figs. 12-13, 18-19)
  trajectory.png         both paths seen from above: x north to the right, y east down (Fig. 14)
  towfish_depth.png      the towfish's depth z (Fig. 20)

The towing body is --tow (default tow_vehicle, else the first body of bodies.csv), the towed
one --fish (default towfish, else the last body).
"""

import argparse
import csv
import math
import os
import sys
from collections import defaultdict

try:
    import matplotlib
except ImportError:
    sys.exit("plot_paper: needs matplotlib (Debian: apt-get install python3-matplotlib, then run "
             "it with the system's python3, /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

DEG = 180.0 / math.pi


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def by_name(rows, key):
    """rows grouped by the value of `key`, in order of first appearance"""
    groups = defaultdict(list)
    for row in rows:
        groups[row[key]].append(row)
    return groups


def column(rows, key, scale=1.0):
    return [float(r[key]) * scale for r in rows]


def pick_body(names, wanted, fallback_index, what):
    if wanted in names:
        return wanted
    if not names:
        sys.exit("plot_paper: bodies.csv has no bodies")
    name = names[fallback_index]
    print("plot_paper: no body named %s; using %s as the %s" % (wanted, name, what))
    return name


def save(fig, outdir, name):
    path = os.path.join(outdir, name)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("plot_paper: wrote %s" % path)


def plot_components(outdir, name, title, series, panels):
    """one panel per (column, label, scale); each body in `series` a line per panel"""
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(8, 2.2 * len(panels)))
    for ax, (key, label, scale) in zip(axes, panels):
        for body, rows in series:
            ax.plot(column(rows, "t"), column(rows, key, scale), label=body)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].set_title(title)
    axes[0].legend(loc="best")
    axes[-1].set_xlabel("t [s]")
    save(fig, outdir, name)


def plot_cable_shape(outdir, cable, every, title):
    times = sorted({float(r["t"]) for r in cable})
    if not times:
        return
    # snapshots every `every` seconds, from the first written time, plus the last one
    shown = []
    next_t = times[0]
    for t in times:
        if t >= next_t - 1e-6:
            shown.append(t)
            next_t = t + every
    if shown[-1] != times[-1]:
        shown.append(times[-1])
    rows_at = defaultdict(list)
    wanted = set(shown)
    for r in cable:
        t = float(r["t"])
        if t in wanted:
            rows_at[t].append(r)
    fig, ax = plt.subplots(figsize=(9, 5))
    for t in shown:
        nodes = sorted(rows_at[t], key=lambda r: int(r["node"]))
        ax.plot(column(nodes, "x"), column(nodes, "z"), marker=".", markersize=3,
                label="t = %g s" % t)
    ax.invert_yaxis()  # NED: z down, so depth grows downwards on the page
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z (depth) [m]")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    save(fig, outdir, "cable_shape.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="CSV directory written by sim_node --csv")
    parser.add_argument("outdir", nargs="?", help="where the PNG files go (default: DIR)")
    parser.add_argument("--tow", default="tow_vehicle", help="towing body (default tow_vehicle)")
    parser.add_argument("--fish", default="towfish", help="towed body (default towfish)")
    parser.add_argument("--every", type=float, default=15.0,
                        help="time between cable snapshots [s] (default 15)")
    args = parser.parse_args()
    if args.every <= 0:
        sys.exit("plot_paper: --every must be > 0")
    outdir = args.outdir or args.dir
    os.makedirs(outdir, exist_ok=True)
    run = os.path.basename(os.path.normpath(args.dir))

    bodies = by_name(read_rows(os.path.join(args.dir, "bodies.csv")), "body")
    forces = by_name(read_rows(os.path.join(args.dir, "forces.csv")), "body")
    cable = read_rows(os.path.join(args.dir, "cable.csv"))
    names = list(bodies.keys())
    tow = pick_body(names, args.tow, 0, "towing body")
    fish = pick_body(names, args.fish, -1, "towfish")
    series = [(name, bodies[name]) for name in dict.fromkeys([tow, fish])]

    plot_cable_shape(outdir, cable, args.every, "%s: cable shape every %g s" % (run, args.every))
    plot_components(outdir, "linear_velocity.png", "%s: linear velocity, body frame" % run,
                    series, [("u", "u [m/s]", 1.0), ("v", "v [m/s]", 1.0), ("w", "w [m/s]", 1.0)])
    plot_components(outdir, "angular_velocity.png", "%s: angular velocity, body frame" % run,
                    series, [("p", "p [deg/s]", DEG), ("q", "q [deg/s]", DEG),
                             ("r", "r [deg/s]", DEG)])
    plot_components(outdir, "euler_angles.png", "%s: Euler angles (ZYX)" % run, series,
                    [("roll", "roll [deg]", DEG), ("pitch", "pitch [deg]", DEG),
                     ("yaw", "yaw [deg]", DEG)])
    for name, _ in series:
        if name not in forces:
            continue
        plot_components(outdir, "force_%s.png" % name,
                        "%s: cable force on %s, body frame" % (run, name), [(name, forces[name])],
                        [("fx", "fx [N]", 1.0), ("fy", "fy [N]", 1.0), ("fz", "fz [N]", 1.0),
                         ("mx", "mx [N m]", 1.0), ("my", "my [N m]", 1.0),
                         ("mz", "mz [N m]", 1.0)])

    # trajectories from above: NED seen from above has x to the right and y downwards
    fig, ax = plt.subplots(figsize=(8, 6))
    for name, rows in series:
        ax.plot(column(rows, "x"), column(rows, "y"), label=name)
        ax.plot(column(rows[:1], "x"), column(rows[:1], "y"), "o", color="gray")
    ax.invert_yaxis()
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (north) [m]")
    ax.set_ylabel("y (east) [m]")
    ax.set_title("%s: trajectories seen from above (o: start)" % run)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best")
    save(fig, outdir, "trajectory.png")

    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(column(bodies[fish], "t"), column(bodies[fish], "z"))
    ax.invert_yaxis()
    ax.set_xlabel("t [s]")
    ax.set_ylabel("z (depth) [m]")
    ax.set_title("%s: depth of %s" % (run, fish))
    ax.grid(True, alpha=0.3)
    save(fig, outdir, "towfish_depth.png")


if __name__ == "__main__":
    main()
