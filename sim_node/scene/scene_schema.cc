#include "scene/scene_schema.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <map>

#include "core/publish_rates.h"

namespace towsim::scene::internal {
namespace {

// Levenshtein distance, to suggest the key a typo meant.
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

const std::vector<std::string>& AllowedKeys(MapKind kind) {
  // a model's own keys: a sphere's, a vehicle's (core::VehicleParams, one key each)
  static const std::vector<std::string> kSphereKeys = {"mass", "volume", "drag_coefficient",
                                                       "added_mass_coefficient", "source"};
  static const std::vector<std::string> kVehicleKeys = {
      "source", "length",   "diameter",   "mass",        "inertia", "r_g",
      "r_b",    "volume",   "added_mass", "munk_moment", "damping", "surfaces",
      "rudder", "elevator", "propeller",  "waterplane"};
  // a vessel's motion (core::Vessel, docs/vessels.md); its initial pose is the scene's
  static const std::vector<std::string> kVesselKeys = {
      "source",  "speed", "max_acceleration",  "max_yaw_acceleration_deg", "harmonic",
      "raos",    "rao_extrapolation", "time_history", "external"};
  // a line type's properties (core::CableParams)
  static const std::vector<std::string> kLineTypeKeys = {
      "diameter",          "mass_per_length", "density", "axial_stiffness", "youngs_modulus",
      "bending_stiffness", "axial_damping",   "drag",    "added_mass"};
  static const std::vector<std::string> kSourceKey = {"source"};
  // the cable's own keys after the line type's (added_mass_coefficient: C_an, before line types)
  static const std::vector<std::string> kCableKeys = {
      "added_mass_coefficient", "loads", "initial", "initial_velocity", "start", "end", "winch"};
  // type first, then the keys of `groups`, each once, in order
  const auto join = [](std::vector<std::string> keys,
                       std::initializer_list<const std::vector<std::string>*> groups) {
    for (const std::vector<std::string>* group : groups) {
      for (const std::string& key : *group) {
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
      }
    }
    return keys;
  };
  // the rate keys (core/publish_rates.h), then the command timeout
  const auto publish_keys = [] {
    std::vector<std::string> keys;
    for (const core::PublishRateKey& k : core::kPublishRateKeys) keys.push_back(k.key);
    keys.push_back("command_timeout");
    return keys;
  };
  static const std::map<MapKind, std::vector<std::string>> kKeys = {
      {MapKind::kScene,
       {"name", "time", "environment", "line_types", "cable", "cables", "bodies", "integrator",
        "script", "publish", "security"}},
      {MapKind::kPublish, publish_keys()},
      {MapKind::kSecurity, {"open_outputs"}},
      {MapKind::kTime, {"step", "duration", "output_rate"}},
      {MapKind::kEnvironment,
       {"water_density", "dynamic_viscosity", "gravity", "current", "waves", "seabed"}},
      {MapKind::kCurrent, {"profile", "power_law", "time_scale"}},
      {MapKind::kPowerLaw, {"surface", "depth", "exponent"}},
      {MapKind::kWaves, {"regular", "jonswap", "pierson_moskowitz", "ramp"}},
      {MapKind::kRegularWave, {"height", "period", "direction_deg", "phase_deg"}},
      {MapKind::kJonswap, {"hs", "tp", "gamma", "direction_deg", "components", "seed"}},
      {MapKind::kPmSpectrum, {"hs", "tp", "direction_deg", "components", "seed"}},
      {MapKind::kSeabed,
       {"depth", "slope_deg", "slope_direction_deg", "grid", "stiffness", "damping", "friction",
        "friction_lateral"}},
      // a line type's properties (docs/scene_format.md "Line types"), then its sources
      {MapKind::kLineTypes, {}},
      {MapKind::kLineType, join({}, {&kLineTypeKeys, &kSourceKey})},
      {MapKind::kLineDrag, {"normal", "tangential"}},
      {MapKind::kLineAddMass, {"normal", "tangential"}},
      // the cable: a line type's properties inline (overriding cable.line_type's)
      {MapKind::kCables, {}},
      {MapKind::kCable, join({"length", "elements", "line_type"}, {&kLineTypeKeys, &kCableKeys})},
      {MapKind::kWinch,
       {"name", "min_length", "max_length", "max_speed", "max_acceleration", "brake_tension"}},
      {MapKind::kEnd, {"fixed", "slope", "driven", "free", "body", "at"}},
      {MapKind::kDriven, {"position", "velocity"}},
      {MapKind::kBodies, {}},
      // a body in the scene: its initial state and any key of its model (the scene's wins)
      {MapKind::kBody,
       join({"type", "model", "scale", "position", "euler_deg", "velocity", "command", "sensors"},
            {&kSphereKeys, &kVehicleKeys, &kVesselKeys})},
      {MapKind::kModelFile, join({"type"}, {&kSphereKeys})},
      {MapKind::kVehicleFile, join({"type"}, {&kVehicleKeys})},
      {MapKind::kVesselFile, join({"type"}, {&kVesselKeys})},
      {MapKind::kHarmonic, {"dof", "amplitude", "period", "phase_deg"}},
      {MapKind::kAddedMass,
       {"x_udot", "y_vdot", "z_wdot", "k_pdot", "m_qdot", "n_rdot", "y_rdot", "n_vdot", "z_qdot",
        "m_wdot"}},
      {MapKind::kDamping,
       {"x_uu", "y_vv", "z_ww", "y_rr", "z_qq", "m_ww", "n_vv", "m_qq", "n_rr", "k_pp", "y_uv",
        "z_uw", "m_uw", "n_uv", "y_ur", "z_uq", "m_uq", "n_ur", "k_p"}},
      {MapKind::kSurface,
       {"name", "channel", "position", "normal", "area", "aspect_ratio", "lift_slope", "oswald",
        "cd0", "stall_angle_deg", "incidence_deg", "deflection_sign"}},
      {MapKind::kActuator, {"max_deflection_deg", "max_rate_deg"}},
      {MapKind::kPropeller, {"max_thrust", "time_constant"}},
      {MapKind::kWaterplane,
       {"area", "position", "design_depth", "inertia_longitudinal", "inertia_transverse"}},
      {MapKind::kCommand, {"thrust", "rudder", "rudder_deg", "elevator", "elevator_deg"}},
      // a sensor's errors (core/sensor_model.h, docs/sensors.md "Sensor models")
      {MapKind::kSensors, {"altimeter", "pressure", "odometry"}},
      {MapKind::kSensor, {"noise", "bias", "rate", "latency_steps", "dropout", "seed"}},
      {MapKind::kOdometry,
       {"noise", "bias", "velocity_noise", "velocity_bias", "rate", "latency_steps", "dropout",
        "seed"}},
      {MapKind::kIntegrator,
       {"scheme", "rho_inf", "coupling", "tolerance", "force_tolerance", "max_iterations",
        "max_substep_level", "max_coupling_iterations"}},
      {MapKind::kScriptEntry,
       {"at", "when", "body", "thrust", "rudder", "rudder_deg", "elevator", "elevator_deg",
        "winch", "winch_speed", "winch_length", "speed", "heading_deg", "turn_rate_deg"}},
  };
  return kKeys.at(kind);
}

std::optional<MapKind> ChildMap(MapKind parent, const std::string& key) {
  switch (parent) {
    case MapKind::kScene:
      if (key == "time") return MapKind::kTime;
      if (key == "environment") return MapKind::kEnvironment;
      if (key == "cable") return MapKind::kCable;
      if (key == "cables") return MapKind::kCables;
      if (key == "line_types") return MapKind::kLineTypes;
      if (key == "bodies") return MapKind::kBodies;
      if (key == "integrator") return MapKind::kIntegrator;
      if (key == "publish") return MapKind::kPublish;
      if (key == "security") return MapKind::kSecurity;
      return std::nullopt;  // name; script is a list
    case MapKind::kEnvironment:
      // current is a value ([u, v, w] or a map): --set sets it whole
      if (key == "waves") return MapKind::kWaves;
      if (key == "seabed") return MapKind::kSeabed;
      return std::nullopt;
    case MapKind::kWaves:
      if (key == "regular") return MapKind::kRegularWave;
      if (key == "jonswap") return MapKind::kJonswap;
      if (key == "pierson_moskowitz") return MapKind::kPmSpectrum;
      return std::nullopt;
    case MapKind::kCurrent:
      if (key == "power_law") return MapKind::kPowerLaw;
      return std::nullopt;
    case MapKind::kCable:
      if (key == "start" || key == "end") return MapKind::kEnd;
      if (key == "winch") return MapKind::kWinch;
      [[fallthrough]];
    case MapKind::kLineType:
      // drag may also be the name of a law (choo_casarella): --set it whole
      if (key == "drag") return MapKind::kLineDrag;
      if (key == "added_mass") return MapKind::kLineAddMass;
      return std::nullopt;
    case MapKind::kLineTypes:
      return MapKind::kLineType;
    case MapKind::kCables:
      return MapKind::kCable;
    case MapKind::kEnd:
      if (key == "driven") return MapKind::kDriven;
      return std::nullopt;
    case MapKind::kBodies:
      return MapKind::kBody;
    case MapKind::kSensors:
      if (key == "odometry") return MapKind::kOdometry;
      if (key == "altimeter" || key == "pressure") return MapKind::kSensor;
      return std::nullopt;
    case MapKind::kBody:
    case MapKind::kVehicleFile:
      if (key == "added_mass") return MapKind::kAddedMass;
      if (key == "damping") return MapKind::kDamping;
      if (key == "rudder" || key == "elevator") return MapKind::kActuator;
      if (key == "propeller") return MapKind::kPropeller;
      if (key == "waterplane") return MapKind::kWaterplane;
      if (key == "command" && parent == MapKind::kBody) return MapKind::kCommand;
      if (key == "sensors" && parent == MapKind::kBody) return MapKind::kSensors;
      return std::nullopt;  // values; surfaces is a list
    default:
      return std::nullopt;
  }
}

const char* NamedEntries(MapKind kind) {
  if (kind == MapKind::kBodies) return "body names";
  if (kind == MapKind::kLineTypes) return "line type names";
  if (kind == MapKind::kCables) return "cable names";
  return nullptr;
}

bool IsValidName(const std::string& name) {
  if (name.empty()) return false;
  const auto letter = [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
  };
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  if (!letter(name[0])) return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || digit(c); });
}

