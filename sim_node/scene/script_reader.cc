#include "scene/script_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "scene/body_reader.h"
#include "scene/vehicle_reader.h"

namespace towsim::scene::internal {
namespace {

using Condition = core::ScriptCondition;

constexpr const char* kConditionForm =
    "<vehicle>.<quantity> <op> <number>, e.g. tow_vehicle.yaw_deg >= 170";

// quantity names, in the order of ScriptCondition::Quantity
const std::vector<std::string>& QuantityNames() {
  static const std::vector<std::string> kNames = {
      "x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg", "u", "v", "w", "p", "q", "r", "speed"};
  return kNames;
}

std::string Join(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

std::string VehicleNames(const core::Model& model) {
  std::string names;
  for (const core::Vehicle& v : model.vehicles) names += (names.empty() ? "" : ", ") + v.name;
  return names.empty() ? "none" : names;
}

}  // namespace

core::ScriptCondition ReadCondition(const Field& field, const core::Model& model) {
  const std::string text = Trim(field.String());
  if (text.empty()) field.Fail(std::string("must be a condition ") + kConditionForm);

  // the comparison: the first < or >, with an optional =
  const size_t at = text.find_first_of("<>");
  if (at == std::string::npos) {
    field.Fail(std::string("has no comparison (>=, <=, >, <); the form is ") + kConditionForm);
  }
  const bool or_equal = at + 1 < text.size() && text[at + 1] == '=';
  const std::string op = text.substr(at, or_equal ? 2 : 1);
  const std::string left = Trim(text.substr(0, at));
  const std::string right = Trim(text.substr(at + op.size()));
  if (!left.empty() && (left.back() == '=' || left.back() == '!')) {
    field.Fail("unknown comparison " + left.substr(left.size() - 1) + op +
               "; use one of >=, <=, >, <");
  }
  Condition c;
  c.op = op == ">="   ? Condition::kGreaterEqual
         : op == "<=" ? Condition::kLessEqual
         : op == ">"  ? Condition::kGreater
                      : Condition::kLess;

  // <vehicle>.<quantity>
  const size_t dot = left.find('.');
  if (left.empty() || dot == std::string::npos) {
    field.Fail("needs <vehicle>.<quantity> before " + op + "; the form is " + kConditionForm);
  }
  const std::string vehicle = left.substr(0, dot);
  const std::string quantity = left.substr(dot + 1);
  const BodyRef ref = FindBody(model, vehicle);
  if (ref.kind == BodyRef::kNone) {
    field.Fail("no vehicle named " + vehicle + " (vehicles: " + VehicleNames(model) + ")");
  }
  if (ref.kind == BodyRef::kSphere || ref.kind == BodyRef::kVessel) {
    field.Fail(vehicle + (ref.kind == BodyRef::kSphere ? " is a sphere" : " is a vessel") +
               "; conditions are on vehicles (vehicles: " + VehicleNames(model) + ")");
  }
  c.vehicle = ref.index;
  const std::vector<std::string>& names = QuantityNames();
  const auto it = std::find(names.begin(), names.end(), quantity);
  if (it == names.end()) {
    const std::string suggestion = Suggestion(quantity, names);
    field.Fail("unknown quantity " + quantity +
               (suggestion.empty() ? "" : "; did you mean " + suggestion + "?") +
               " (quantities: " + Join(names) + ")");
  }
  c.quantity = static_cast<Condition::Quantity>(it - names.begin());

  // the number: finite, nothing after it
  double value = 0.0;
  const char* end = right.data() + right.size();
  const auto [ptr, ec] = std::from_chars(right.data(), end, value);
  if (right.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    field.Fail("needs a finite number after " + op + ", not '" + right + "'; the form is " +
               kConditionForm);
  }
  c.value = value;
  return c;
}

namespace {

// a vessel's course entry {at, body, speed} / {at, body, heading_deg, turn_rate_deg} /
// {at, body, turn_rate_deg} (docs/vessels.md "Course")
core::CourseChange ReadCourseChange(const MapReader& map, const core::Vessel& vessel) {
  const Field& item = map.field();
  for (const auto& [key, value] : map.entries()) {
    if (key == "at" || key == "body" || key == "speed" || key == "heading_deg" ||
        key == "turn_rate_deg")
      continue;
    value.Fail("does not apply to a vessel (" + vessel.name +
               "): its entries are {at, body, speed}, {at, body, heading_deg, turn_rate_deg} "
               "or {at, body, turn_rate_deg}");
  }
  if (vessel.time_history || vessel.external) {
    item.Fail(vessel.name + " takes its motion from " +
              (vessel.time_history ? "its time_history" : "another program (external: true)") +
              ", so the script cannot change its course");
  }
  core::CourseChange c;
  c.at = map.Number("at", Range::AtLeast(0.0), 0.0);
  if (map.Has("speed")) {
    c.set_speed = true;
    c.speed = map.Get("speed").Number();
  }
  if (map.Has("turn_rate_deg")) {
    c.set_turn_rate = true;
    c.turn_rate = kDegToRad * map.Get("turn_rate_deg").Number();
  }
  if (map.Has("heading_deg")) {
    if (!map.Has("turn_rate_deg")) {
      map.Get("heading_deg")
          .Fail("needs turn_rate_deg, the rate of the turn to it [deg/s] (> 0)");
    }
    c.set_heading = true;
    c.heading = kDegToRad * map.Get("heading_deg").Number();
    if (!(c.turn_rate > 0.0))
      map.Get("turn_rate_deg").Fail("must be > 0 with heading_deg (the turn takes the shorter way)");
  }
  if (!c.set_speed && !c.set_turn_rate) {
    item.Fail("gives no course change; give speed, heading_deg with turn_rate_deg, or "
              "turn_rate_deg");
  }
  return c;
}

// the winch a script entry's winch_speed / winch_length (`value`) commands: its `winch:`,
// or the scene's one winch (winch w on cable w, core/model.h)
int WinchIndex(const MapReader& map, const core::Model& model, const Field& value) {
  std::vector<std::string> names;
  for (const core::CableParams& c : model.cables)
    if (c.winch) names.push_back(c.winch->name);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  if (!map.Has("winch")) {
    if (names.size() > 1)
      value.Fail("needs winch: <name>, the scene has " + std::to_string(names.size()) +
                 " winches (" + list + ")");
    return 0;
  }
  const Field winch = map.Get("winch");
  const std::string name = winch.String();
  for (size_t w = 0; w < names.size(); ++w)
    if (names[w] == name) return static_cast<int>(w);
  winch.Fail("no such winch (winches: " + list + ")");
  return 0;
}

// the scene key of winch w's limits: cable.winch, or cables.<c>.winch in a network
std::string WinchKey(const core::Model& model, int w) {
  return model.cables.size() == 1 && model.cables[0].name == "cable"
             ? std::string("cable.winch")
             : "cables." + model.cables[w].name + ".winch";
}

}  // namespace

std::vector<core::ScriptEntry> ReadScript(const Field& field, core::Model* vessels_model) {
  const core::Model& model = *vessels_model;
  std::vector<core::ScriptEntry> script;
  for (const Field& item : field.Items()) {
    const MapReader map(item, MapKind::kScriptEntry);
    // a vessel's entries change its course (core::Vessel::course), not a command
    if (map.Has("body")) {
      const BodyRef ref = FindBody(model, map.Get("body").String());
      if (ref.kind == BodyRef::kVessel) {
        if (map.Has("when")) map.Get("when").Fail("a vessel's course entries fire at `at`; no when");
        core::Vessel& vessel = vessels_model->vessels[ref.index];
        vessel.course.push_back(ReadCourseChange(map, vessel));
        continue;
      }
    }
    for (const char* key : {"speed", "heading_deg", "turn_rate_deg"})
      if (map.Has(key)) map.Get(key).Fail("applies only to a vessel's entry (body: <vessel>)");
    core::ScriptEntry entry;
    entry.at = map.Number("at", Range::AtLeast(0.0), 0.0);
    if (map.Has("when")) {
      entry.has_condition = true;
      entry.condition = ReadCondition(map.Get("when"), model);
    }

    // the winch: a speed or a length, not both, within its limits; `winch: <name>` names it
    // (may be left out when the scene has one winch)
    if (map.Has("winch") && !map.Has("winch_speed") && !map.Has("winch_length")) {
      map.Get("winch").Fail("names the winch of a winch_speed or winch_length; give one");
    }
    if (map.Has("winch_speed") || map.Has("winch_length")) {
      if (map.Has("winch_speed") && map.Has("winch_length")) {
        map.Get("winch_length").Fail("give winch_speed or winch_length, not both");
      }
      const bool speed = map.Has("winch_speed");
      const Field f = map.Get(speed ? "winch_speed" : "winch_length");
      if (!model.cables[0].winch) f.Fail("the scene has no cable.winch");
      entry.winch_index = WinchIndex(map, model, f);
      const core::WinchParams& w = *model.cables[entry.winch_index].winch;
      entry.set_winch = true;
      if (speed) {
        entry.winch.mode = core::WinchCommand::Mode::kSpeed;
        entry.winch.value = f.Number();
        if (std::abs(entry.winch.value) > w.max_speed) {
          f.Fail("must be within +-" + WinchKey(model, entry.winch_index) + ".max_speed = " +
                 FormatNumber(w.max_speed));
        }
      } else {
        entry.winch.mode = core::WinchCommand::Mode::kLength;
        entry.winch.value = f.Number();
        if (entry.winch.value < w.min_length || entry.winch.value > w.max_length) {
          f.Fail("must be within " + WinchKey(model, entry.winch_index) +
                 " [min_length, max_length] = [" +
                 FormatNumber(w.min_length) + ", " + FormatNumber(w.max_length) + "]");
        }
      }
      if (!map.Has("body")) {
        if (map.Has("when")) map.Get("when").Fail("a winch entry without a body has no condition");
        script.push_back(entry);
        continue;
      }
    }

    // the body must exist and take commands: a vehicle
    const Field body = map.Require("body");
    entry.body = body.String();
    const BodyRef ref = FindBody(model, entry.body);
    if (ref.kind == BodyRef::kNone) body.Fail("no such body (bodies: " + BodyNames(model) + ")");
    if (ref.kind == BodyRef::kSphere) {
      body.Fail(entry.body +
                " is a sphere, and spheres take no commands (thrust, rudder, elevator); remove "
                "this script entry");
    }
    entry.vehicle = ref.index;

    // the commands given, each one the vehicle can carry out
    core::VehicleCommand command;
    const CommandFields given = ReadCommand(map, model.vehicles[ref.index], &command);
    if (!given.any() && !entry.set_winch) {
      item.Fail(
          "gives no command; give at least one of thrust, rudder, rudder_deg, elevator, "
          "elevator_deg, winch_speed, winch_length");
    }
    entry.set_thrust = given.thrust;
    entry.set_rudder = given.rudder;
    entry.set_elevator = given.elevator;
    entry.thrust = command.thrust;
    entry.rudder = command.rudder;
    entry.elevator = command.elevator;
    script.push_back(entry);
  }
  return script;
}

}  // namespace towsim::scene::internal
