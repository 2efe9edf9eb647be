#pragma once
// The winch at the cable's start (docs/winch.md): its limits (Model::cable.winch), its command
// (an input, like VehicleCommand) and the limits an incoming command is checked against.
//
// The drum pays out (dL/dt > 0) or reels in (dL/dt < 0) the unstretched cable length L within
//   min_length <= L <= max_length,  |dL/dt| <= max_speed,  |d2L/dt2| <= max_acceleration;
// a speed command V drives dL/dt to V, a length command drives L to the target and stops there.
// Above brake_tension the drum slips and pays out.
//
// The drum's motion over a step h (AdvanceWinch): L_{n+1} = L_n + h (V_n + V_{n+1}) / 2 (constant
// acceleration), V_{n+1} = V_n + clamp(V_des - V_n, -a h, a h), a = max_acceleration, with the
// desired speed V_des the command's, limited so that the drum can still stop exactly at every
// stop point ahead (min_length, max_length, a length target) by braking at a. Braking from u to
// 0 at a over whole steps covers u^2 / (2 a) with this update, so the largest speed u at the
// step's end from which the point at distance d can be reached (d - h (V_n + u) / 2 left) is
//   u^2 + a h u = 2 a d - a h V_n,   u = (-a h + sqrt(a^2 h^2 + 4 (2 a d - a h V_n))) / 2.
// A step that reaches a stop point at a speed <= a h ends there at rest (exact stop); L stays
// within [min_length, max_length] always.
// Brake: a slipping friction brake holds its tension, T = brake_tension, while the drum pays
// out. Explicitly, per step, the slip speed s >= 0 (on top of the drive's, kept apart) grows by
// the speed that would relieve the tension excess of the drum element within the step,
//   s_{n+1} = max(0, s_n + (T - brake_tension) l_0 / (E A h))   (dT/dl_0 = -E A / l_0),
// and falls likewise once the tension is below the brake's, until the drum grips (s = 0). This
// integral law drives T to brake_tension while slipping (a constant slip speed would leave the
// load falling steadily at its full weight: a damper, not a brake); it is not bound by
// max_speed or max_acceleration (the brake, not the motor, sets it). T is the tension at the
// step's start.
//
// The cable's side (system.h, docs/winch.md): element 0 at the drum has the variable rest length
// l_0 = L - (nodes - 2) l_e; it is split when l_0 would exceed kSplitLength l_e and merged
// with its neighbour when it would fall below kMergeLength l_e.

#include <limits>

#include "core/actuator.h"

namespace towsim::core {

struct CableParams;  // model.h

// the drum element's bounds, in nominal element lengths l_e = cable.length / cable.elements:
// split beyond the first (leaving kSplitLength - 1), merge below the second (giving
// kMergeLength + 1); the gap between them keeps a reversal from splitting and merging again
inline constexpr double kSplitLength = 1.6;
inline constexpr double kMergeLength = 0.4;

struct WinchParams {               // Model::cable.winch (std::optional<WinchParams>)
  double min_length = 0.0;         // [m]
  double max_length = 0.0;         // [m]
  double max_speed = 0.0;          // |dL/dt| [m/s]
  double max_acceleration = 0.0;   // |d2L/dt2| [m/s^2]
  double brake_tension = std::numeric_limits<double>::infinity();  // [N]
};

struct WinchCommand {  // an input, like VehicleCommand (not part of State)
  enum class Mode { kSpeed, kLength };
  Mode mode = Mode::kSpeed;
  double value = 0.0;  // kSpeed: dL/dt [m/s], + pays out; kLength: target L [m]
};

// The range a command of each mode is clamped into (the one place the DDS command check takes
// the winch's limits from): kSpeed [-max_speed, max_speed] with the acceleration limit as its
// rate; kLength [min_length, max_length].
Actuator WinchSpeedRange(const WinchParams& p);
Actuator WinchLengthRange(const WinchParams& p);
// the range of command's mode
Actuator WinchCommandRange(const WinchParams& p, WinchCommand::Mode mode);
// clamps command->value into its mode's range; returns whether it had to (NaN is the caller's
// to reject: it is returned unchanged and counts as clamped)
bool ClampWinchCommand(const WinchParams& p, WinchCommand* command);

// the most cable nodes a run with cable.winch can have: ceil(max_length / l_e) + 2
int WinchMaxNodes(const CableParams& cable);

struct WinchStep {
  double length = 0.0;       // L_{n+1} [m]
  double speed = 0.0;        // dL/dt at the step's end [m/s]: drive_speed + slip_speed
  double drive_speed = 0.0;  // V_{n+1}, the drive's (limited) speed [m/s]
  double slip_speed = 0.0;   // s_{n+1}, the brake's slip [m/s]
  bool slipping = false;     // the brake slips (s_{n+1} > 0)
};

// the drum's step h (above) from L_n = length, the drive's V_n = drive_speed and the slip
// s_n = slip_speed under `command` (clamped into its range), with the drum tension T and
// slip_compliance = l_0 / (E A) [m/N]
WinchStep AdvanceWinch(const WinchParams& p, const WinchCommand& command, double length,
                       double drive_speed, double slip_speed, double tension,
                       double slip_compliance, double h);

}  // namespace towsim::core
