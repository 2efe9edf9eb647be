#include "core/winch.h"

#include <algorithm>
#include <cmath>

#include "core/model.h"

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

int WinchMaxNodes(const CableParams& cable) {
  const double element = cable.length / cable.elements;
  return static_cast<int>(std::ceil(cable.winch->max_length / element)) + 2;
}

namespace {

// the largest speed at the step's end toward a stop point d >= 0 ahead, moving toward it at v
// now, from which the drum can still stop there braking at a (winch.h)
double StoppingSpeed(double a, double h, double d, double v) {
  const double c = 2.0 * a * d - a * h * v;
  if (c <= 0.0) return 0.0;
  return 0.5 * (-a * h + std::sqrt(a * a * h * h + 4.0 * c));
}

}  // namespace

WinchStep AdvanceWinch(const WinchParams& p, const WinchCommand& command, double length,
                       double speed, double slip_speed, double tension, double slip_compliance,
                       double h) {
  // `speed`: the drive's (winch.h)
  WinchCommand c = command;
  ClampWinchCommand(p, &c);
  const double a = p.max_acceleration;
  const double L = length, V = speed;
  // the speed wanted, within the limits, and what the stop points ahead allow
  double upper = std::min(p.max_speed, StoppingSpeed(a, h, p.max_length - L, V));
  double lower = -std::min(p.max_speed, StoppingSpeed(a, h, L - p.min_length, -V));
  double wanted = c.value;
  if (c.mode == WinchCommand::Mode::kLength) {
    wanted = c.value > L ? p.max_speed : (c.value < L ? -p.max_speed : 0.0);
    if (c.value >= L) upper = std::min(upper, StoppingSpeed(a, h, c.value - L, V));
    if (c.value <= L) lower = std::max(lower, -StoppingSpeed(a, h, L - c.value, -V));
  }
  const double desired = std::clamp(wanted, std::min(lower, upper), upper);
  WinchStep s;
  s.speed = V + std::clamp(desired - V, -a * h, a * h);
  s.length = L + 0.5 * h * (V + s.speed);
  // a stop point reached at a speed the drum stops from within a step: exactly there, at rest
  auto land = [&](double point) {
    const bool crossed = (L - point) * (s.length - point) <= 0.0 && s.length != L;
    if (crossed && std::abs(s.speed) <= a * h * (1.0 + 1e-12)) {
      s.length = point;
      s.speed = 0.0;
    }
  };
  if (c.mode == WinchCommand::Mode::kLength) land(c.value);
  s.drive_speed = s.speed;
  // the brake: the slip integrates the tension's excess over it (winch.h)
  if (std::isfinite(p.brake_tension)) {
    s.slip_speed =
        std::max(0.0, slip_speed + (tension - p.brake_tension) * slip_compliance / h);
    s.slipping = s.slip_speed > 0.0;
    s.speed += s.slip_speed;
    s.length += h * s.slip_speed;
  }
  // the drum's ends: the cable is fully reeled in or paid out
  if (s.length >= p.max_length) {
    s.length = p.max_length;
    s.speed = s.drive_speed = s.slip_speed = 0.0;
  } else if (s.length <= p.min_length) {
    s.length = p.min_length;
    s.speed = s.drive_speed = s.slip_speed = 0.0;
  }
  return s;
}

}  // namespace towsim::core
