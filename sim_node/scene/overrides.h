#pragma once
// --set overrides: "key.path=value" strings applied to the scene tree before validation.

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Applies `overrides` to the scene map `root`, in order (a later one wins). Each value is parsed
// as YAML; its key path must be one the scene schema allows; missing maps on the way are
// created. Records the paths set (and maps created) in scene->set_paths, so messages about
// those values say "--set". Throws ConfigError for a malformed override or an unknown path.
void ApplyOverrides(const std::vector<std::string>& overrides, YAML::Node root, Source* scene);

}  // namespace towsim::scene::internal
