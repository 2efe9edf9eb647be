#!/usr/bin/env python3
"""Measures sim_node runs of Park & Kim's Case 1 and Case 2 against the paper's statements.

    python3 scripts/paper_cases.py DIR [DIR ...]              full report of each run
    python3 scripts/paper_cases.py --case1 C1DIR DIR ...      Case 2 depth also relative to Case 1
    python3 scripts/paper_cases.py --summary DIR              short table (run.sh)
    python3 scripts/paper_cases.py --compare REF DIR [DIR ...]  key numbers side by side and the
                                                              largest differences from REF
    python3 scripts/paper_cases.py --depth-control REF CTL    Case 2 towfish depth range from the
                                                              turn command on, without (REF) and
                                                              with (CTL) a depth controller

Standard library only. DIR holds the CSV files of `sim_node --csv DIR` (docs/command_line.md,
"Output files").
The case is recognised from the data: Case 2 when the towing vehicle's heading changes by more
than 90 deg. The towing body is tow_vehicle (else the first body), the towfish towfish (else
the last). docs/paper_cases.md explains every number; the definitions are:

  reach / settle     first time within the band / time after which it never leaves the band
  u band             6 m/s +- 3 % (the paper's steady surge), and +- 3 % of the run's final u
  all-DOF steady     every quantity of Figs. 9-10 near its final value: |du| <= 3 % u_final,
                     |dv|, |dw| <= 0.03 m/s, |dp|, |dq|, |dr| <= 0.2 deg/s (final = mean over
                     the last 5 s)
  cable straightness largest distance of a node from the chord (node 0 to the last node),
                     divided by the unstretched length (200 m)
  turning radius     least-squares circle (Kasa) through the body's track while its own heading
                     has turned between 20 and 160 deg from its heading at the rudder command
"""

import argparse
import csv
import math
import os
import sys
from collections import defaultdict

DEG = 180.0 / math.pi
TARGET_U = 6.0      # the paper's steady surge [m/s]
U_BAND = 0.03       # +-3 %
VW_BAND = 0.03      # m/s
PQR_BAND = 0.2      # deg/s
LAST_WINDOW = 5.0   # s, the "final" value is the mean over the run's last LAST_WINDOW seconds
FIT_FROM, FIT_TO = 20.0, 160.0   # deg of heading change: the turning part of a track


# ---------------------------------------------------------------------------------------------
# reading


class Run:
    """the CSV files of one run: per-body column lists, per-time cable nodes, per-body forces"""

    def __init__(self, path):
        self.path = path
        for name in ("bodies.csv", "forces.csv", "cable.csv"):
            if not os.path.isfile(os.path.join(path, name)):
                sys.exit("paper_cases: error: %s: no %s here (a directory written by "
                         "sim_node --csv DIR or towsim_export FILE --csv DIR)" % (path, name))
        self.name = os.path.basename(os.path.normpath(path))
        self.bodies = self._columns(os.path.join(path, "bodies.csv"))
        self.forces = self._columns(os.path.join(path, "forces.csv"))
        self.cable = defaultdict(list)  # t -> [(node, x, y, z, tension)] sorted by node
        with open(os.path.join(path, "cable.csv"), newline="") as f:
            for r in csv.DictReader(f):
                self.cable[round(float(r["t"]), 6)].append(
                    (int(r["node"]), float(r["x"]), float(r["y"]), float(r["z"]),
                     float(r["tension"])))
        for nodes in self.cable.values():
            nodes.sort()
        self.cable_times = sorted(self.cable)
        names = list(self.bodies)
        if not names:
            sys.exit("paper_cases: %s/bodies.csv has no bodies" % path)
        self.tow = "tow_vehicle" if "tow_vehicle" in names else names[0]
        self.fish = "towfish" if "towfish" in names else names[-1]
        for name in names:
            continuous_euler(self.bodies[name])
        self.case = 2 if max(abs(a) for a in heading_change(self.bodies[self.tow])) > 90 else 1

    @staticmethod
    def _columns(path):
        out = {}
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                cols = out.setdefault(r["body"], defaultdict(list))
                for k, v in r.items():
                    if k != "body":
                        cols[k].append(float(v))
        return out

    def top_tension(self):
        """(t, axial force at node 0, at the last node)"""
        ts = self.cable_times
        return (ts, [self.cable[t][0][4] for t in ts], [self.cable[t][-1][4] for t in ts])


