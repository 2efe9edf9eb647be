#include "jumper_model.h"

#include "scene/scene_loader.h"

namespace towsim::reference {

core::Model Jumper(int elements, const std::vector<std::string>& overrides) {
  return scene::LoadSceneFromString(
      "name: jumper\n"
      "time: {step: 0.01, duration: 1, output_rate: 10}\n"
      "environment: {water_density: 1000, gravity: 9.807}\n"
      "cable:\n"
      "  line_type: lowe_langley_jumper\n"
      "  length: 170\n"
      "  elements: " +
          std::to_string(elements) +
          "\n"
          "  loads: [gravity, buoyancy, bending]\n"
          "  initial: static\n"
          "  start: {fixed: [-100, 0, 55]}\n"
          "  end: {fixed: [0, 0, 5]}\n",
      "jumper.yaml", std::string(TOWSIM_SOURCE_DIR) + "/config/scenes", overrides);
}

}  // namespace towsim::reference
