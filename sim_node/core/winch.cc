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
                       double speed, double slip_speed, double h) {
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
  // the brake's slip over the step, solved with the step (winch.h, BrakeSlipIteration)
  if (slip_speed > 0.0) {
    s.slip_speed = slip_speed;
    s.slipping = true;
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

bool BrakeSlipIteration::Next(double slip, double tension, double* next) {
  ++attempts_;
  const double excess = tension - brake_;
  if (slip <= 0.0 && excess <= 0.0) return false;                      // the drum grips
  if (std::abs(excess) <= kBrakeTensionRelTol * brake_) return false;  // it holds T_b
  if (attempts_ >= kMaxBrakeAttempts) return false;
  // dT/ds: the first slope, then the secant of the last two attempts (where it is a falling
  // one: more slip, less tension)
  if (attempts_ > 1 && slip != last_slip_) {
    const double secant = (tension - last_tension_) / (slip - last_slip_);
    if (secant < 0.0) slope_ = secant;
  }
  last_slip_ = slip;
  last_tension_ = tension;
  const double s = std::clamp(slip - excess / slope_, 0.0, max_slip_);
  if (s == slip) return false;  // at a bound it cannot leave
  *next = s;
  return true;
}

}  // namespace towsim::core
