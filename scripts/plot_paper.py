#!/usr/bin/env python3
"""Draws the figures of Park & Kim (Case 1: Figs. 8-13, Case 2: Figs. 14-20) from a sim_node run.

    python3 scripts/plot_paper.py DIR [OUTDIR] [--tow NAME] [--fish NAME] [--every S]
                                  [--prefix P] [--dpi N] [--case1 C1DIR]

DIR holds the CSV files of `sim_node --csv DIR` (docs/command_line.md, "Output files"); the PNG
files go to OUTDIR (default DIR), each name preceded by --prefix (e.g. case2_). Needs python3 and
matplotlib (Debian: python3-matplotlib; run it with /usr/bin/python3 where the python3 on PATH
lacks it); draws off-screen. The case is recognised from the data (Case 2: the towing vehicle
turns by more than 90 deg; scripts/paper_cases.py, which also measures the numbers).

  cable_shape.png         cable in the x-z plane every --every seconds, depth down (Fig. 8)
  linear_velocity.png     u, v, w of both bodies, body frame (Figs. 9, 15)
  angular_velocity.png    p, q, r of both bodies [deg/s] (Figs. 10, 16)
  euler_angles.png        roll, pitch, yaw of both bodies [deg] (Figs. 11, 17), drawn continuous:
                          through pitch 90 deg the equivalent angles are kept (pitch may exceed
                          90 deg) and yaw is unwrapped (a U-turn reads 0 -> 188 deg)
  interaction_forces.png  force and moment the cable exerts on each body, body frame, one column
                          per body (Figs. 12-13, 18-19)
  trajectory.png          both paths seen from above, x north to the right, y east down (Fig. 14);
                          in a turn a second panel zooms on it with the fitted turning circles
  towfish_depth.png       the towfish's depth (Fig. 20); with --case1, Case 1's depth for reference

--combined (for docs/figures): motion.png holds Figs. 9-11 (15-17) as a 3 x 3 grid instead of the
three files, and only the figures of the case are drawn (Case 1: cable shape, motion, forces;
Case 2: motion, forces, trajectory, depth).

In Case 2 every time plot marks the rudder command and shades the towing vehicle's turn (rudder
at 20 deg until its heading has changed by 170 deg).
"""

import argparse
import math
import os
import sys

try:
    import matplotlib