def continuous_euler(cols):
    """Rewrites roll, pitch, yaw (ZYX, yaw in (-180, 180]) as continuous curves: through pitch
    +-90 deg the equivalent set (roll + pi, pi - pitch, yaw + pi) is taken where it is closer to
    the previous sample (pitch may then exceed 90 deg), and 2 pi jumps are removed."""
    roll, pitch, yaw = cols["roll"], cols["pitch"], cols["yaw"]
    for i in range(1, len(roll)):
        a = (roll[i], pitch[i], yaw[i])
        sign = 1.0 if pitch[i] >= 0 else -1.0
        b = (roll[i] + math.pi, sign * math.pi - pitch[i], yaw[i] + math.pi)
        prev = (roll[i - 1], pitch[i - 1], yaw[i - 1])

        def dist(c):
            return sum(abs(wrap(c[k] - prev[k])) for k in range(3))
        best = b if dist(b) < dist(a) else a
        roll[i] = prev[0] + wrap(best[0] - prev[0])
        pitch[i] = best[1] if abs(best[1] - prev[1]) <= math.pi else prev[1] + wrap(best[1] - prev[1])
        yaw[i] = prev[2] + wrap(best[2] - prev[2])


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def heading_change(cols):
    """heading change from the first sample [deg], continuous"""
    return [(y - cols["yaw"][0]) * DEG for y in cols["yaw"]]


# ---------------------------------------------------------------------------------------------
# measures


def first_reach(ts, ys, pred):
    for t, y in zip(ts, ys):
        if pred(y):
            return t
    return None


def settle_time(ts, ys, pred):
    """the first time after which pred holds to the end; None if it does not hold at the end"""
    last_bad = None
    for i, y in enumerate(ys):
        if not pred(y):
            last_bad = i
    if last_bad is None:
        return ts[0]
    if last_bad == len(ys) - 1:
        return None
    return ts[last_bad + 1]


def final_mean(ts, ys, window=LAST_WINDOW):
    sel = [y for t, y in zip(ts, ys) if t >= ts[-1] - window - 1e-9]
    return sum(sel) / len(sel)


def all_dof_settle(cols):
    ts = cols["t"]
    worst = ts[0]
    for key, band in (("u", None), ("v", VW_BAND), ("w", VW_BAND), ("p", PQR_BAND / DEG),
                      ("q", PQR_BAND / DEG), ("r", PQR_BAND / DEG)):
        fin = final_mean(ts, cols[key])
        b = U_BAND * abs(fin) if band is None else band
        s = settle_time(ts, cols[key], lambda y: abs(y - fin) <= b)
        if s is None:
            return None, key
        if s > worst:
            worst, which = s, key
    return worst, (which if worst > ts[0] else "-")


def straightness(nodes, length):
    """(largest node distance from the chord) / length, and the chord's angle below horizontal"""
    a = nodes[0][1:4]
    b = nodes[-1][1:4]
    d = [b[k] - a[k] for k in range(3)]
    n = math.sqrt(sum(c * c for c in d))
    worst = 0.0
    for node in nodes:
        p = [node[1 + k] - a[k] for k in range(3)]
        s = sum(p[k] * d[k] for k in range(3)) / (n * n)
        off = math.sqrt(sum((p[k] - s * d[k]) ** 2 for k in range(3)))
        worst = max(worst, off)
    return worst / length, math.degrees(math.atan2(d[2], math.hypot(d[0], d[1])))


def cable_length(nodes):
    return sum(math.dist(nodes[i][1:4], nodes[i + 1][1:4]) for i in range(len(nodes) - 1))


def circle_fit(xs, ys):
    """Kasa least squares: x^2 + y^2 + D x + E y + F = 0; returns (xc, yc, R, rms residual)"""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    u = [x - mx for x in xs]
    v = [y - my for y in ys]
    suu = sum(a * a for a in u)
    svv = sum(b * b for b in v)
    suv = sum(a * b for a, b in zip(u, v))
    z = [a * a + b * b for a, b in zip(u, v)]
    suz = sum(a * c for a, c in zip(u, z))
    svz = sum(b * c for b, c in zip(v, z))
    det = suu * svv - suv * suv
    if abs(det) < 1e-12:
        return None
    uc = 0.5 * (suz * svv - svz * suv) / det
    vc = 0.5 * (svz * suu - suz * suv) / det
    r = math.sqrt(uc * uc + vc * vc + sum(z) / n)
    xc, yc = uc + mx, vc + my
    rms = math.sqrt(sum((math.hypot(x - xc, y - yc) - r) ** 2 for x, y in zip(xs, ys)) / n)
    return xc, yc, r, rms


def turn_fit(cols, t_cmd):
    """circle through the track while the heading has turned FIT_FROM..FIT_TO deg since t_cmd"""
    ts = cols["t"]
    i0 = next(i for i, t in enumerate(ts) if t >= t_cmd - 1e-9)
    psi0 = cols["yaw"][i0]
    dpsi = [abs(y - psi0) * DEG for y in cols["yaw"]]
    a = next((i for i in range(i0, len(ts)) if dpsi[i] >= FIT_FROM), None)
    b = next((i for i in range(i0, len(ts)) if dpsi[i] >= FIT_TO), None)
    if a is None or b is None or b - a < 3:
        return None
    fit = circle_fit(cols["x"][a:b + 1], cols["y"][a:b + 1])
    if fit is None:
        return None
    speed = [math.sqrt(cols["u"][i] ** 2 + cols["v"][i] ** 2) for i in range(a, b + 1)]
    rate = (cols["yaw"][b] - cols["yaw"][a]) / (ts[b] - ts[a])
    return {"t0": ts[a], "t1": ts[b], "xc": fit[0], "yc": fit[1], "R": fit[2], "rms": fit[3],
            "speed": sum(speed) / len(speed), "rate": rate * DEG,
            "R_kin": (sum(speed) / len(speed)) / abs(rate) if rate else float("inf")}


