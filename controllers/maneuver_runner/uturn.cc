#include "maneuver_runner/uturn.h"

namespace towsim::controllers {

ManeuverCommand UTurnStep(const UTurnParams& p, UTurnState& s, double t, double yaw) {
  ManeuverCommand c;
  c.thrust = p.thrust;
  if (t < p.start - 1e-9) return c;
  // a starboard turn (rudder > 0) ends once yaw >= until_yaw; a port turn once yaw <= it
  if (!s.turned) {
    const bool reached = p.rudder >= 0.0 ? yaw >= p.until_yaw : yaw <= p.until_yaw;
    if (reached) s.turned = true;
  }
  c.rudder = s.turned ? 0.0 : p.rudder;
  return c;
}

}  // namespace towsim::controllers
