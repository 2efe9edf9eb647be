#include "towfish_depth/winch_law.h"

#include <algorithm>
#include <cmath>

namespace towsim::controllers {

double WinchDepthStep(const WinchDepthParams& p, WinchDepthState& s, double target, double z,
                      double deeper, double dt) {
  const double e = target - z + p.elevator_depth * deeper;
  if (!s.initialized) {
    s.initialized = true;
    s.error = e;
    s.speed = 0.0;
  }
  // s_f' = (s - s_f) / T_f, exact for s held over the step
  s.error += (e - s.error) * (1.0 - std::exp(-dt / p.filter));
  double v = 0.0;
  if (s.error > p.deadband) v = p.gain * (s.error - p.deadband);
  if (s.error < -p.deadband) v = p.gain * (s.error + p.deadband);
  v = std::clamp(v, -p.max_speed, p.max_speed);
  const double dv = p.max_acceleration * dt;
  s.speed = std::clamp(v, s.speed - dv, s.speed + dv);
  return s.speed;
}

}  // namespace towsim::controllers
