#include "towfish_depth/depth_law.h"

#include <cmath>

namespace towsim::controllers {

double DepthStep(const DepthParams& p, PidState& state, double z, double z_dot, double pitch,
                 double dt) {
  if (p.hold) return 0.0;
  if (std::abs(pitch) > p.max_pitch) {
    state = PidState{};
    return 0.0;
  }
  PidParams pid;
  pid.kp = p.kp;
  pid.ki = p.ki;
  pid.kd = p.kd;
  pid.out_min = -p.max_elevator;
  pid.out_max = p.max_elevator;
  pid.rate_limit = p.rate_limit;
  // "deeper" demand: e = commanded - z, the measurement z, its rate z_dot; the limits are
  // symmetric, so the sign applied to the output keeps saturation, rate limit, anti-windup
  const double deeper = PidStep(pid, state, p.depth - z, z_dot, dt);
  return p.sign >= 0.0 ? deeper : -deeper;
}

}  // namespace towsim::controllers
