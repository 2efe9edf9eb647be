#pragma once
// Scene file (YAML, docs/contract.md §5) -> validated core::Model. Every rule broken throws
// ConfigError naming the key path, the value, file:line and the rule, e.g.
//   cable.elements = 0 (catenary.yaml:14): must be >= 1
// The app maps ConfigError to exit code 2.

#include <string>
#include <vector>

#include "core/model.h"
#include "scene/config_error.h"

namespace towsim::scene {

// Loads the scene file at `path`. `overrides` are "key.path=value" strings from --set, applied
// to the YAML tree before validation (value parsed as YAML; location "--set" in messages).
// Vehicle model paths resolve against the scene file's folder. Messages name files by basename.
// Throws ConfigError.
core::Model LoadScene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same from text (tests): `name_for_messages` stands in for the file name, relative model
// paths resolve against `base_dir`. Throws ConfigError.
core::Model LoadSceneFromString(const std::string& yaml, const std::string& name_for_messages,
                                const std::string& base_dir,
                                const std::vector<std::string>& overrides = {});

// What a valid scene deserves a word about without failing: a body no cable end holds (it
// moves on its own). One line each, "bodies.<name>: ..."; the programs print them as warnings.
std::vector<std::string> SceneWarnings(const core::Model& model);

// Loads a vehicle model file (type: vehicle, config/vehicles/*.yaml) by itself, checked as the
// scene loader checks it; key paths in messages start at the file's root (added_mass.x_udot).
// Throws ConfigError.
core::VehicleParams LoadVehicleFile(const std::string& path);

}  // namespace towsim::scene
