#include "autopilot/autopilot_law.h"

#include <algorithm>
#include <cmath>

namespace towsim::controllers {

double RateLimit(double x, double target, double rate, double dt) {
  if (!(rate > 0.0)) return target;
  const double step = rate * dt;
  return std::clamp(target, x - step, x + step);
}

AutopilotCommand AutopilotStep(const AutopilotGains& g, AutopilotState& s,
                               const AutopilotSetpoint& sp, const AutopilotMeasurement& m,
                               double dt) {
  AutopilotCommand c;
  // speed: feedforward of the towed system's drag plus a PID within the remaining range
  const double ff = g.thrust_ff * sp.speed * std::abs(sp.speed);
  PidParams speed = g.speed;
  speed.out_min = g.speed.out_min - ff;
  speed.out_max = g.speed.out_max - ff;
  speed.rate_limit = 0.0;  // on the total, below
  const double error = sp.speed - m.u;
  const double integral_before = s.speed.integral;
  const double total = ff + PidStep(speed, s.speed, error, 0.0, dt);
  const double limited = std::clamp(total, g.speed.out_min, g.speed.out_max);
  c.thrust = RateLimit(s.initialized ? s.thrust : 0.0, limited, g.thrust_rate, dt);
  // anti-windup through the rate limit too: while the ramp holds the thrust back in the
  // direction the error pushes, the integral does not grow (else it overshoots after the ramp)
  if (c.thrust != limited && (limited - c.thrust) * error > 0.0) {
    s.speed.integral = integral_before;
  }
  s.thrust = c.thrust;
  s.initialized = true;
  // heading: the error the short way round
  c.rudder = PidStep(g.heading, s.heading, WrapPi(sp.heading - m.yaw), m.r, dt);
  // depth: "deeper" demand on e = z_d - z, mapped to the elevator by its sign
  if (g.depth_enabled) {
    const double deeper = PidStep(g.depth, s.depth, sp.depth - m.z, m.z_dot, dt);
    c.elevator = g.depth_sign >= 0.0 ? deeper : -deeper;
  }
  return c;
}

}  // namespace towsim::controllers
