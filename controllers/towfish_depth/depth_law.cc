#include "towfish_depth/depth_law.h"

namespace towsim::controllers {

double DepthStep(const DepthParams& p, PidState& state, double z, double z_dot, double dt) {
  if (p.hold) return 0.0;
  PidParams pid;
  pid.kp = p.kp;
  pid.ki = p.ki;
  pid.kd = p.kd;
  pid.out_min = -p.max_elevator;
  pid.out_max = p.max_elevator;
  pid.rate_limit = p.rate_limit;
  // "bow up" demand u: positive when too deep; the measurement is the depth, so the
  // derivative-on-measurement term uses +z_dot (e = z - depth rises with z)
  return PidStep(pid, state, z - p.depth, -z_dot, dt);
}

}  // namespace towsim::controllers
