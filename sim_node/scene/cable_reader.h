#pragma once
// cable: material, loads, ends and the initial shape, with the geometric rules that let the
// core build the initial state (DESIGN.md §5).

#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

struct CableInput {
  core::CableParams params;
  // cable.initial_velocity, or the driven end's velocity, or zero; also the velocity of bodies
  // that give none (core::CableParams has no field for it yet)
  core::Vec3 initial_velocity = core::Vec3::Zero();
};

// Reads and checks the cable map; `bodies` are the scene's bodies (for body ends).
CableInput ReadCable(const Field& cable, const std::vector<core::SphereBody>& bodies);

}  // namespace towsim::scene::internal
