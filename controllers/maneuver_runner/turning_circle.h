#pragma once
// The turning circle of the IMO / ITTC manoeuvring trials (ITTC 7.5-04-02-01 §2.2; IMO
// MSC.137(76)) as a pure decision on the live heading and a pure trials sheet from the track
// (no DDS). Thrust T all along; at t >= start the rudder goes to delta and is held until the
// heading has changed by `until_turn` (<= 0: to the end of the run), then 0.
// The sheet, in the frame of the approach course at execute (origin p_0 = the position at
// execute, heading psi_0; NED: the course direction is (cos psi_0, sin psi_0)):
//   advance   (p - p_0) . (cos psi_0, sin psi_0)   when the heading has changed by 90 deg
//   transfer  (p - p_0) . (-sin psi_0, cos psi_0)  at 90 deg (> 0 to starboard)
//   tactical diameter: the transfer at 180 deg
// (each linearly interpolated between the two samples around the angle); the steady turning
// diameter: a least-squares circle (Kasa's algebraic fit) through the track once the heading
// has changed by `steady_from` (360 deg by default) and covering at least 180 deg more; the
// steady speed and yaw rate over the same window, and 2 U / r as a kinematic check.

#include <vector>

#include "maneuver_runner/uturn.h"

namespace towsim::controllers {

struct TurningCircleParams {
  double thrust = 4165.0;              // [N]
  double rudder = 0.3490658503988659;  // delta [rad], sign: + starboard
  double start = 55.0;                 // execute time [s]
  double until_turn = 0.0;             // heading change [rad] after which rudder 0; <= 0: never
};

struct TurningCircleState {
  bool started = false, ended = false;
  double last_yaw = 0.0, change = 0.0;  // unwrapped heading change since execute [rad]
};

// the command answering the state at time t [s] with heading yaw [rad]
ManeuverCommand TurningCircleStep(const TurningCircleParams& p, TurningCircleState& state, double t,
                                  double yaw);

// the track and the sheet
struct TrackSample {
  double t = 0, x = 0, y = 0, yaw = 0, speed = 0, yaw_rate = 0;  // [s, m, m, rad, m/s, rad/s]
};

struct TurningCircleResults {
  bool has_90 = false, has_180 = false, has_steady = false;
  double t_execute = 0.0;
  double advance = 0.0, transfer = 0.0, time_90 = 0.0;  // [m, m, s after execute]
  double tactical_diameter = 0.0, time_180 = 0.0;       // [m, s]
  double steady_diameter = 0.0;                         // least-squares circle [m]
  double steady_center_x = 0.0, steady_center_y = 0.0;  // [m]
  double steady_speed = 0.0, steady_yaw_rate = 0.0;     // means over the window [m/s, rad/s]
  double kinematic_diameter = 0.0;                      // 2 U / |r| [m]
  double total_turn = 0.0;                              // heading change reached [rad]
};

// `track` in time order from the execute sample on (its first sample is the execute state)
TurningCircleResults TurningCircleSheet(const std::vector<TrackSample>& track,
                                        double steady_from = 6.283185307179586);

// Kasa's fit: the circle minimizing sum (x^2 + y^2 + D x + E y + F)^2; false if degenerate
bool FitCircle(const std::vector<double>& x, const std::vector<double>& y, double* cx, double* cy,
               double* radius);

}  // namespace towsim::controllers
