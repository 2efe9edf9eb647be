#pragma once
// The paper's Case 2 (U-turn) as a pure decision on the live state (no DDS): thrust T all
// along; from t >= start the rudder at `rudder` until the yaw first reaches `until_yaw`, then
// 0 for the rest of the run (latched: the yaw wrapping past 180 deg does not restart the turn).

namespace towsim::controllers {

struct UTurnParams {
  double thrust = 4165.0;  // [N]
  double rudder = 0.0;     // [rad], positive turns the bow to starboard (yaw increasing)
  double start = 55.0;     // [s]
  double until_yaw = 0.0;  // [rad], in (-pi, pi]
};

struct UTurnState {
  bool turned = false;  // the yaw reached until_yaw: rudder back to 0 for good
};

struct ManeuverCommand {
  double thrust = 0.0, rudder = 0.0, elevator = 0.0;
};

// the command answering the state at time t [s] with yaw [rad] (in (-pi, pi]); the script's
// rule: times to 1e-9 s, the yaw condition is checked on the state reached
ManeuverCommand UTurnStep(const UTurnParams& p, UTurnState& state, double t, double yaw);

}  // namespace towsim::controllers