def half_peak_radius(cols, t_from):
    """speed over ground / |yaw rate| averaged over the samples after t_from where |r| is at
    least half its peak (the measure of tests/reference/paper_cases_test.cc)"""
    sel = [i for i, t in enumerate(cols["t"]) if t >= t_from - 1e-9]
    peak = max(abs(cols["r"][i]) for i in sel)
    core = [i for i in sel if abs(cols["r"][i]) >= 0.5 * peak]
    speed = sum(math.hypot(cols["u"][i], cols["v"][i]) for i in core)
    rate = sum(abs(cols["r"][i]) for i in core)
    return speed / rate


def time_of_heading(cols, t_from, deg):
    ts = cols["t"]
    i0 = next(i for i, t in enumerate(ts) if t >= t_from - 1e-9)
    psi0 = cols["yaw"][i0]
    for i in range(i0, len(ts)):
        if abs(cols["yaw"][i] - psi0) * DEG >= deg:
            return ts[i]
    return None


def turn_command_time(cols):
    """the first time the towing vehicle's yaw rate exceeds 0.5 deg/s (the rudder command is one
    output interval earlier at most)"""
    return first_reach(cols["t"], cols["r"], lambda r: abs(r) * DEG > 0.5)


def window(ts, ys, t0, t1):
    sel = [(t, y) for t, y in zip(ts, ys) if t0 - 1e-9 <= t <= t1 + 1e-9]
    return sel


def extreme(sel, fn):
    t, y = fn(sel, key=lambda p: p[1])
    return y, t


def value_at(ts, ys, t):
    i = min(range(len(ts)), key=lambda k: abs(ts[k] - t))
    return ys[i]


def fmt_t(t):
    return "never" if t is None else "%.1f s" % t


# ---------------------------------------------------------------------------------------------
# Case 1