except ImportError:
    sys.exit("plot_paper: needs matplotlib (Debian: apt-get install python3-matplotlib, then run "
             "it with the system's python3, /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

sys.dont_write_bytecode = True  # no scripts/__pycache__ from the import below
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_cases as pc  # noqa: E402

DEG = 180.0 / math.pi
COLORS = {"tow": "tab:blue", "fish": "tab:orange"}


class Plotter:
    def __init__(self, run, outdir, prefix, dpi, tow, fish):
        self.run = run
        self.outdir = outdir
        self.prefix = prefix
        self.dpi = dpi
        self.tow = tow
        self.fish = fish
        self.tag = "Case %d" % run.case
        self.turn = None
        if run.case == 2:
            tv = run.bodies[tow]
            t_cmd = pc.turn_command_time(tv)
            t170 = pc.time_of_heading(tv, t_cmd, 170.0)
            self.turn = (t_cmd, t170 or tv["t"][-1])

    def fig_no(self, case1, case2):
        return "Fig. %s" % (case1 if self.run.case == 1 else case2)

    def save(self, fig, name):
        path = os.path.join(self.outdir, self.prefix + name)
        fig.savefig(path, dpi=self.dpi)
        plt.close(fig)
        print("plot_paper: wrote %s" % path)

    def mark_turn(self, ax, label=False):
        if self.turn is None:
            return
        ax.axvspan(self.turn[0], self.turn[1], color="0.88", zorder=0,
                   label="rudder 20 deg" if label else None)

    def series(self):
        out = [(self.tow, self.run.bodies[self.tow], COLORS["tow"])]
        if self.fish != self.tow:
            out.append((self.fish, self.run.bodies[self.fish], COLORS["fish"]))
        return out

    def components(self, title, panels, source=None):
        """one panel per (column, label, scale, minimum span); a line per body"""
        fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(8, 1.9 * len(panels) + 0.6),
                                 constrained_layout=True)
        for k, (ax, (key, label, scale, span)) in enumerate(zip(axes, panels)):
            self.mark_turn(ax, label=(k == 0))
            for body, cols, color in (source or self.series()):
                ax.plot(cols["t"], [v * scale for v in cols[key]], color=color, lw=1.3,
                        label=body)
            min_span(ax, span)
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
        axes[0].set_title(title)
        axes[0].legend(loc="best", fontsize="small")
        axes[-1].set_xlabel("t [s]")
        return fig, axes

    def cable_shape(self, every):
        run = self.run
        times = run.cable_times
        shown = []
        next_t = times[0]
        for t in times:
            if t >= next_t - 1e-6:
                shown.append(t)
                next_t = t + every
        if shown[-1] != times[-1]:
            shown.append(times[-1])
        fig, ax = plt.subplots(figsize=(9, 4.6), constrained_layout=True)
        cmap = plt.get_cmap("viridis")
        for k, t in enumerate(shown):
            nodes = run.cable[t]
            c = cmap(k / max(1, len(shown) - 1))
            ax.plot([n[1] for n in nodes], [n[3] for n in nodes], color=c, lw=1.4, marker=".",
                    markersize=3, label="%g s" % t)
            ax.plot(nodes[0][1], nodes[0][3], "^", color=c, markersize=6)
            ax.plot(nodes[-1][1], nodes[-1][3], "o", color=c, markersize=5)
        ax.invert_yaxis()  # NED: z down, so depth grows downwards on the page
        ax.set_xlabel("x (north) [m]")
        ax.set_ylabel("z (depth) [m]")
        ax.set_title("%s (%s): cable in the x-z plane every %g s  (^ towing point, o towfish bow)"
                     % (self.fig_no(8, "-"), self.tag, every))
        ax.grid(True, alpha=0.3)
        ax.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize="small", title="t")
        self.save(fig, "cable_shape.png")

    def velocities(self):
        fig, axes = self.components(
            "%s (%s): linear velocity, body frame" % (self.fig_no(9, 15), self.tag),
            [("u", "u [m/s]", 1.0, 0.1), ("v", "v [m/s]", 1.0, 0.1), ("w", "w [m/s]", 1.0, 0.1)])
        ax = axes[0]
        ax.axhspan(pc.TARGET_U * (1 - pc.U_BAND), pc.TARGET_U * (1 + pc.U_BAND), color="green",
                   alpha=0.12, zorder=0, label="6 m/s +-3 %")
        ax.legend(loc="best", fontsize="small")
        self.save(fig, "linear_velocity.png")
        fig, _ = self.components(
            "%s (%s): angular velocity, body frame" % (self.fig_no(10, 16), self.tag),
            [("p", "p [deg/s]", DEG, 0.5), ("q", "q [deg/s]", DEG, 0.5),
             ("r", "r [deg/s]", DEG, 0.5)])
        self.save(fig, "angular_velocity.png")
        fig, _ = self.components(
            "%s (%s): Euler angles (ZYX, drawn continuous)" % (self.fig_no(11, 17), self.tag),
            [("roll", "roll [deg]", DEG, 1.0), ("pitch", "pitch [deg]", DEG, 1.0),
             ("yaw", "yaw [deg]", DEG, 1.0)])
        self.save(fig, "euler_angles.png")

    def motion(self):
        """Figs. 9-11 (15-17) in one: columns linear velocity, angular velocity, Euler angles"""
        cols_spec = [
            (self.fig_no(9, 15) + ": linear velocity",
             [("u", "u [m/s]", 1.0, 0.1), ("v", "v [m/s]", 1.0, 0.1), ("w", "w [m/s]", 1.0, 0.1)]),
            (self.fig_no(10, 16) + ": angular velocity",
             [("p", "p [deg/s]", DEG, 0.5), ("q", "q [deg/s]", DEG, 0.5),
              ("r", "r [deg/s]", DEG, 0.5)]),
            (self.fig_no(11, 17) + ": Euler angles",
             [("roll", "roll [deg]", DEG, 1.0), ("pitch", "pitch [deg]", DEG, 1.0),
              ("yaw", "yaw [deg]", DEG, 1.0)])]
        fig, axes = plt.subplots(3, 3, sharex=True, figsize=(13, 7.6), constrained_layout=True)
        for c, (title, panels) in enumerate(cols_spec):
            for r, (key, label, scale, span) in enumerate(panels):
                ax = axes[r][c]
                self.mark_turn(ax, label=(r == 0 and c == 0))
                if key == "u":
                    ax.axhspan(pc.TARGET_U * (1 - pc.U_BAND), pc.TARGET_U * (1 + pc.U_BAND),
                               color="green", alpha=0.12, zorder=0, label="6 m/s +-3 %")
                for body, data, color in self.series():
                    ax.plot(data["t"], [v * scale for v in data[key]], color=color, lw=1.2,
                            label=body)
                min_span(ax, span)
                ax.set_ylabel(label)
                ax.grid(True, alpha=0.3)
            axes[0][c].set_title(title)
            axes[-1][c].set_xlabel("t [s]")
        axes[0][0].legend(loc="best", fontsize="small")
        fig.suptitle("%s: motion of both bodies, body frame; Euler angles ZYX drawn continuous"
                     % self.tag)
        self.save(fig, "motion.png")

    def forces(self):
        run = self.run
        keys = [("fx", "fx [N]", 10.0), ("fy", "fy [N]", 10.0), ("fz", "fz [N]", 10.0),
                ("mx", "mx [N m]", 10.0), ("my", "my [N m]", 10.0), ("mz", "mz [N m]", 10.0)]
        columns = [(self.tow, COLORS["tow"], self.fig_no(12, 18)),
                   (self.fish, COLORS["fish"], self.fig_no(13, 19))]
        if self.fish == self.tow:
            columns = columns[1:]
        fig, axes = plt.subplots(len(keys), len(columns), sharex=True, squeeze=False,
                                 figsize=(5.5 * len(columns), 10.5), constrained_layout=True)
        for col, (body, color, fig_no) in enumerate(columns):
            f = run.forces.get(body)
            for row, (key, label, span) in enumerate(keys):
                ax = axes[row][col]
                self.mark_turn(ax)
                if f is not None:
                    ax.plot(f["t"], f[key], color=color, lw=1.1)
                min_span(ax, span)
                ax.set_ylabel(label)
                ax.grid(True, alpha=0.3)
            axes[0][col].set_title("%s: cable force on the %s" % (fig_no, body))
            axes[-1][col].set_xlabel("t [s]")
        fig.suptitle("%s: interaction force, body frame (moment about the body origin)" % self.tag)
        self.save(fig, "interaction_forces.png")

    def trajectory(self):
        run = self.run
        series = self.series()
        zoom = self.turn is not None
        if zoom:
            fig, axes = plt.subplots(2, 1, figsize=(11, 6.4), constrained_layout=True,
                                     gridspec_kw={"height_ratios": [1, 1.25]})
        else:
            fig, ax = plt.subplots(figsize=(9, 3.5), constrained_layout=True)
            axes = [ax]
        ax = axes[0]
        for body, cols, color in series:
            ax.plot(cols["x"], cols["y"], color=color, label=body)
            ax.plot(cols["x"][0], cols["y"][0], "o", color="gray")
        ax.set_aspect("equal", adjustable="datalim")
        ax.invert_yaxis()
        ax.set_xlabel("x (north) [m]")
        ax.set_ylabel("y (east) [m]")
        ax.set_title("%s (%s): trajectories from above (o: start)" % (self.fig_no("-", 14),
                                                                       self.tag))
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small")
        if not zoom:
            self.save(fig, "trajectory.png")
            return
        tv = run.bodies[self.tow]
        tf = run.bodies[self.fish]
        t_cmd = self.turn[0]
        t_f = pc.time_of_heading(tf, t_cmd, 170.0) or tv["t"][-1]
        t0, t1 = t_cmd - 10.0, t_f + 10.0
        ax = axes[1]
        xs, ys = [], []
        for body, cols, color in series:
            sel = [i for i, t in enumerate(cols["t"]) if t0 <= t <= t1]
            x = [cols["x"][i] for i in sel]
            y = [cols["y"][i] for i in sel]
            xs += x
            ys += y
            ax.plot(x, y, color=color, lw=1.6, label=body)
            fit = pc.turn_fit(cols, t_cmd)
            if fit:
                circle = plt.Circle((fit["xc"], fit["yc"]), fit["R"], fill=False, ls="--",
                                    color=color, lw=0.9)
                ax.add_patch(circle)
                ax.plot(fit["xc"], fit["yc"], "+", color=color)
                # the towing vehicle's label inside its circle, the towfish's to its left
                inside = body == self.tow
                ax.annotate("R = %.1f m\n(%.0f-%.0f s)" % (fit["R"], fit["t0"], fit["t1"]),
                            (fit["xc"] if inside else fit["xc"] - fit["R"], fit["yc"]),
                            color=color, ha="center" if inside else "right", va="center",
                            textcoords="offset points", xytext=(0, -16) if inside else (-4, 0),
                            fontsize="small")
        # the straight line between the bodies every 10 s (where the cable ends are)
        tt = tv["t"]
        for i, t in enumerate(tt):
            if t0 <= t <= t1 and abs(t / 10.0 - round(t / 10.0)) < 1e-6:
                ax.plot([tv["x"][i], tf["x"][i]], [tv["y"][i], tf["y"][i]], color="0.75",
                        lw=0.6, zorder=0)
                for cols, color, dy in ((tv, COLORS["tow"], 9), (tf, COLORS["fish"], -12)):
                    ax.plot(cols["x"][i], cols["y"][i], ".", color=color)
                    ax.annotate("%g" % t, (cols["x"][i], cols["y"][i]), fontsize=7, color=color,
                                textcoords="offset points", xytext=(-6, dy))
        pad = 8.0
        ax.set_xlim(min(xs) - pad, max(xs) + pad)
        ax.set_ylim(max(ys) + pad, min(ys) - pad)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("x (north) [m]")
        ax.set_ylabel("y (east) [m]")
        ax.set_title("the turns, %g-%g s: dots every 10 s (label: t [s]), grey: towing vehicle to "
                     "towfish at the same time,\ndashed: circles fitted over 20-160 deg of "
                     "heading change" % (t0, t1), fontsize="medium")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="lower left", fontsize="small")
        self.save(fig, "trajectory.png")

    def depth(self, ref1):
        tf = self.run.bodies[self.fish]
        fig, ax = plt.subplots(figsize=(8, 3.8), constrained_layout=True)
        self.mark_turn(ax, label=True)
        if ref1 is not None:
            rf = ref1.bodies[ref1.fish]
            ax.plot(rf["t"], rf["z"], color="0.5", ls="--", lw=1.0,
                    label="Case 1 (%s), no turn" % ref1.name)
        ax.plot(tf["t"], tf["z"], color=COLORS["fish"], lw=1.5, label=self.fish)
        ax.invert_yaxis()
        ax.set_xlabel("t [s]")
        ax.set_ylabel("z (depth) [m]")
        ax.set_title("%s (%s): depth of the %s" % (self.fig_no("-", 20), self.tag, self.fish))
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small")
        if self.turn is not None:
            # zoom on the turn: the depth range from the rudder command on (the rise from the
            # start at 203.7 m, before it, leaves the plot at the bottom left)
            t_from = self.turn[0]
            sel = [z for t, z in zip(tf["t"], tf["z"]) if t >= t_from]
            if ref1 is not None:
                rf = ref1.bodies[ref1.fish]
                sel += [z for t, z in zip(rf["t"], rf["z"]) if t >= t_from]
            t5 = pc.time_of_heading(tf, t_from, 5.0)
            t170 = pc.time_of_heading(tf, t_from, 170.0)
            if t5 is not None and t170 is not None:
                ax.axvspan(t5, t170, color=COLORS["fish"], alpha=0.15, zorder=0,
                           label="%s turning (heading 5-170 deg)" % self.fish)
                ax.legend(loc="best", fontsize="small")
            ax.set_xlim(t_from - 10.0, tf["t"][-1])
            ax.set_ylim(max(sel) + 1.5, min(sel) - 1.5)
            ax.set_title("%s (%s): depth of the %s from the turn on"
                         % (self.fig_no("-", 20), self.tag, self.fish))
        self.save(fig, "towfish_depth.png")


