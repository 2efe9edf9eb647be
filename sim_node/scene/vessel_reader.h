#pragma once
// bodies.<name> of type vessel (docs/vessels.md): a kinematic 6-DOF body of prescribed motion,
//   {type: vessel, position, euler_deg, speed, max_acceleration, max_yaw_acceleration_deg,
//    harmonic: [{dof, amplitude, period, phase_deg}, ...], raos: FILE,
//    rao_extrapolation: none | hold}
// or {type: vessel, time_history: FILE} or {type: vessel, external: true, position, ...};
// the motion keys may come from a model file (`model:`, type: vessel). File names are relative
// to the folder of the file that names them (the scene's or the model file's).

#include <string>

#include "core/vessel.h"
#include "scene/body_reader.h"

namespace towsim::scene::internal {

// `scene_dir`: the scene's folder; `model_dir`: the model file's folder (empty: none)
core::Vessel ReadVessel(const std::string& name, const BodyKeys& keys,
                        const std::string& scene_dir, const std::string& model_dir);

}  // namespace towsim::scene::internal
