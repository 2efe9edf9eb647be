#pragma once
// script: offline commands for the vehicles, each fired once, at a time and optionally when a
// condition on a vehicle's state holds:
//   - {at: 55, when: "tow_vehicle.yaw_deg >= 170", body: tow_vehicle, rudder_deg: 0}
// and the winch (cable.winch; docs/winch.md), with or without a body:
//   - {at: 10, winch_speed: 1.0}     dL/dt [m/s], + pays out, |V| <= max_speed
//   - {at: 200, winch_length: 150}   drive to L [m], min_length <= L <= max_length
// and a vessel's course (docs/vessels.md): {at: 60, body: ship, speed: 2.5},
//   {at: 100, body: ship, heading_deg: 90, turn_rate_deg: 1}, {at: 100, body: ship, turn_rate_deg: 1}

#include <string>
#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads the script list (absent: empty) against the scene's bodies and vehicles in `model`;
// the entries on a vessel ({at, body, speed}, {at, body, heading_deg, turn_rate_deg},
// {at, body, turn_rate_deg}) go to its course (core::Vessel::course, in script order).
std::vector<core::ScriptEntry> ReadScript(const Field& script, core::Model* model);

// Parses `<vehicle>.<quantity> <op> <number>` (the value of `field`, e.g. script[3].when);
// quantity one of x, y, z, roll_deg, pitch_deg, yaw_deg, u, v, w, p, q, r, speed and op one of
// >=, <=, >, <. Throws ConfigError saying what is wrong.
core::ScriptCondition ReadCondition(const Field& field, const core::Model& model);

}  // namespace towsim::scene::internal