def min_span(ax, span):
    """keeps an axis from magnifying numerical noise: at least `span` of y range"""
    lo, hi = ax.get_ylim()
    if hi - lo < span:
        mid = 0.5 * (lo + hi)
        ax.set_ylim(mid - 0.5 * span, mid + 0.5 * span)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="CSV directory written by sim_node --csv")
    parser.add_argument("outdir", nargs="?", help="where the PNG files go (default: DIR)")
    parser.add_argument("--tow", default="tow_vehicle", help="towing body (default tow_vehicle)")
    parser.add_argument("--fish", default="towfish", help="towed body (default towfish)")
    parser.add_argument("--every", type=float, default=15.0,
                        help="time between cable snapshots [s] (default 15)")
    parser.add_argument("--prefix", default="", help="prefix of the PNG names (e.g. case1_)")
    parser.add_argument("--dpi", type=int, default=90, help="resolution (default 90)")
    parser.add_argument("--case1", help="a Case 1 run, drawn for reference in the depth figure")
    parser.add_argument("--combined", action="store_true",
                        help="Figs. 9-11 (15-17) in one motion.png instead of three files, and "
                             "only the figures the case has in the paper (for docs/figures)")
    args = parser.parse_args()
    if args.every <= 0:
        sys.exit("plot_paper: --every must be > 0")
    outdir = args.outdir or args.dir
    os.makedirs(outdir, exist_ok=True)

    run = pc.Run(args.dir)
    names = list(run.bodies)
    tow = args.tow if args.tow in names else run.tow
    fish = args.fish if args.fish in names else run.fish
    for wanted, got, what in ((args.tow, tow, "towing body"), (args.fish, fish, "towfish")):
        if wanted != got:
            print("plot_paper: no body named %s; using %s as the %s" % (wanted, got, what))
    ref1 = pc.Run(args.case1) if args.case1 else None

    p = Plotter(run, outdir, args.prefix, args.dpi, tow, fish)
    if args.combined:
        if run.case == 1:
            p.cable_shape(args.every)
        p.motion()
        p.forces()
        if run.case == 2:
            p.trajectory()
            p.depth(ref1)
        return
    p.cable_shape(args.every)
    p.velocities()
    p.forces()
    p.trajectory()
    p.depth(ref1)


if __name__ == "__main__":
    main()
