#!/usr/bin/env python3
"""Writes the example displacement RAO table of a ~60 m survey ship (config/vessels/).

    python3 scripts/vessel_raos.py [--out config/vessels/survey_ship_raos.csv]

Standard library only, no network. The model and its limits are in docs/vessels.md, "Example
RAOs"; in short: the ship is a rectangular box (length L, beam B, draught T) in deep water at
zero speed. Each of heave, pitch and roll is a single-degree-of-freedom oscillator,
    H_j = X_j / (1 - r^2 + 2 i zeta_j r),    r = omega / omega_j,
driven by the Froude-Krylov force of the undisturbed wave's pressure on the box's bottom,
X_j, normalised by the hydrostatic stiffness so that X_j is the wave's elevation (heave) or
slope (pitch, roll) in the long-wave limit. Complex amplitudes are per metre of wave amplitude
with the time dependence e^{i omega t} and the wave's crest at the reference point (midships,
on the centreline) at t = 0, so H = |H| e^{-i phi} with phi the lag behind the crest (the
convention of the RAO files, docs/vessels.md). Axes: x forward, y starboard; heave up, roll
starboard down, pitch bow up. beta is the direction the waves travel toward, from the bow
toward starboard (0 following seas, 180 head seas). A wave component
    eta(x, y, t) = Re[e^{i (omega t - kx x - ky y)}],  kx = k cos beta, ky = k sin beta,
has the bottom pressure rho g e^{-k T} eta, so (per rho g)
    heave force   F3 = e^{-kT} L B sinc(kx L/2) sinc(ky B/2)
    pitch moment  M5 = int x p dA   = e^{-kT} B sinc(ky B/2) (-2 i J(kx, L/2))
    roll moment   M4 = -int y p dA  = e^{-kT} L sinc(kx L/2) ( 2 i J(ky, B/2))
with sinc u = sin(u)/u and J(q, l) = (sin(q l) - q l cos(q l)) / q^2 (int_-l^l x e^{-iqx} dx =
-2 i J). Divided by C33 = L B, C55 = B L^3 / 12 and L B^3 / 12 these tend to 1, -i kx and
i ky: the ship follows the surface (heave = eta, pitch = d eta/dx, roll = -d eta/dy).
Surge, sway and yaw are not given (zero).
"""

import argparse
import cmath
import math
import os

G = 9.81  # [m/s^2]

# the ship (a box): a representative ~60 m survey vessel
LENGTH = 60.0  # L [m]
BEAM = 13.0  # B [m]
DRAUGHT = 4.0  # T [m]

# heave: added mass equal to the displaced mass (a33 = m), so omega_3^2 = g / (2 T)
HEAVE_PERIOD = 2.0 * math.pi * math.sqrt(2.0 * DRAUGHT / G)  # 5.67 s
HEAVE_DAMPING = 0.2
# pitch: radius of gyration 0.25 L and added inertia equal to the inertia, so
# omega_5^2 = (rho g B L^3 / 12) / (2 m (L/4)^2) = 2 g / (3 T)
PITCH_PERIOD = 2.0 * math.pi * math.sqrt(1.5 * DRAUGHT / G)  # 4.91 s
PITCH_DAMPING = 0.2
# roll: the IMO Intact Stability Code's natural roll period T = 2 C B / sqrt(GM),
# C = 0.373 + 0.023 B/T - 0.043 L/100, with GM = 1.2 m: 10.0 s
GM = 1.2  # [m]
ROLL_C = 0.373 + 0.023 * BEAM / DRAUGHT - 0.043 * LENGTH / 100.0
ROLL_PERIOD = round(2.0 * ROLL_C * BEAM / math.sqrt(GM), 1)  # 10.0 s
ROLL_DAMPING = 0.1

# the grid: 1 to 30 s (a JONSWAP sea of Tp 8 s holds components down to 1.5 s), directions
# 0 to 360 deg every 15 (the full circle)
PERIODS = ([1.0 + 0.5 * i for i in range(27)]  # 1 .. 14 s
           + [float(p) for p in range(15, 21)]  # 15 .. 20 s
           + [float(p) for p in range(22, 31, 2)])  # 22 .. 30 s
DIRECTIONS = [15 * i for i in range(25)]  # deg, 0 .. 360


