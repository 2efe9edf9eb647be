#pragma once
// Towfish depth hold with the elevators, a pure function (no DDS). Depth z is world NED (down
// positive). A positive elevator pushes the stern down, the bow up: the towfish rises
// (measured in the Case 2 run at 6 m/s, 75..100 s: elevator +10 deg holds it at ~19 m, 0 at
// ~22 m, -10 deg at ~37 m). So the elevator is sign * PID on e = commanded - depth (too
// shallow: e > 0 -> "deeper" demand), sign = -1 (deeper = negative elevator), with the
// derivative on the measured depth rate, anti-windup, saturation to the elevator's travel and
// its rate limit. While the fish hangs steeply (|pitch| > max_pitch: launch from rest, being
// hauled up by the cable) the fins are stalled or nearly so and only slow it down (measured:
// any elevator from 0 to 55 s leaves it deeper than 0): the law commands 0 and resets the
// PID, which engages once the fish is towed level. `hold` mode commands 0 (the uncontrolled
// reference).

#include "common/laws.h"

namespace towsim::controllers {

struct DepthParams {
  double depth = 25.0;  // commanded depth [m]
  // tuned on the Case 2 U-turn at 6 m/s (tests/integration/controllers_integration_test.cc)
  double kp = 0.15;     // [rad/m]
  double ki = 0.01;     // [rad/(m s)]
  double kd = 0.5;      // [rad/(m/s)]
  double max_elevator = Rad(25.0);  // [rad], within the fin's 30 deg
  double rate_limit = Rad(20.0);    // [rad/s], the fin's max rate
  double max_pitch = Rad(30.0);     // [rad], engaged below
  double sign = -1.0;               // -1: positive elevator makes the body rise
  bool hold = false;                // command zero elevator
};

// the elevator [rad] answering depth z [m], depth rate z_dot [m/s] (world) and pitch [rad],
// step dt [s]
double DepthStep(const DepthParams& p, PidState& state, double z, double z_dot, double pitch,
                 double dt);

}  // namespace towsim::controllers
