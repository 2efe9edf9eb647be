#!/usr/bin/env python3
"""The heave of the towfish against the tow vehicle's in waves, and the spectra of both.

    python3 scripts/plot_waves.py DIR [OUTDIR] [--tow NAME] [--fish NAME] [--from S]
                                  [--segment S] [--dpi N]

DIR holds the CSV files of `sim_node --csv DIR` (e.g. config/scenes/case3_waves.yaml;
docs/command_line.md "Output files"); the PNG files go to OUTDIR (default DIR). Needs python3
with matplotlib and numpy (Debian: python3-matplotlib python3-numpy; run it with
/usr/bin/python3 where the python3 on PATH lacks them); draws off-screen.

  heave.png           heave of both bodies over time: their height above their mean depth
                      after --from [m, up positive], with the wave elevation when the run has it
  heave_spectrum.png  one-sided spectral density of each heave [m^2 s/rad] against the angular
                      frequency, by Welch's method (Hann windows of --segment seconds, half
                      overlapping, periodograms averaged), and the wave elevation's when present

The wave elevation is read, when present, from a column `wave_elevation` (eta at the body, m,
positive up) of `environment.csv` (rows t,body,...) or of `bodies.csv`; without it only the
heaves are drawn. It prints per body: the heave's significant height 4 std and the peak period
of its spectrum.
"""

import argparse
import csv
import math
import os
import sys

try:
    import matplotlib
    import numpy as np
except ImportError:
    sys.exit("plot_waves: needs matplotlib and numpy (Debian: apt-get install python3-matplotlib "
             "python3-numpy, then run it with the system's python3, /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

sys.dont_write_bytecode = True  # no scripts/__pycache__ from the import below
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_cases as pc  # noqa: E402

COLORS = {"tow": "tab:blue", "fish": "tab:orange", "eta": "tab:gray"}


def wave_elevation(path, body):
    """(t, eta) at `body` from environment.csv or bodies.csv, or None without the column"""
    for name in ("environment.csv", "bodies.csv"):
        f = os.path.join(path, name)
        if not os.path.isfile(f):
            continue
        with open(f, newline="") as fh:
            reader = csv.DictReader(fh)
            if "wave_elevation" not in (reader.fieldnames or []):
                continue
            rows = [(float(r["t"]), float(r["wave_elevation"])) for r in reader
                    if r.get("body", body) == body]
            if rows:
                return np.array([r[0] for r in rows]), np.array([r[1] for r in rows])
    return None


def welch(x, dt, segment):
    """one-sided density [unit^2 s/rad] at w = 2 pi k / (m dt): Hann windows of m samples,
    half overlapping, periodograms averaged (sum S dw ~ the variance)"""
    m = min(segment, len(x))
    m -= m % 2
    w = np.hanning(m + 1)[:-1]  # periodic Hann
    u = np.sum(w * w)
    x = x - np.mean(x)
    acc = np.zeros(m // 2 + 1)
    count = 0
    for start in range(0, len(x) - m + 1, m // 2):
        spec = np.fft.rfft(w * x[start:start + m])
        acc += np.abs(spec) ** 2
        count += 1
    density = acc / count * dt / (2.0 * math.pi * u)
    density[1:-1] *= 2.0  # one-sided: the negative frequencies folded in
    return 2.0 * math.pi * np.fft.rfftfreq(m, dt), density, count


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dir")
    ap.add_argument("outdir", nargs="?")
    ap.add_argument("--tow", default=None, help="the tow vehicle's name (default tow_vehicle)")
    ap.add_argument("--fish", default=None, help="the towfish's name (default towfish)")
    ap.add_argument("--from", dest="t_from", type=float, default=60.0,
                    help="start of the analysed window [s] (default 60: after the ramp and the "
                         "start-up transient)")
    ap.add_argument("--segment", type=float, default=102.4,
                    help="Welch segment length [s] (default 102.4)")
    ap.add_argument("--dpi", type=int, default=120)
    a = ap.parse_args()
    run = pc.Run(a.dir)
    tow = a.tow or run.tow
    fish = a.fish or run.fish
    for name in (tow, fish):
        if name not in run.bodies:
            sys.exit("plot_waves: error: %s/bodies.csv has no body %s (bodies: %s)" %
                     (a.dir, name, ", ".join(run.bodies)))
    outdir = a.outdir or a.dir
    os.makedirs(outdir, exist_ok=True)

    series = []  # (label, key, t, heave)
    for key, name in (("tow", tow), ("fish", fish)):
        t = np.array(run.bodies[name]["t"])
        z = np.array(run.bodies[name]["z"])
        sel = t >= a.t_from
        if np.count_nonzero(sel) < 16:
            sys.exit("plot_waves: error: %s: fewer than 16 samples after --from %g s" %
                     (name, a.t_from))
        # heave: up positive, about the mean depth of the window
        series.append(("%s heave" % name, key, t[sel], -(z[sel] - np.mean(z[sel]))))
    eta = wave_elevation(a.dir, tow)
    if eta is not None:
        sel = eta[0] >= a.t_from
        series.append(("wave elevation at %s" % tow, "eta", eta[0][sel], eta[1][sel]))

    fig, ax = plt.subplots(figsize=(10, 4))
    for label, key, t, h in series:
        ax.plot(t, h, color=COLORS[key], lw=0.8, label=label)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("heave, elevation [m] (up)")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right")
    ax.set_title("%s: heave of %s and %s" % (run.name, tow, fish))
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "heave.png"), dpi=a.dpi)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 4.5))
    for label, key, t, h in series:
        dt = float(np.median(np.diff(t)))
        w, s, count = welch(h, dt, int(round(a.segment / dt)))
        ax.semilogy(w[1:], np.maximum(s[1:], 1e-12), color=COLORS[key], lw=1.0,
                    label="%s (%d segments)" % (label, count))
        k = 1 + int(np.argmax(s[1:]))
        print("%-32s 4 std = %.3f m, spectral peak at %.3f rad/s (period %.2f s)" %
              (label, 4.0 * float(np.std(h)), w[k], 2.0 * math.pi / w[k]))
    ax.set_xlim(0.0, 3.0)
    ax.set_xlabel("angular frequency w [rad/s]")
    ax.set_ylabel("S(w) [m^2 s/rad]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="upper right")
    ax.set_title("%s: heave spectra from t = %g s" % (run.name, a.t_from))
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "heave_spectrum.png"), dpi=a.dpi)
    plt.close(fig)
    print("plot_waves: wrote heave.png and heave_spectrum.png to %s" % outdir)


if __name__ == "__main__":
    main()