def case1(run, out, length=200.0):
    tv, tf = run.bodies[run.tow], run.bodies[run.fish]
    ts = tv["t"]
    out("%s: Case 1 (forward running), %g s, tow body %s, towfish %s"
        % (run.name, ts[-1], run.tow, run.fish))
    m = {}
    out("  surge u [m/s]          reach 6+-3%%  settle 6+-3%%  final(last %gs)  settle +-3%% final"
        % LAST_WINDOW)
    for label, cols in (("towing vehicle", tv), ("towfish", tf)):
        fin = final_mean(cols["t"], cols["u"])
        reach = first_reach(cols["t"], cols["u"], lambda u: abs(u - TARGET_U) <= U_BAND * TARGET_U)
        sett = settle_time(cols["t"], cols["u"], lambda u: abs(u - TARGET_U) <= U_BAND * TARGET_U)
        sfin = settle_time(cols["t"], cols["u"], lambda u: abs(u - fin) <= U_BAND * fin)
        s1 = settle_time(cols["t"], cols["u"], lambda u: abs(u - TARGET_U) <= 0.01 * TARGET_U)
        out("  %-22s %9s %12s %12.4f %14s   (+-1%% of 6: %s)"
            % (label, fmt_t(reach), fmt_t(sett), fin, fmt_t(sfin), fmt_t(s1)))
        m[label] = {"reach": reach, "settle": sett, "u": fin, "settle1": s1}
    lag = None
    if m["towfish"]["settle"] is not None and m["towing vehicle"]["settle"] is not None:
        lag = m["towfish"]["settle"] - m["towing vehicle"]["settle"]
    out("  towfish lag (u settles in 6+-3%%): %s" % ("n/a" if lag is None else "%.1f s" % lag))
    sv, kv = all_dof_settle(tv)
    sf, kf = all_dof_settle(tf)
    out("  all-DOF steady (u 3%%, v w %.2f m/s, p q r %.1f deg/s): towing vehicle %s (last: %s),"
        " towfish %s (last: %s), lag %s"
        % (VW_BAND, PQR_BAND, fmt_t(sv), kv, fmt_t(sf), kf,
           "n/a" if sv is None or sf is None else "%.1f s" % (sf - sv)))
    zf = final_mean(tf["t"], tf["z"])
    sz = settle_time(tf["t"], tf["z"], lambda z: abs(z - zf) <= 1.0)
    pf = final_mean(tf["t"], tf["pitch"])
    sp = settle_time(tf["t"], tf["pitch"], lambda p: abs(p - pf) * DEG <= 1.0)
    out("  towfish depth within 1 m of its final %.2f m from %s; pitch within 1 deg of its final"
        " %.2f deg from %s" % (zf, fmt_t(sz), pf * DEG, fmt_t(sp)))
    pmax, tpmax = extreme(list(zip(tf["t"], tf["pitch"])), max)
    out("  towfish transient: largest pitch %.1f deg (nose up) at %.1f s; deepest towing-vehicle"
        " excursion %.3f m from 3.5 m" % (pmax * DEG, tpmax,
                                            max(abs(z - 3.5) for z in tv["z"])))
    out("  steady state (mean of the last %g s):" % LAST_WINDOW)
    out("    towing vehicle depth %.3f m, pitch %.3f deg; towfish depth %.2f m, pitch %.3f deg"
        % (final_mean(ts, tv["z"]), final_mean(ts, tv["pitch"]) * DEG, zf, pf * DEG))
    # cable shape
    out("  cable (every 15 s): t, max node distance from the chord / 200 m, chord angle below"
        " horizontal, towfish layback behind node 0, stretched length")
    shown = []
    nxt = run.cable_times[0]
    for t in run.cable_times:
        if t >= nxt - 1e-6:
            shown.append(t)
            nxt = t + 15.0
    if shown[-1] != run.cable_times[-1]:
        shown.append(run.cable_times[-1])
    for t in shown:
        nodes = run.cable[t]
        s, ang = straightness(nodes, length)
        lay = math.hypot(nodes[-1][1] - nodes[0][1], nodes[-1][2] - nodes[0][2])
        out("    %6.1f s  %7.4f (%6.2f m)  %6.2f deg  layback %6.1f m  length %.2f m"
            % (t, s, s * length, ang, lay, cable_length(nodes)))
    m["straightness"] = straightness(run.cable[run.cable_times[-1]], length)[0]
    tt, top, bot = run.top_tension()
    out("  tension: top %.1f N, bottom %.1f N (axial force at node 0 / at the towfish; mean of the"
        " last %g s)" % (final_mean(tt, top), final_mean(tt, bot), LAST_WINDOW))
    m["top"], m["bottom"] = final_mean(tt, top), final_mean(tt, bot)
    out("  interaction force, body frame, mean of the last %g s (cable on the body):" % LAST_WINDOW)
    for label, name in (("towing vehicle", run.tow), ("towfish", run.fish)):
        f = run.forces[name]
        vals = [final_mean(f["t"], f[k]) for k in ("fx", "fy", "fz", "mx", "my", "mz")]
        mag = math.sqrt(sum(v * v for v in vals[:3]))
        out("    %-15s fx %8.1f  fy %7.2f  fz %8.1f N | mx %7.2f  my %8.2f  mz %7.2f N m |"
            " |fz|/|fx| %.3f, fx/|f| %.3f"
            % (label, *vals, abs(vals[2]) / max(abs(vals[0]), 1e-12), vals[0] / max(mag, 1e-12)))
        m["force_" + label] = vals
    m["settle_all"] = (sv, sf)
    m["fish_depth"] = zf
    return m


# ---------------------------------------------------------------------------------------------
# Case 2


