#pragma once
// cables: a network of named cables (docs/scene_format.md "Networks"), each read like the
// one-cable form's `cable` (cable_reader.h), then checked as a graph: names, winches, the
// static start and that every connected part of the network is held.

#include <string>
#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads the cables map (name -> cable); `model` holds the scene's bodies. The cables come
// back in the scene's order, but the one with a winch first (core/model.h).
std::vector<core::CableParams> ReadCables(const Field& cables, const Field& line_types,
                                          const std::string& base_dir, const core::Model& model);

// Names a cable may not take: the files and node topics of a run share its namespace
// (docs/scene_format.md "Networks")
bool IsReservedCableName(const std::string& name);

}  // namespace towsim::scene::internal
