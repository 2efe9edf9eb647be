#pragma once
// The keys a scene file and a vehicle model file may hold. One table serves the loader (reject
// unknown keys) and the --set overrides (reject paths the loader would not read).

#include <optional>
#include <string>
#include <vector>

namespace towsim::scene::internal {

// The map-shaped parts of a scene (and of a vehicle model file).
enum class MapKind {
  kScene,        // top level
  kTime,         // time
  kEnvironment,  // environment
  kCurrent,      // environment.current, when a map (a profile or a power law)
  kPowerLaw,     // environment.current.power_law
  kWaves,        // environment.waves
  kRegularWave,  // environment.waves.regular
  kJonswap,      // environment.waves.jonswap
  kPmSpectrum,   // environment.waves.pierson_moskowitz
  kSeabed,       // environment.seabed
  kLineTypes,    // line_types: user-chosen names -> kLineType
  kLineType,     // line_types.<name>, a file of config/line_types/ (and the same keys in cable)
  kLineDrag,     // <line type>.drag, when a map {normal, tangential}
  kLineAddMass,  // <line type>.added_mass {normal, tangential}
  kCables,       // cables: user-chosen names -> kCable (a network, docs/scene_format.md)
  kCable,        // cable, cables.<name>
  kEnd,          // cable.start, cable.end
  kDriven,       // cable.<end>.driven
  kWinch,        // cable.winch
  kBodies,       // bodies: user-chosen names -> kBody
  kBody,         // bodies.<name>: a sphere's or a vehicle's keys, plus its initial state
  kModelFile,    // the file named by bodies.<name>.model, type: sphere
  kVehicleFile,  // the file named by bodies.<name>.model, type: vehicle
  kVesselFile,   // the file named by bodies.<name>.model, type: vessel
  kHarmonic,     // <vessel>.harmonic[i]
  kAddedMass,    // <vehicle>.added_mass
  kDamping,      // <vehicle>.damping
  kSurface,      // <vehicle>.surfaces[i]
  kActuator,     // <vehicle>.rudder, <vehicle>.elevator
  kPropeller,    // <vehicle>.propeller
  kWaterplane,   // <vehicle>.waterplane
  kCommand,      // bodies.<name>.command
  kSensors,      // bodies.<name>.sensors {altimeter, pressure, odometry}
  kSensor,       // bodies.<name>.sensors.altimeter, .pressure
  kOdometry,     // bodies.<name>.sensors.odometry
  kIntegrator,   // integrator
  kPublish,      // publish
  kSecurity,     // security
  kScriptEntry,  // script[i]
};

// Keys a map of this kind may hold, in documentation order (empty for kBodies, kLineTypes and
// kCables: any valid name).
const std::vector<std::string>& AllowedKeys(MapKind kind);

// The kind of map found under `key` in a map of kind `parent`; nullopt if that key holds a
// value (number, string, vector or list) rather than a map of named keys.
std::optional<MapKind> ChildMap(MapKind parent, const std::string& key);

// Maps whose keys are user-chosen names (kBodies, kLineTypes, kCables): "body names", "line type
// names", "cable names"; nullptr for maps of schema keys.
const char* NamedEntries(MapKind kind);

// Body names become topic and CSV names: [A-Za-z_][A-Za-z0-9_]*.
bool IsValidName(const std::string& name);
inline constexpr const char* kNameRule = "must match [A-Za-z_][A-Za-z0-9_]*";

// the entry of `allowed` that `word` most likely meant: one that continues it with "_..." (a
// unit suffix left off: yaw -> yaw_deg), else the nearest within 2 edits; empty if none
std::string Suggestion(const std::string& word, const std::vector<std::string>& allowed);

// "unknown key; did you mean length? (allowed: length, elements, ...)"
std::string UnknownKeyRule(const std::string& key, const std::vector<std::string>& allowed);

}  // namespace towsim::scene::internal