def case2(run, out, ref1=None):
    tv, tf = run.bodies[run.tow], run.bodies[run.fish]
    ts = tv["t"]
    m = {}
    out("%s: Case 2 (U-turn), %g s, tow body %s, towfish %s" % (run.name, ts[-1], run.tow, run.fish))
    t_cmd = turn_command_time(tv)
    # the rudder command is issued at the output time before the yaw rate shows
    out("  yaw rate of the towing vehicle first above 0.5 deg/s at %s (rudder command)" % fmt_t(t_cmd))
    u_cmd = value_at(ts, tv["u"], t_cmd)
    out("  before the turn: towing vehicle u %.3f m/s, towfish u %.3f m/s, towfish depth %.2f m"
        % (u_cmd, value_at(ts, tf["u"], t_cmd), value_at(ts, tf["z"], t_cmd)))
    t170 = time_of_heading(tv, t_cmd, 170.0)
    out("  towing vehicle heading change 170 deg (rudder back to 0) at %s, %.1f s after the command"
        % (fmt_t(t170), (t170 - t_cmd) if t170 else float("nan")))
    m["t_cmd"], m["t170"] = t_cmd, t170
    for label, cols in (("towing vehicle", tv), ("towfish", tf)):
        t5 = time_of_heading(cols, t_cmd, 5.0)
        t90 = time_of_heading(cols, t_cmd, 90.0)
        t170b = time_of_heading(cols, t_cmd, 170.0)
        psi_end = (cols["yaw"][-1] - value_at(ts, cols["yaw"], t_cmd)) * DEG
        out("  %-15s heading change 5 / 90 / 170 deg at %s / %s / %s; final change %.1f deg"
            % (label, fmt_t(t5), fmt_t(t90), fmt_t(t170b), psi_end))
        m["t5_" + label], m["t90_" + label] = t5, t90
        m["psi_end_" + label] = psi_end
    if m["t90_towfish"] and m["t90_towing vehicle"]:
        out("  towfish lag in heading (90 deg): %.1f s; towfish starts to turn (5 deg) %.1f s after"
            " the command" % (m["t90_towfish"] - m["t90_towing vehicle"], m["t5_towfish"] - t_cmd))
    out("  turning radius (circle fitted while the heading has turned %g-%g deg):"
        % (FIT_FROM, FIT_TO))
    for label, cols in (("towing vehicle", tv), ("towfish", tf)):
        fit = turn_fit(cols, t_cmd)
        m["fit_" + label] = fit
        if fit is None:
            out("    %-15s no turn of %g deg" % (label, FIT_TO))
            continue
        out("    %-15s R %6.1f m (rms %.2f m) over %.1f-%.1f s, centre (%.1f, %.1f); mean speed"
            " %.2f m/s, mean yaw rate %.2f deg/s, speed / yaw rate %.1f m"
            % (label, fit["R"], fit["rms"], fit["t0"], fit["t1"], fit["xc"], fit["yc"],
               fit["speed"], fit["rate"], fit["R_kin"]))
    hv, hf = half_peak_radius(tv, t_cmd), half_peak_radius(tf, t_cmd)
    out("    cross-check, mean speed / mean |r| where |r| >= half its peak: towing vehicle %.1f m,"
        " towfish %.1f m" % (hv, hf))
    m["R_half_peak"] = (hv, hf)
    ft, ff = m["fit_towing vehicle"], m["fit_towfish"]
    if ft and ff:
        out("    ratio towfish / towing vehicle %.2f; centres %.1f m apart"
            % (ff["R"] / ft["R"], math.hypot(ff["xc"] - ft["xc"], ff["yc"] - ft["yc"])))
    out("  furthest north (advance): towing vehicle x %.1f m, towfish x %.1f m; largest |y|"
        " before heading 90 deg: towing vehicle %.1f m, towfish %.1f m"
        % (max(tv["x"]), max(tf["x"]),
           max(abs(y) for t, y in zip(ts, tv["y"]) if t <= (m["t90_towing vehicle"] or ts[-1])),
           max(abs(y) for t, y in zip(ts, tf["y"]) if t <= (m["t90_towfish"] or ts[-1]))))
    sel = window(ts, tv["u"], t_cmd, ts[-1])
    umin, tumin = extreme(sel, min)
    umax, tumax = extreme(sel, max)
    out("  towing vehicle u after the command: min %.2f m/s at %.1f s, max %.2f m/s at %.1f s,"
        " final %.3f m/s" % (umin, tumin, umax, tumax, final_mean(ts, tv["u"])))
    sel = window(ts, tf["u"], t_cmd, ts[-1])
    out("  towfish u after the command: min %.2f m/s at %.1f s, max %.2f m/s at %.1f s"
        % (*extreme(sel, min), *extreme(sel, max)))
    m["u_final"] = final_mean(ts, tv["u"])
    # depth of the towfish by phase
    t_f90 = m["t90_towfish"] or ts[-1]
    phases = [("A vehicle turning", t_cmd, t170 or ts[-1]),
              ("B until towfish heading 90", t170 or ts[-1], t_f90),
              ("C after", t_f90, ts[-1])]
    out("  towfish depth z [m] by phase: start -> end, min (t), max (t)")
    for label, a, b in phases:
        sel = window(ts, tf["z"], a, b)
        if len(sel) < 2:
            continue
        zmin, tzmin = extreme(sel, min)
        zmax, tzmax = extreme(sel, max)
        m["z_phase_" + label[0]] = (zmin, tzmin, zmax, tzmax)
        out("    %-27s %5.1f-%5.1f s: %6.2f -> %6.2f, min %6.2f (%.1f s), max %6.2f (%.1f s)"
            % (label, a, b, sel[0][1], sel[-1][1], zmin, tzmin, zmax, tzmax))
    sel = window(ts, tf["z"], t_cmd, ts[-1])
    m["z_range"] = (extreme(sel, min)[0], extreme(sel, max)[0])
    m["z_cmd"] = sel[0][1]
    m["z_final"] = final_mean(ts, tf["z"])
    out("    range after the command %.2f-%.2f m; final %.2f m" % (*m["z_range"], m["z_final"]))
    if ref1 is not None:
        rf = ref1.bodies[ref1.fish]
        zref_final = final_mean(rf["t"], rf["z"])
        d = []
        for t, z in zip(ts, tf["z"]):
            if t < t_cmd - 1e-9:
                continue
            zr = value_at(rf["t"], rf["z"], t) if t <= rf["t"][-1] + 1e-9 else zref_final
            d.append((t, z - zr))
        dmax, tdmax = extreme(d, max)
        dmin, tdmin = extreme(d, min)
        out("  towfish depth minus Case 1 (%s) at the same time: largest +%.2f m (deeper) at %.1f s,"
            " most negative %.2f m (shallower) at %.1f s" % (ref1.name, dmax, tdmax, dmin, tdmin))
        m["dz_case1"] = (dmax, tdmax, dmin, tdmin)
    # towing vehicle heave / pitch rate after the command (the paper: oscillation near 80 s)
    sel_q = window(ts, tv["q"], t_cmd, ts[-1])
    sel_w = window(ts, tv["w"], t_cmd, ts[-1])
    sel_z = window(ts, tv["z"], t_cmd, ts[-1])
    out("  towing vehicle after the command: q %.2f..%.2f deg/s, w %.3f..%.3f m/s, depth"
        " %.3f..%.3f m" % (extreme(sel_q, min)[0] * DEG, extreme(sel_q, max)[0] * DEG,
                            extreme(sel_w, min)[0], extreme(sel_w, max)[0],
                            extreme(sel_z, min)[0], extreme(sel_z, max)[0]))
    for label, cols in (("towing vehicle", tv), ("towfish", tf)):
        sel_r = window(ts, cols["roll"], t_cmd, ts[-1])
        sel_p = window(ts, cols["pitch"], t_cmd, ts[-1])
        out("  %-15s after the command: roll %.1f..%.1f deg, pitch %.1f..%.1f deg"
            % (label, extreme(sel_r, min)[0] * DEG, extreme(sel_r, max)[0] * DEG,
               extreme(sel_p, min)[0] * DEG, extreme(sel_p, max)[0] * DEG))
    tt, top, bot = run.top_tension()
    out("  tension [N]: top / bottom at the command %.0f / %.0f; after it top %.0f..%.0f,"
        " bottom %.0f..%.0f; final %.0f / %.0f"
        % (value_at(tt, top, t_cmd), value_at(tt, bot, t_cmd),
           extreme(window(tt, top, t_cmd, tt[-1]), min)[0],
           extreme(window(tt, top, t_cmd, tt[-1]), max)[0],
           extreme(window(tt, bot, t_cmd, tt[-1]), min)[0],
           extreme(window(tt, bot, t_cmd, tt[-1]), max)[0],
           final_mean(tt, top), final_mean(tt, bot)))
    m["top_cmd"] = value_at(tt, top, t_cmd)
    m["top_range"] = (extreme(window(tt, top, t_cmd, tt[-1]), min)[0],
                      extreme(window(tt, top, t_cmd, tt[-1]), max)[0])
    m["bottom_range"] = (extreme(window(tt, bot, t_cmd, tt[-1]), min)[0],
                         extreme(window(tt, bot, t_cmd, tt[-1]), max)[0])
    m["top_final"] = final_mean(tt, top)
    for label, name in (("towing vehicle", run.tow), ("towfish", run.fish)):
        f = run.forces[name]
        parts = []
        for k in ("fx", "fy", "fz"):
            sel = window(f["t"], f[k], t_cmd, f["t"][-1])
            parts.append("%s %.0f..%.0f" % (k, extreme(sel, min)[0], extreme(sel, max)[0]))
        out("  interaction force on the %s after the command [N, body frame]: %s"
            % (label, ", ".join(parts)))
    sv, kv = all_dof_settle(tv)
    sf, kf = all_dof_settle(tf)
    out("  all-DOF steady again: towing vehicle %s (last: %s), towfish %s (last: %s), lag %s"
        % (fmt_t(sv), kv, fmt_t(sf), kf,
           "n/a" if sv is None or sf is None else "%.1f s" % (sf - sv)))
    m["settle_all"] = (sv, sf)
    return m


