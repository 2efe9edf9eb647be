#include "line_types_models.h"

#include <cstdio>
#include <string>

#include "scene/scene_loader.h"

namespace towsim::reference {
namespace {

const std::string kScenesDir = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";

core::Model Load(const std::string& yaml) {
  return scene::LoadSceneFromString(yaml, "line_types_core_test.yaml", kScenesDir, {});
}

}  // namespace

core::Model ConstantDragTow(double speed, int factor) {
  const std::string v = "[" + std::to_string(speed) + ", 0, 0]";
  return scene::LoadScene(
      kScenesDir + "/steady_tow.yaml",
      {"cable.initial=static", "cable.drag={normal: 1.5, tangential: 0.01}",
       "cable.start.driven.velocity=" + v, "cable.initial_velocity=" + v,
       "bodies.towfish.velocity=" + v, "cable.elements=" + std::to_string(20 * factor)});
}

core::Model RopeCatenary(int factor) {
  return Load(
      "name: rope_catenary\n"
      "time: {step: 0.05, duration: 1, output_rate: 10}\n"
      "line_types:\n"
      "  rope: {diameter: 0.03, mass_per_length: 2.5, axial_stiffness: 2.0e5,\n"
      "         bending_stiffness: 0, drag: {normal: 1.2, tangential: 0.01}}\n"
      "cable:\n"
      "  line_type: rope\n"
      "  length: 200\n"
      "  elements: " +
      std::to_string(20 * factor) +
      "\n"
      "  initial: static\n"
      "  start: {fixed: [0, 0, 10]}\n"
      "  end: {fixed: [150, 0, 10]}\n");
}

double OwnBendingStiffness() {
  constexpr double kLength = kOwnWeightLength;
  return kOwnWeightMass * kOwnWeightGravity * kLength * kLength * kLength / (8.0 * 1e-3);
}

core::Model OwnBendingCantilever(int factor) {
  char yaml[1024];
  std::snprintf(yaml, sizeof yaml,
                "name: cantilever\n"
                "time: {step: 0.05, duration: 1, output_rate: 10}\n"
                "environment: {gravity: %g}\n"
                "line_types:\n"
                "  beam: {diameter: 0.2, mass_per_length: %g, axial_stiffness: 1.0e10,\n"
                "         bending_stiffness: %.17g}\n"
                "cable:\n"
                "  line_type: beam\n"
                "  length: %g\n"
                "  elements: %d\n"
                "  loads: [gravity, bending]\n"
                "  initial: static\n"
                "  start: {fixed: [0, 0, 0], slope: [1, 0, 0]}\n"
                "  end: {body: tip}\n"
                // a weightless marker at the tip: the static solve starts from the straight
                // line to it (a free end starts hanging, cantilever_core_test does the same)
                "bodies:\n"
                "  tip: {type: sphere, mass: 1.0e-9, volume: 0, position: [%g, 0, 0]}\n",
                kOwnWeightGravity, kOwnWeightMass, OwnBendingStiffness(), kOwnWeightLength,
                10 * factor, kOwnWeightLength);
  return Load(yaml);
}

}  // namespace towsim::reference