std::string Suggestion(const std::string& word, const std::vector<std::string>& allowed) {
  // a suffix left off (yaw for yaw_deg, rudder for rudder_deg), else the fewest edits
  for (const std::string& candidate : allowed) {
    if (candidate.size() > word.size() + 1 && candidate.compare(0, word.size(), word) == 0 &&
        candidate[word.size()] == '_') {
      return candidate;
    }
  }
  const std::string* best = nullptr;
  size_t best_distance = 3;
  for (const std::string& candidate : allowed) {
    const size_t d = EditDistance(word, candidate);
    if (d < best_distance) {
      best = &candidate;
      best_distance = d;
    }
  }
  return best != nullptr ? *best : std::string();
}

std::string UnknownKeyRule(const std::string& key, const std::vector<std::string>& allowed) {
  std::string rule = "unknown key";
  // suggest the closest allowed key when it is a plausible typo (at most 2 edits)
  const std::string best = Suggestion(key, allowed);
  if (!best.empty()) rule += "; did you mean " + best + "?";
  if (!allowed.empty()) {
    rule += " (allowed: ";
    for (size_t i = 0; i < allowed.size(); ++i) rule += (i ? ", " : "") + allowed[i];
    rule += ")";
  }
  return rule;
}

}  // namespace towsim::scene::internal
