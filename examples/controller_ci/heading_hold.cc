#include "heading_hold.h"

#include <algorithm>

#include "common/laws.h"

namespace controller_ci {

towsim::controllers::Actuation HeadingHold(const HeadingHoldParams& p,
                                           const towsim::controllers::BodyState& s) {
  const double target = s.t >= p.heading_from - 1e-9 ? p.heading : p.initial_heading;
  // e = wrap(psi_d - psi)
  const double e = towsim::controllers::WrapPi(target - s.yaw);
  towsim::controllers::Actuation a;
  a.thrust = p.thrust;
  a.rudder = std::clamp(p.kp * e - p.kd * s.r, -p.max_rudder, p.max_rudder);
  return a;
}

}  // namespace controller_ci