# ---------------------------------------------------------------------------------------------
# compare and summary


def series_diff(a, b, t_from=0.0):
    """largest differences of b from a at the output times both have (t >= t_from):
    {quantity: (difference, time)}"""
    out = {}
    ta = {round(t, 6): i for i, t in enumerate(a.bodies[a.tow]["t"])}
    idx = [(ta[round(t, 6)], j, t) for j, t in enumerate(b.bodies[b.tow]["t"])
           if round(t, 6) in ta and t >= t_from - 1e-9]

    def worst(fn):
        return max(((fn(i, j), t) for i, j, t in idx), key=lambda p: p[0])
    for label, na, nb in (("towing vehicle", a.tow, b.tow), ("towfish", a.fish, b.fish)):
        ca, cb = a.bodies[na], b.bodies[nb]
        out[label + " u [m/s]"] = worst(lambda i, j: abs(ca["u"][i] - cb["u"][j]))
        out[label + " position [m]"] = worst(lambda i, j: math.dist(
            (ca["x"][i], ca["y"][i], ca["z"][i]), (cb["x"][j], cb["y"][j], cb["z"][j])))
        out[label + " depth [m]"] = worst(lambda i, j: abs(ca["z"][i] - cb["z"][j]))
        out[label + " yaw [deg]"] = worst(lambda i, j: abs(ca["yaw"][i] - cb["yaw"][j]) * DEG)
        out[label + " pitch [deg]"] = worst(lambda i, j: abs(ca["pitch"][i] - cb["pitch"][j])
                                            * DEG)
        fa, fb = a.forces[na], b.forces[nb]
        out[label + " |cable force| [N]"] = worst(lambda i, j: abs(
            math.hypot(fa["fx"][i], fa["fy"][i], fa["fz"][i])
            - math.hypot(fb["fx"][j], fb["fy"][j], fb["fz"][j])))
    _, a_top, _ = a.top_tension()
    _, b_top, _ = b.top_tension()
    ca_top = {round(t, 6): v for t, v in zip(a.cable_times, a_top)}
    out["top tension [N]"] = max(((abs(ca_top[round(t, 6)] - v), t)
                                  for t, v in zip(b.cable_times, b_top)
                                  if round(t, 6) in ca_top and t >= t_from - 1e-9),
                                 key=lambda p: p[0])
    return out