def cos_sin_deg(deg):
    """cos and sin of a whole number of degrees, exact at multiples of 90."""
    d = deg % 360
    exact = {0: (1.0, 0.0), 90: (0.0, 1.0), 180: (-1.0, 0.0), 270: (0.0, -1.0)}
    if d in exact:
        return exact[d]
    r = math.radians(d)
    return math.cos(r), math.sin(r)


def sinc(u):
    return 1.0 - u * u / 6.0 if abs(u) < 1e-4 else math.sin(u) / u


def moment_integral(q, half):
    """J(q, l) = (sin(ql) - ql cos(ql)) / q^2; its series near q = 0."""
    u = q * half
    if abs(u) < 0.1:
        return half ** 3 * q / 3.0 * (1.0 - u * u / 10.0 + u ** 4 / 280.0)
    return (math.sin(u) - u * math.cos(u)) / (q * q)


def oscillator(omega, period, damping):
    r = omega * period / (2.0 * math.pi)
    return 1.0 / complex(1.0 - r * r, 2.0 * damping * r)


def raos(period, direction_deg):
    """{dof: complex H} per metre of wave amplitude, rotations in rad/m."""
    omega = 2.0 * math.pi / period
    k = omega * omega / G  # deep water
    c, s = cos_sin_deg(direction_deg)
    kx, ky = k * c, k * s
    depth = math.exp(-k * DRAUGHT)
    x_heave = depth * sinc(kx * LENGTH / 2.0) * sinc(ky * BEAM / 2.0)
    x_pitch = (depth * sinc(ky * BEAM / 2.0) * (-2j) * moment_integral(kx, LENGTH / 2.0)
               * 12.0 / LENGTH ** 3)
    x_roll = (depth * sinc(kx * LENGTH / 2.0) * 2j * moment_integral(ky, BEAM / 2.0)
              * 12.0 / BEAM ** 3)
    return {
        "heave": x_heave * oscillator(omega, HEAVE_PERIOD, HEAVE_DAMPING),
        "roll": x_roll * oscillator(omega, ROLL_PERIOD, ROLL_DAMPING),
        "pitch": x_pitch * oscillator(omega, PITCH_PERIOD, PITCH_DAMPING),
    }


def amplitude_phase(h, rotation):
    """(amplitude in m/m or deg/m, phase lag in deg within (-180, 180]) of H = |H| e^{-i phi}."""
    a = abs(h)
    if a < 1e-12:
        return 0.0, 0.0
    phi = -math.degrees(cmath.phase(h))
    if phi <= -180.0:
        phi += 360.0
    if abs(phi) < 5e-4:
        phi = 0.0  # no "-0.000"
    return (math.degrees(a) if rotation else a), phi


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--out", default=os.path.join(here, "..", "config", "vessels",
                                                      "survey_ship_raos.csv"))
    args = parser.parse_args()
    lines = [
        "# Displacement RAOs of a representative 60 m survey ship: a box L 60 m, B 13 m, T 4 m",
        "# in deep water at zero speed; Froude-Krylov excitation on the bottom, one",
        "# degree-of-freedom oscillator per dof (docs/vessels.md, \"Example RAOs\").",
        "# heave: T_n %.2f s, damping ratio %.2f; pitch: T_n %.2f s, %.2f; roll: T_n %.1f s, %.2f."
        % (HEAVE_PERIOD, HEAVE_DAMPING, PITCH_PERIOD, PITCH_DAMPING, ROLL_PERIOD, ROLL_DAMPING),
        "# surge, sway and yaw are not given (zero). An illustration, not a diffraction analysis.",
        "# Written by: python3 scripts/vessel_raos.py",
        "# direction_deg: toward which the waves travel, from the bow toward starboard",
        "# (0 following, 90 toward starboard, 180 head seas); phase_deg: lag behind the crest",
        "# at the reference point (midships); heave up, roll starboard down, pitch bow up.",
        "period,direction_deg,dof,amplitude,phase_deg",
    ]
    for period in PERIODS:
        for direction in DIRECTIONS:
            h = raos(period, direction)
            for dof in ("heave", "roll", "pitch"):
                a, phi = amplitude_phase(h[dof], rotation=dof != "heave")
                lines.append("%g,%d,%s,%.6g,%.3f" % (period, direction, dof, a, phi))
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s (%d rows)" % (args.out, len(lines) - 10))


if __name__ == "__main__":
    main()
