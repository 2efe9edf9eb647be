#pragma once
// Towfish depth hold with the elevators, a pure function (no DDS). Depth z is world NED (down
// positive). A positive elevator pushes the stern down, the bow up: the fish rises. So the
// elevator is minus a PID on the depth error e = depth - commanded (too deep: e > 0 -> bow up),
// with the derivative on the measured depth rate, anti-windup, saturation to the elevator's
// travel and its rate limit. `hold` mode commands 0 (the uncontrolled reference).

#include "common/laws.h"

namespace towsim::controllers {

struct DepthParams {
  double depth = 25.0;  // commanded depth [m]
  double kp = 0.08;     // [rad/m]
  double ki = 0.004;    // [rad/(m s)]
  double kd = 0.25;     // [rad/(m/s)]
  double max_elevator = Rad(25.0);  // [rad], within the fin's 30 deg
  double rate_limit = Rad(20.0);    // [rad/s], the fin's max rate
  bool hold = false;                // command zero elevator
};

// the elevator [rad] answering depth z [m] and depth rate z_dot [m/s] (world), step dt [s]
double DepthStep(const DepthParams& p, PidState& state, double z, double z_dot, double dt);

}  // namespace towsim::controllers
