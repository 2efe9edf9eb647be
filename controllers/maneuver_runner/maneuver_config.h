#pragma once
// What the manoeuvre runner plays: the manoeuvre and its parameters, from the command line
// and / or a YAML file (config/maneuvers/*.yaml). Precedence: the manoeuvre's defaults, then
// the file (--config FILE), then the flags. File keys (flat map, unknown keys rejected):
//   maneuver: case1 | uturn | zigzag | turning_circle | payout
//   body, thrust [N], start [s], rudder_deg, heading_deg (zig-zag switch angle),
//   until_yaw_deg (U-turn), until_turn_deg (turning circle, 0: hold to the end),
//   reversals (zig-zag), port_first (zig-zag / turning circle: first rudder to port),
//   payout (maneuver_runner/payout.h): tow_speed [m/s], from_length, to_length [m],
//   payout_rate [m/s], hold [s], towfish (the body whose depth the sheet reports),
//   sample_period [s] (the sheet's table); thrust is then the speed hold's limit
// Flags: --maneuver, --config, --body, --thrust, --start, --rudder-deg, --heading-deg,
// --until-yaw-deg, --until-turn-deg, --reversals, --port-first, --tow-speed, --from-length,
// --to-length, --payout-rate, --hold, --towfish, --sample-period, --results FILE,
// --plot FILE.svg (payout: the depth against time and length).
// Defaults: case1 (rudder 0), uturn (20 deg until yaw 170 deg), zigzag (10/10, 4 reversals),
// turning_circle (20 deg held); thrust 4165 N, start 55 s (the paper's cases); payout: 150 m
// to 250 m at 1 m/s while towing at 3 m/s, from t = 100 s, hold 100 s, then back to 150 m.

#include <string>
#include <vector>

#include "common/flags.h"

namespace towsim::controllers {

enum class ManeuverKind { kCase1, kUTurn, kZigZag, kTurningCircle, kPayout };

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
  // payout (maneuver_runner/payout.h)
  double tow_speed = 3.0;      // [m/s]
  double from_length = 150.0;  // [m]
  double to_length = 250.0;    // [m]
  double payout_rate = 1.0;    // [m/s]
  double hold = 100.0;         // [s]
  std::string towfish = "towfish";
  double sample_period = 10.0;  // [s]
  std::string results;  // --results FILE ("" : none)
  std::string plot;     // --plot FILE.svg ("" : none; payout only)
};

// the flags of the runner that take a value / are switches (DDS flags included)
std::vector<std::string> ManeuverFlagNames();
std::vector<std::string> ManeuverSwitchNames();

// resolves defaults, file and flags; throws ConfigError or std::runtime_error naming the key
// or flag, its value and the rule (the runner exits 2)
ManeuverConfig ResolveManeuver(const Flags& flags);

}  // namespace towsim::controllers
