#include "seabed_drag_model.h"

#include <string>

#include "core/state.h"
#include "scene/scene_loader.h"

namespace towsim::reference {

using core::Vec3;

core::Model DraggedOnTheBed(int factor) {
  return scene::LoadScene(
      std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/catenary.yaml",
      {"cable.length=100", "cable.elements=" + std::to_string(20 * factor),
       "cable.loads=[gravity, buoyancy]", "cable.initial=vertical", "cable.axial_damping=0.01",
       "cable.start={driven: {position: [0, 0, 60], velocity: [0.1, 0, 0]}}",
       "cable.end={free: true}", "cable.initial_velocity=[0.1, 0, 0]",
       "environment.seabed={depth: 60, stiffness: 3.0e6, damping: 3.0e4, friction: 0.5}"});
}

void LayOnTheBed(core::Simulation* sim) {
  const core::Model& m = sim->model();
  core::State laid = sim->state();
  const double l = m.cables[0].length / m.cables[0].elements;
  for (int n = 0; n < sim->num_nodes(); ++n) {
    laid.q.segment<3>(sim->cable_dof(n)) = Vec3(-n * l, 0.0, 60.0);
    laid.q.segment<3>(sim->cable_dof(n) + 3) = Vec3(-1.0, 0.0, 0.0);
    laid.v.segment<3>(sim->cable_dof(n)) = Vec3(kDragSpeed, 0.0, 0.0);
    laid.v.segment<3>(sim->cable_dof(n) + 3).setZero();
  }
  sim->StartFrom(laid);
}

}  // namespace towsim::reference
