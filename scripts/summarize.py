#!/usr/bin/env python3
"""Prints a short summary of a sim_node CSV run directory (standard library only).

    python3 scripts/summarize.py out/steady_tow [--towfish NAME]

Reads bodies.csv, cable.csv and forces.csv (docs/contract.md §5) and, when present, summary.txt (the
stdout of sim_node, for its real-time factor). Reports at the last written time:
  - the towfish position (body named "towfish", else --towfish, else the last body),
  - the tow point (cable node 0), and the towfish's layback (horizontal distance behind the
    tow point) and depth below it (NED: z down),
  - the top tension: the magnitude of the force the cable exerts at its start (the tow body's
    cable force, or the "cable.start" support row), and the axial force at node 0,
  - the real-time factor.
"""

import argparse
import csv
import math
import os
import re
import sys


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def last_time(rows):
    return max(float(r["t"]) for r in rows)


def at_time(rows, t):
    return [r for r in rows if abs(float(r["t"]) - t) <= 1e-9 * max(1.0, abs(t))]


def vec(row, keys):
    return [float(row[k]) for k in keys]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="CSV directory written by sim_node --csv")
    parser.add_argument("--towfish", help="name of the towed body (default: towfish)")
    args = parser.parse_args()

    bodies = read_rows(os.path.join(args.dir, "bodies.csv"))
    cable = read_rows(os.path.join(args.dir, "cable.csv"))
    forces = read_rows(os.path.join(args.dir, "forces.csv"))
    if not cable:
        sys.exit("summarize: %s/cable.csv has no rows" % args.dir)

    t = last_time(cable)
    nodes = sorted(at_time(cable, t), key=lambda r: int(r["node"]))
    tow_point = vec(nodes[0], ("x", "y", "z"))
    print("summary of %s at t = %.6g s" % (args.dir, t))
    print("  tow point (cable node 0)   x %10.3f  y %8.3f  z %8.3f m" % tuple(tow_point))

    final_bodies = at_time(bodies, t)
    names = [r["body"] for r in final_bodies]
    fish_name = args.towfish or ("towfish" if "towfish" in names else (names[-1] if names else None))
    if fish_name is not None and fish_name in names:
        fish = vec(next(r for r in final_bodies if r["body"] == fish_name), ("x", "y", "z"))
        dx, dy, dz = (fish[i] - tow_point[i] for i in range(3))
        print("  %-26s x %10.3f  y %8.3f  z %8.3f m" % (fish_name + " position", *fish))
        print("  layback %.3f m, depth below the tow point %.3f m" % (math.hypot(dx, dy), dz))
    else:
        print("  no towed body in bodies.csv")

    # top tension: the cable force at the start support, whichever row carries it
    final_forces = at_time(forces, t)
    start_row = next((r for r in final_forces if r["body"] == "cable.start"), None)
    if start_row is None and final_bodies:
        # the body closest to the tow point carries the start joint
        def distance(r):
            return math.dist(vec(r, ("x", "y", "z")), tow_point)
        tow_body = min(final_bodies, key=distance)["body"]
        start_row = next((r for r in final_forces if r["body"] == tow_body), None)
    top = math.hypot(*vec(start_row, ("fx", "fy", "fz"))) if start_row else float("nan")
    print("  top tension %.1f N (cable force at the tow point), node-0 axial force %.1f N"
          % (top, float(nodes[0]["tension"])))

    summary_path = os.path.join(args.dir, "summary.txt")
    rtf = None
    if os.path.exists(summary_path):
        with open(summary_path) as f:
            match = re.search(r"\(RTF ([0-9.eE+-]+|inf)\)", f.read())
        rtf = match.group(1) if match else None
    if rtf is not None:
        print("  real-time factor %sx (simulated time / wall time, whole run)" % rtf)
    else:
        status = read_rows(os.path.join(args.dir, "status.csv"))
        stepped = [r for r in status if int(r["step"]) > 0]
        if len(status) >= 2 and stepped:
            h = (float(status[1]["t"]) - float(status[0]["t"])) / int(status[1]["step"])
            mean_wall = sum(float(r["wall_us"]) for r in stepped) / len(stepped) * 1e-6
            print("  real-time factor ~%.0fx (step time only, sampled steps)"
                  % (h / mean_wall if mean_wall > 0 else float("inf")))


if __name__ == "__main__":
    main()