def compare(paths, out, ref1=None):
    runs = [Run(p) for p in paths]
    metrics = []
    quiet = []
    for r in runs:
        metrics.append(case1(r, quiet.append) if r.case == 1 else case2(r, quiet.append, ref1))
    names = [r.name for r in runs]
    w = max(12, max(len(n) for n in names) + 1)
    out("comparison, %s" % ", ".join("%s = %s" % (n, p) for n, p in zip(names, paths)))
    out("  %-44s" % "" + "".join("%*s" % (w, n) for n in names))

    def row(label, vals):
        out("  %-44s" % label + "".join("%*s" % (w, v) for v in vals))

    def f(v, spec="%.2f"):
        return "-" if v is None else spec % v
    if all(r.case == 1 for r in runs):
        row("towing vehicle u reaches 6 m/s +-3% [s]", [f(m["towing vehicle"]["reach"], "%.1f")
                                                        for m in metrics])
        row("towfish u settles in 6 m/s +-3% [s]", [f(m["towfish"]["settle"], "%.1f")
                                                   for m in metrics])
        row("all-DOF steady, towing vehicle [s]", [f(m["settle_all"][0], "%.1f") for m in metrics])
        row("all-DOF steady, towfish [s]", [f(m["settle_all"][1], "%.1f") for m in metrics])
        row("final u towing vehicle [m/s]", [f(m["towing vehicle"]["u"], "%.4f") for m in metrics])
        row("final towfish depth [m]", [f(m["fish_depth"], "%.3f") for m in metrics])
        row("cable straightness (final)", [f(m["straightness"], "%.5f") for m in metrics])
        row("top tension (final) [N]", [f(m["top"], "%.1f") for m in metrics])
    elif all(r.case == 2 for r in runs):
        row("heading 170 deg (rudder back) [s]", [f(m["t170"], "%.1f") for m in metrics])
        row("turning radius towing vehicle [m]",
            [f(m["fit_towing vehicle"]["R"] if m["fit_towing vehicle"] else None, "%.1f")
             for m in metrics])
        row("turning radius towfish [m]",
            [f(m["fit_towfish"]["R"] if m["fit_towfish"] else None, "%.1f") for m in metrics])
        row("towfish heading 90 deg at [s]", [f(m["t90_towfish"], "%.1f") for m in metrics])
        row("towfish deepest after the vehicle's turn [m]",
            [f(m["z_phase_B"][2] if "z_phase_B" in m else None) for m in metrics])
        row("towfish shallowest after its turn [m]",
            [f(m["z_phase_C"][0] if "z_phase_C" in m else None) for m in metrics])
        row("top tension max after the command [N]", [f(m["top_range"][1], "%.0f")
                                                      for m in metrics])
        row("bottom tension max after the command [N]", [f(m["bottom_range"][1], "%.0f")
                                                         for m in metrics])
        row("final heading change towing vehicle [deg]",
            [f(m["psi_end_towing vehicle"], "%.2f") for m in metrics])
    for r in runs[1:]:
        d = series_diff(runs[0], r)
        d10 = series_diff(runs[0], r, 10.0)
        out("  largest difference of %s from %s:" % (r.name, runs[0].name))
        out("    %-40s %21s %21s" % ("", "whole run (at t)", "t >= 10 s (at t)"))
        for k in d:
            out("    %-40s %10.4g (%5.1f s) %10.4g (%5.1f s)" % (k, *d[k], *d10[k]))


