#pragma once
// A heading-hold controller for towsim's tow vehicle: constant thrust, rudder from a PD law on
// the heading error,
//   rudder = clamp(kp * e - kd * r, -max_rudder, max_rudder),  e = wrap(psi_d - psi),
// with psi the yaw (ZYX, world NED: 0 north, +90 deg east) and r the yaw rate. Positive rudder
// turns the bow to starboard (yaw increases), so a positive error asks for positive rudder.
// The law is a pure function of the body state: the same states give the same commands.

#include "common/client.h"

namespace controller_ci {

struct HeadingHoldParams {
  double heading = 0.0;          // psi_d, commanded from t >= heading_from [rad]
  double heading_from = 0.0;     // [s]
  double initial_heading = 0.0;  // psi_d before heading_from [rad]
  double thrust = 4165.0;        // [N] (Case 1's calibrated 6 m/s)
  double kp = 1.0;               // [rad rudder / rad error]
  double kd = 2.0;               // [s]
  double max_rudder = 0.436;     // [rad] (25 deg)
};

towsim::controllers::Actuation HeadingHold(const HeadingHoldParams& p,
                                           const towsim::controllers::BodyState& s);

}  // namespace controller_ci
