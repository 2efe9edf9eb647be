#include "core/winch.h"

namespace towsim::core {

Actuator WinchSpeedRange(const WinchParams& p) {
  Actuator a;
  a.min = -p.max_speed;
  a.max = p.max_speed;
  a.max_rate = p.max_acceleration;
  return a;
}

Actuator WinchLengthRange(const WinchParams& p) {
  Actuator a;
  a.min = p.min_length;
  a.max = p.max_length;
  a.max_rate = p.max_speed;
  return a;
}

Actuator WinchCommandRange(const WinchParams& p, WinchCommand::Mode mode) {
  return mode == WinchCommand::Mode::kSpeed ? WinchSpeedRange(p) : WinchLengthRange(p);
}

bool ClampWinchCommand(const WinchParams& p, WinchCommand* command) {
  return WinchCommandRange(p, command->mode).Clamp(&command->value);
}

}  // namespace towsim::core
