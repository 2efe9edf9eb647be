#pragma once
// cable: its line type (line_type_reader.h), loads, ends and the initial shape, with the
// geometric rules that let the core build the initial state (docs/contract.md §5).

#include <string>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads and checks the cable map; `line_types` is the scene's line_types map (absent: none),
// `base_dir` the scene's folder (the line type library, line_type_reader.h); `model` holds the
// scene's bodies (spheres and vehicles, for body ends, with their initial positions).
// initial_velocity: given, else that of a driven end, else zero.
core::CableParams ReadCable(const Field& cable, const Field& line_types,
                            const std::string& base_dir, const core::Model& model);

}  // namespace towsim::scene::internal