def summary(path, out):
    run = Run(path)
    quiet = []
    out("summary of %s (Park & Kim Case %d)" % (path, run.case))
    if run.case == 1:
        m = case1(run, quiet.append)
        out("  %-46s %s" % ("steady surge, towing vehicle [m/s]", "%.3f" % m["towing vehicle"]["u"]))
        out("  %-46s %s" % ("reaches 6 m/s +-3 % at", fmt_t(m["towing vehicle"]["reach"])))
        out("  %-46s %s" % ("towfish settles in 6 m/s +-3 % at", fmt_t(m["towfish"]["settle"])))
        out("  %-46s %.2f m" % ("towfish depth (steady)", m["fish_depth"]))
        out("  %-46s %.0f / %.0f N" % ("tension top / bottom (steady)", m["top"], m["bottom"]))
        return
    m = case2(run, quiet.append)
    tv = run.bodies[run.tow]
    ft, ff = m["fit_towing vehicle"], m["fit_towfish"]
    rows = [
        ("surge before the turn, towing vehicle",
         "%.3f m/s at %.1f s" % (value_at(tv["t"], tv["u"], m["t_cmd"]), m["t_cmd"])),
        ("steady surge at the end, towing vehicle", "%.3f m/s" % m["u_final"]),
        ("turn starts (r > 0.5 deg/s) -> heading 170 deg",
         "%.1f s -> %.1f s" % (m["t_cmd"], m["t170"] or -1)),
        ("turning radius, towing vehicle (circle fit)", "%.1f m" % ft["R"] if ft else "-"),
        ("turning radius, towfish (circle fit)", "%.1f m" % ff["R"] if ff else "-"),
        ("towfish heading 90 deg", "%s (vehicle %s)" % (fmt_t(m["t90_towfish"]),
                                                       fmt_t(m["t90_towing vehicle"]))),
        ("towfish depth at the command (still rising)", "%.1f m" % m["z_cmd"]),
        ("towfish deepest after the vehicle's turn",
         "%.1f m at %.1f s" % (m["z_phase_B"][2], m["z_phase_B"][3]) if "z_phase_B" in m
         else "-"),
        ("towfish shallowest after its own turn",
         "%.1f m at %.1f s" % (m["z_phase_C"][0], m["z_phase_C"][1]) if "z_phase_C" in m
         else "-"),
        ("towfish depth at the end", "%.1f m" % m["z_final"]),
        ("top tension: at the command, range after, end",
         "%.0f N, %.0f-%.0f N, %.0f N" % (m["top_cmd"], m["top_range"][0], m["top_range"][1],
                                          m["top_final"])),
        ("bottom tension range after the command",
         "%.0f-%.0f N" % m["bottom_range"]),
    ]
    for k, v in rows:
        out("  %-48s %s" % (k, v))


def depth_range(run, t_from):
    """(min, max) towfish depth from t_from to the end of the run"""
    c = run.bodies[run.fish]
    zs = [z for t, z in zip(c["t"], c["z"]) if t >= t_from - 1e-9]
    return min(zs), max(zs)


def depth_control(ref_path, ctl_path, out):
    """the towfish depth range of a Case 2 run without (ref) and with (ctl) depth control,
    both from the turn command of the reference run on (the issue's 'depth excursion')"""
    ref, ctl = Run(ref_path), Run(ctl_path)
    if ref.case != 2:
        sys.exit("paper_cases: error: --depth-control: %s is not a Case 2 (U-turn) run" % ref_path)
    t_cmd = turn_command_time(ref.bodies[ref.tow])
    r0, r1 = depth_range(ref, t_cmd), depth_range(ctl, t_cmd)
    e0, e1 = r0[1] - r0[0], r1[1] - r1[0]
    out("towfish depth excursion from the turn command (t >= %.1f s) on:" % t_cmd)
    out("  %-48s %.2f m (%.1f-%.1f m)" % ("fins held at zero (%s)" % ref.name, e0, *r0))
    out("  %-48s %.2f m (%.1f-%.1f m)" % ("depth controller (%s)" % ctl.name, e1, *r1))
    out("  %-48s %.2f (the issue's aim: at most 0.5)" % ("ratio controlled / uncontrolled",
                                                         e1 / e0 if e0 > 0 else float("nan")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dirs", nargs="+", help="CSV directories written by sim_node --csv")
    parser.add_argument("--summary", action="store_true", help="short table of one run")
    parser.add_argument("--compare", action="store_true",
                        help="compare the runs with the first (same case)")
    parser.add_argument("--case1", help="a Case 1 run: Case 2 towfish depth relative to it")
    parser.add_argument("--depth-control", action="store_true",
                        help="REF CTL: towfish depth excursion without and with depth control")
    args = parser.parse_args()
    if args.depth_control:
        if len(args.dirs) != 2:
            parser.error("--depth-control takes two directories: REF CTL")
        depth_control(args.dirs[0], args.dirs[1], print)
        return
    ref1 = Run(args.case1) if args.case1 else None
    if args.summary:
        for d in args.dirs:
            summary(d, print)
        return
    if args.compare:
        compare(args.dirs, print, ref1)
        return
    for i, d in enumerate(args.dirs):
        if i:
            print()
        run = Run(d)
        if run.case == 1:
            case1(run, print)
        else:
            case2(run, print, ref1)


if __name__ == "__main__":
    main()
