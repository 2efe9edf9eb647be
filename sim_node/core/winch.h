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
// Brake: a slipping friction brake holds its tension, T = brake_tension = T_b, while the drum
// pays out (Coulomb friction: it grips below T_b and slips at T_b). The slip speed s >= 0 of a
// step (on top of the drive's, kept apart; constant over the step) is solved with the step, so
// that the drum tension at the step's end T_{n+1}(s) (the start's joint force) satisfies the
// complementarity
//   s = 0 and T_{n+1}(0) <= T_b   (the drum grips),   or   s > 0 and T_{n+1}(s) = T_b,
// by secant iteration on whole steps (BrakeSlipIteration; Simulation::StepBy repeats the step
// from its start with each new s): a step that grips (s_n = 0 and T_{n+1}(0) <= T_b) is taken
// once, a slipping one converges to |T_{n+1} - T_b| <= kBrakeTensionRelTol T_b in at most 3
// attempts in the hanging-weight test, 6 in the unit tests' steady tow.
// The first correction takes the slope the last slipping step measured (WinchState::slip_slope),
// or without one the drum element's stiffness, dT/ds = -E A h / l_0 (the stiffest the cable can
// respond within a step); later ones the secant. The slip is not bound by
// max_speed or max_acceleration (the brake, not the motor, sets it) but by the scene's step rule,
// h s <= (kSplitLength - 1 - kMergeLength) l_e (docs/winch.md), and it stops at max_length.
//
// The cable's side (system.h, docs/winch.md): element 0 at the drum has the variable rest length
// l_0 = L - (nodes - 2) l_e; it is split when l_0 would exceed kSplitLength l_e and merged
// with its neighbour when it would fall below kMergeLength l_e.

#include <limits>
#include <string>

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
  // its name: its command topic <ns>/<name>/command and CSV file <name>.csv
  // (docs/scene_format.md "Networks"): `winch` in a scene with one winch
  std::string name = "winch";
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

// the drum's step h (above) from L_n = length and the drive's V_n = drive_speed under
// `command` (clamped into its range), with the brake's slip `slip_speed` >= 0 over the step
// added (0 with a brake that grips, or without one)
WinchStep AdvanceWinch(const WinchParams& p, const WinchCommand& command, double length,
                       double drive_speed, double slip_speed, double h);

// the brake's slip solved with the step (above): its tension band and its attempts
inline constexpr double kBrakeTensionRelTol = 1e-3;  // |T_{n+1} - T_b| <= 1e-3 T_b (2 N in 2 kN)
// then the last attempt is kept (the tests need at most 6)
inline constexpr int kMaxBrakeAttempts = 8;

// the secant iteration for the slip s of one step (above): a first attempt with the previous
// step's slip (within [0, s_max]), then Next with the tension each attempt gave until it says
// the step stands
class BrakeSlipIteration {
 public:
  // brake_tension T_b, the slip's bound s_max and the first slope dT/ds < 0 [N s/m]
  BrakeSlipIteration(double brake_tension, double max_slip, double first_slope)
      : brake_(brake_tension), max_slip_(max_slip), slope_(first_slope) {}
  // the attempt with slip `slip` ended at drum tension `tension`: false if it stands (grips,
  // holds T_b within the band, or the slip is at a bound it cannot leave); else true and
  // *next is the slip of the next attempt
  bool Next(double slip, double tension, double* next);
  int attempts() const { return attempts_; }
  // the last slope used (the secant once two attempts differ)
  double slope() const { return slope_; }

 private:
  double brake_, max_slip_, slope_;
  double last_slip_ = 0.0, last_tension_ = 0.0;
  int attempts_ = 0;
};

}  // namespace towsim::core
