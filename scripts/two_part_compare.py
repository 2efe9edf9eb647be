#!/usr/bin/env python3
"""What the depressor buys: the single-part and the two-part tow in the same sea, side by side.

    python3 scripts/two_part_compare.py [--sim-node PATH] [--out DIR] [--duration S]
                                        [--from S] [--dpi N]

Runs sim_node offline on config/scenes/two_part_tow_single.yaml (the towing vehicle, 475 m of
armoured cable straight to the towfish) and config/scenes/two_part_tow.yaml (the same vehicle
and sea, 400 m of the cable to a 500 kg depressor, a 75 m near-neutral tether to the towfish),
writing their CSV files to OUT/single_part and OUT/two_part (default OUT: out/two_part). From
--from seconds on (default 200: the start-up and the waves' ramp left out) it takes the
wave-frequency heave (height above the 30 s centred moving average of the depth, m, up
positive: the slow drift of the mean depth as the tow settles in the waves left out) and pitch
(deg, the same way) of the towing vehicle and of the towfish, prints their standard deviations
and the ratios towfish / vehicle (how much of the vehicle's motion reaches the towfish) and
two-part / single-part (what the depressor takes out), and draws both time series side by side
into OUT/two_part_compare.png (and .svg). sim_node's own output goes to OUT/<run>.log.

Needs python3 with matplotlib and numpy (Debian: python3-matplotlib python3-numpy); draws
off-screen. sim_node: --sim-node, else build/sim_node/app/sim_node of this checkout, else
sim_node on PATH. Exits non-zero if a run fails.
"""

import argparse
import csv
import math
import os
import shutil
import subprocess
import sys

try:
    import matplotlib
    import numpy as np
except ImportError:
    sys.exit("two_part_compare: needs matplotlib and numpy (Debian: apt-get install "
             "python3-matplotlib python3-numpy, then run it with /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNS = (("single_part", "two_part_tow_single.yaml", "single-part tow"),
        ("two_part", "two_part_tow.yaml", "two-part tow (depressor)"))


def find_sim_node(given):
    if given:
        return given
    local = os.path.join(ROOT, "build", "sim_node", "app", "sim_node")
    if os.access(local, os.X_OK):
        return local
    found = shutil.which("sim_node")
    if not found:
        sys.exit("two_part_compare: no sim_node (build it with ./run.sh or give --sim-node)")
    return found


def body_series(csv_dir, body, t_from):
    """t, z (NED, m) and pitch (deg) of `body` from bodies.csv, from t_from on"""
    t, z, pitch = [], [], []
    with open(os.path.join(csv_dir, "bodies.csv"), newline="") as fh:
        for row in csv.DictReader(fh):
            if row["body"] != body or float(row["t"]) < t_from:
                continue
            t.append(float(row["t"]))
            z.append(float(row["z"]))
            pitch.append(math.degrees(float(row["pitch"])))
    if not t:
        sys.exit(f"two_part_compare: no rows of {body} after {t_from} s in {csv_dir}")
    return np.array(t), np.array(z), np.array(pitch)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sim-node", help="the sim_node to run")
    ap.add_argument("--out", default=os.path.join("out", "two_part"), help="output folder")
    ap.add_argument("--duration", type=float, default=600.0, help="simulated seconds per run")
    ap.add_argument("--from", dest="t_from", type=float, default=200.0,
                    help="statistics from this time on [s]")
    ap.add_argument("--dpi", type=int, default=110)
    args = ap.parse_args()
    if not args.t_from < args.duration:
        sys.exit("two_part_compare: --from must be below --duration")
    sim_node = find_sim_node(args.sim_node)
    series = {}
    for key, scene, _ in RUNS:
        out = os.path.join(args.out, key)
        cmd = [sim_node, "--scene", os.path.join(ROOT, "config", "scenes", scene), "--mode",
               "offline", "--duration", str(args.duration), "--csv", out]
        print("[two_part_compare] " + " ".join(cmd), file=sys.stderr)
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, key + ".log"), "w") as log:
            done = subprocess.run(cmd, stdout=log, stderr=log)
        if done.returncode != 0:
            sys.exit(f"two_part_compare: sim_node failed on {scene} (exit {done.returncode})")
        series[key] = {b: body_series(out, b, args.t_from) for b in ("tow_vehicle", "towfish")}

    def wave_part(t, x):
        # x less its 30 s centred moving average (edges: the window shrinks)
        dt = float(np.median(np.diff(t)))
        half = max(1, int(round(15.0 / dt)))
        c = np.concatenate(([0.0], np.cumsum(x)))
        i = np.arange(len(x))
        lo, hi = np.maximum(0, i - half), np.minimum(len(x), i + half + 1)
        return x - (c[hi] - c[lo]) / (hi - lo)

    def std(x):
        return float(np.std(x))

    for key in series:
        for body in series[key]:
            t_s, z, pitch = series[key][body]
            series[key][body] = (t_s, -wave_part(t_s, z), wave_part(t_s, pitch))

    print(f"wave-frequency heave and pitch (30 s moving average removed), standard deviations "
          f"from {args.t_from:g} s to {args.duration:g} s:")
    print(f"{'':26s} {'vehicle heave':>13s} {'towfish heave':>13s} {'ratio':>7s} "
          f"{'vehicle pitch':>13s} {'towfish pitch':>13s} {'ratio':>7s}")
    ratios = {}
    for key, _, label in RUNS:
        v, f = series[key]["tow_vehicle"], series[key]["towfish"]
        hv, hf, pv, pf = std(v[1]), std(f[1]), std(v[2]), std(f[2])
        ratios[key] = (hf / hv, pf / pv, hf, pf)
        print(f"{label:26s} {hv:11.3f} m {hf:11.3f} m {hf / hv:7.3f} "
              f"{pv:9.3f} deg {pf:9.3f} deg {pf / pv:7.3f}")
    s, t = ratios["single_part"], ratios["two_part"]
    print(f"the depressor: towfish heave std x {t[2] / s[2]:.3f}, pitch std x {t[3] / s[3]:.3f} "
          "(two-part / single-part)")

    fig, axes = plt.subplots(2, 2, figsize=(12, 6.5), sharex=True)
    for col, (key, _, label) in enumerate(RUNS):
        for row, (index, unit, what) in enumerate(((1, "m", "heave"), (2, "deg", "pitch"))):
            ax = axes[row][col]
            for body, color in (("tow_vehicle", "tab:blue"), ("towfish", "tab:orange")):
                t_s, *values = series[key][body]
                y = values[index - 1]
                ax.plot(t_s, y, color=color, lw=0.8, label=f"{body} (std {std(y):.3f} {unit})")
            ax.set_title(f"{label}: {what}")
            ax.set_ylabel(f"{what}, wave frequency [{unit}]")
            ax.grid(alpha=0.3)
            ax.legend(loc="upper right", fontsize=8)
            if row == 1:
                ax.set_xlabel("t [s]")
    fig.suptitle("JONSWAP Hs 2 m, Tp 8 s: the towfish's heave and pitch against the vehicle's")
    fig.tight_layout()
    for ext in ("png", "svg"):
        path = os.path.join(args.out, f"two_part_compare.{ext}")
        fig.savefig(path, dpi=args.dpi)
        print(f"[two_part_compare] wrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
