#pragma once
// cable: material, loads, ends and the initial shape, with the geometric rules that let the
// core build the initial state (DESIGN.md §5).

#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads and checks the cable map; `bodies` are the scene's bodies (for body ends).
// initial_velocity: given, else that of a driven end, else zero.
core::CableParams ReadCable(const Field& cable, const std::vector<core::SphereBody>& bodies);

}  // namespace towsim::scene::internal
