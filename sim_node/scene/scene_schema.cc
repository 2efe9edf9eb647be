#include "scene/scene_schema.h"

#include <algorithm>
#include <cctype>
#include <map>

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
  static const std::map<MapKind, std::vector<std::string>> kKeys = {
      {MapKind::kScene, {"name", "time", "environment", "cable", "bodies", "integrator", "script"}},
      {MapKind::kTime, {"step", "duration", "output_rate"}},
      {MapKind::kEnvironment, {"water_density", "dynamic_viscosity", "gravity", "current"}},
      {MapKind::kCable,
       {"length", "elements", "diameter", "density", "youngs_modulus", "loads", "axial_damping",
        "added_mass_coefficient", "initial", "initial_velocity", "start", "end"}},
      {MapKind::kEnd, {"fixed", "slope", "driven", "free", "body", "at"}},
      {MapKind::kDriven, {"position", "velocity"}},
      {MapKind::kBodies, {}},
      {MapKind::kBody,
       {"type", "model", "mass", "volume", "drag_coefficient", "added_mass_coefficient", "position",
        "velocity"}},
      {MapKind::kModelFile,
       {"type", "mass", "volume", "drag_coefficient", "added_mass_coefficient", "source"}},
      {MapKind::kIntegrator,
       {"scheme", "rho_inf", "coupling", "tolerance", "max_iterations", "max_substep_level"}},
      {MapKind::kScriptEntry, {"at", "body", "thrust", "rudder", "elevator"}},
  };
  return kKeys.at(kind);
}

std::optional<MapKind> ChildMap(MapKind parent, const std::string& key) {
  switch (parent) {
    case MapKind::kScene:
      if (key == "time") return MapKind::kTime;
      if (key == "environment") return MapKind::kEnvironment;
      if (key == "cable") return MapKind::kCable;
      if (key == "bodies") return MapKind::kBodies;
      if (key == "integrator") return MapKind::kIntegrator;
      return std::nullopt;  // name; script is a list
    case MapKind::kCable:
      if (key == "start" || key == "end") return MapKind::kEnd;
      return std::nullopt;
    case MapKind::kEnd:
      if (key == "driven") return MapKind::kDriven;
      return std::nullopt;
    case MapKind::kBodies:
      return MapKind::kBody;
    default:
      return std::nullopt;
  }
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

std::string UnknownKeyRule(const std::string& key, const std::vector<std::string>& allowed) {
  std::string rule = "unknown key";
  // suggest the closest allowed key when it is a plausible typo (at most 2 edits)
  const std::string* best = nullptr;
  size_t best_distance = 3;
  for (const std::string& candidate : allowed) {
    const size_t d = EditDistance(key, candidate);
    if (d < best_distance) {
      best = &candidate;
      best_distance = d;
    }
  }
  if (best != nullptr) rule += "; did you mean " + *best + "?";
  if (!allowed.empty()) {
    rule += " (allowed: ";
    for (size_t i = 0; i < allowed.size(); ++i) rule += (i ? ", " : "") + allowed[i];
    rule += ")";
  }
  return rule;
}

}  // namespace towsim::scene::internal
