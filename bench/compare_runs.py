#!/usr/bin/env python3
"""Difference of two sim_node runs (their --csv directories), in the measures of the
work-precision sweep (bench/work_precision.cc):
  track    max over the common output times of |p_body(t) - p_body_ref(t)| / L
  tension  RMS over time of T_top - T_top_ref (cable node 0), divided by the RMS of T_top_ref

  bench/compare_runs.py REF_DIR RUN_DIR [--length L] [--body towfish]

Used in docs/benchmarks.md ("The sea") to hold an approximation of the sea (a cheaper sum)
against the exact one, next to the discretization error the sweep shows."""
import argparse
import csv
import math
import sys


def body_track(path, body):
    track = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["body"] == body:
                track[row["t"]] = (float(row["x"]), float(row["y"]), float(row["z"]))
    return track


def top_tension(path):
    tension = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["node"] == "0":
                tension[row["t"]] = float(row["tension"])
    return tension


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ref")
    ap.add_argument("run")
    ap.add_argument("--length", type=float, default=200.0, help="cable length L [m]")
    ap.add_argument("--body", default="towfish")
    a = ap.parse_args()
    p_ref, p_run = (body_track(f"{d}/bodies.csv", a.body) for d in (a.ref, a.run))
    t_ref, t_run = (top_tension(f"{d}/cable.csv") for d in (a.ref, a.run))
    times = [t for t in p_ref if t in p_run]
    ttimes = [t for t in t_ref if t in t_run]
    if not times or not ttimes:
        sys.exit(f"compare_runs: no common output times in {a.ref} and {a.run}")
    track = max(math.dist(p_ref[t], p_run[t]) for t in times) / a.length
    num = math.fsum((t_run[t] - t_ref[t]) ** 2 for t in ttimes)
    den = math.fsum(t_ref[t] ** 2 for t in ttimes)
    print(f"{a.body} track {track:.3e} of L, top tension {math.sqrt(num / den):.3e} (RMS "
          f"relative), {len(times)} output times")


if __name__ == "__main__":
    main()
