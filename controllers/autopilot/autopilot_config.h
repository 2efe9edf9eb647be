#pragma once
// The autopilot's configuration from a YAML file (--config, config/autopilot/*.yaml) and
// flags (flags win). File keys (flat map; unknown keys rejected with file:line):
//   body                              the vehicle (tow_vehicle)
//   speed [m/s], heading_deg, depth   setpoints from t = 0 (depth: enables the depth loop)
//   schedule: [{at: s, speed: .., heading_deg: .., depth: ..}, ...]   setpoint changes
//   waypoints: [{x: m, y: m}, ...]    waypoint following (LOS) instead of heading_deg
//   survey_origin: [x, y], survey_heading_deg, survey_leg_length, survey_spacing,
//   survey_legs, survey_turn (starboard | port)   a lawn-mower pattern (guidance.h)
//   lookahead, acceptance_radius [m]
//   speed_kp, speed_ki, thrust_ff, thrust_rate, max_thrust, min_thrust,
//   heading_kp, heading_ki, heading_kd, max_rudder_deg, rudder_rate_deg,
//   depth_kp, depth_ki, depth_kd, max_elevator_deg, elevator_rate_deg, elevator_sign
// Flags: --config, --body, --speed, --heading-deg, --depth, --survey-origin X,Y,
// --survey-heading-deg, --leg-length, --spacing, --legs, --turn, --lookahead,
// --acceptance-radius, --heading-kp/-ki/-kd, --speed-kp/-ki, --log FILE.

#include <string>
#include <vector>

#include "autopilot/autopilot_law.h"
#include "autopilot/guidance.h"
#include "common/flags.h"

namespace towsim::controllers {

struct SetpointChange {
  double at = 0.0;  // [s]
  bool has_speed = false, has_heading = false, has_depth = false;
  double speed = 0.0, heading = 0.0, depth = 0.0;  // [m/s, rad, m]
};

struct AutopilotConfig {
  std::string body = "tow_vehicle";
  AutopilotGains gains;
  AutopilotSetpoint initial;
  std::vector<SetpointChange> schedule;  // in time order
  bool follow_waypoints = false;
  std::vector<Waypoint> waypoints;
  double lookahead = 60.0, acceptance_radius = 30.0;  // [m]
  std::string log;                                    // --log FILE
};

std::vector<std::string> AutopilotFlagNames();
std::vector<std::string> AutopilotSwitchNames();

// throws ConfigError / std::runtime_error naming the key or flag, the value and the rule
AutopilotConfig ResolveAutopilot(const Flags& flags);

// the setpoint in force at time t [s] (the schedule applied on top of `initial`)
AutopilotSetpoint SetpointAt(const AutopilotConfig& c, double t);

}  // namespace towsim::controllers
