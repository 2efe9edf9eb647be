#pragma once
// Test helper: a sphere hanging at (3, 4, 20) on a 20 m cable from a fixed point straight above
// it, with an `environment` map appended, for tests of what the node reports of the sea at a
// body (sensor and environment translators).

#include <string>

#include "core/model.h"
#include "scene/scene_loader.h"

namespace towsim::test {

// the scene without its environment (calm, bottomless)
inline constexpr const char* kHangingSphereScene = R"(
name: hanging_sphere
time: {step: 0.05, duration: 1, output_rate: 10}
cable:
  length: 20
  elements: 4
  diameter: 0.041
  density: 1300
  youngs_modulus: 7.0e8
  start: {fixed: [3, 4, 0]}
  end: {body: ball, at: [0, 0, 0]}
bodies:
  ball: {type: sphere, mass: 50, volume: 0.01, position: [3, 4, 20]}
)";

// the scene with `environment` (YAML text, e.g. "environment: {seabed: {depth: 40}}\n")
inline core::Model LoadHangingSphere(const std::string& environment) {
  return scene::LoadSceneFromString(std::string(kHangingSphereScene) + environment,
                                    "hanging_sphere.yaml",
                                    std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
}

}  // namespace towsim::test
