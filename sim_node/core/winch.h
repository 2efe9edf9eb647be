#pragma once
// The winch at the cable's start (docs/winch.md): its limits (Model::cable.winch), its command
// (an input, like VehicleCommand) and the limits an incoming command is checked against.
//
// The drum pays out (dL/dt > 0) or reels in (dL/dt < 0) the unstretched cable length L within
//   min_length <= L <= max_length,  |dL/dt| <= max_speed,  |d2L/dt2| <= max_acceleration;
// a speed command V drives dL/dt to V, a length command drives L to the target and stops there.
// Above brake_tension the drum slips and pays out.

#include <limits>

#include "core/actuator.h"

namespace towsim::core {

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

}  // namespace towsim::core
