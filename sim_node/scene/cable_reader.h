#pragma once
// cable: material, loads, ends and the initial shape, with the geometric rules that let the
// core build the initial state (docs/contract.md §5).

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads and checks the cable map; `model` holds the scene's bodies (spheres and vehicles, for
// body ends, with their initial positions). initial_velocity: given, else that of a driven end,
// else zero.
core::CableParams ReadCable(const Field& cable, const core::Model& model);

}  // namespace towsim::scene::internal
