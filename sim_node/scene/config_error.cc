#include "scene/config_error.h"

#include <utility>

namespace towsim::scene {

ConfigError::ConfigError(std::string key, std::string value, std::string location, std::string rule)
    : std::runtime_error(key + " = " + value + " (" + location + "): " + rule),
      key_(std::move(key)),
      value_(std::move(value)),
      location_(std::move(location)),
      rule_(std::move(rule)) {}

}  // namespace towsim::scene
