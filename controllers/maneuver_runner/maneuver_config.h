#pragma once
// What the manoeuvre runner plays: the manoeuvre and its parameters, from the command line
// and / or a YAML file (config/maneuvers/*.yaml). Precedence: the manoeuvre's defaults, then
// the file (--config FILE), then the flags. File keys (flat map, unknown keys rejected):
//   maneuver: case1 | uturn | zigzag | turning_circle
//   body, thrust [N], start [s], rudder_deg, heading_deg (zig-zag switch angle),
//   until_yaw_deg (U-turn), until_turn_deg (turning circle, 0: hold to the end),
//   reversals (zig-zag), port_first (zig-zag / turning circle: first rudder to port)
// Flags: --maneuver, --config, --body, --thrust, --start, --rudder-deg, --heading-deg,
// --until-yaw-deg, --until-turn-deg, --reversals, --port-first, --results FILE.
// Defaults: case1 (rudder 0), uturn (20 deg until yaw 170 deg), zigzag (10/10, 4 reversals),
// turning_circle (20 deg held); thrust 4165 N, start 55 s (the paper's cases).

#include <string>
#include <vector>

#include "common/flags.h"

namespace towsim::controllers {

enum class ManeuverKind { kCase1, kUTurn, kZigZag, kTurningCircle };

const char* ManeuverName(ManeuverKind kind);

struct ManeuverConfig {
  ManeuverKind kind = ManeuverKind::kUTurn;
  std::string body = "tow_vehicle";
  double thrust = 4165.0;        // [N]
  double start = 55.0;           // execute time [s]
  double rudder_deg = 20.0;      // [deg]; U-turn: signed; zig-zag, turning circle: magnitude
  double heading_deg = 10.0;     // zig-zag switch angle [deg]
  double until_yaw_deg = 170.0;  // U-turn end [deg]
  double until_turn_deg = 0.0;   // turning circle: rudder 0 after this heading change [deg]
  int reversals = 4;             // zig-zag
  bool port_first = false;
  std::string results;  // --results FILE ("" : none)
};

// the flags of the runner that take a value / are switches (DDS flags included)
std::vector<std::string> ManeuverFlagNames();
std::vector<std::string> ManeuverSwitchNames();

// resolves defaults, file and flags; throws ConfigError or std::runtime_error naming the key
// or flag, its value and the rule (the runner exits 2)
ManeuverConfig ResolveManeuver(const Flags& flags);

}  // namespace towsim::controllers
