#pragma once
// bodies: name -> {type: sphere, mass, volume, drag_coefficient, added_mass_coefficient,
// position, velocity}, or {model: <vehicle file>, position, velocity} with inline keys
// overriding the model file's.

#include <string>
#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

struct BodyInput {
  core::SphereBody body;
  bool velocity_given = false;  // false: the body starts with the cable's initial velocity
};

// Reads the bodies map (absent: no bodies), in document order. Model paths are relative to
// `base_dir`; errors inside a model file name that file and line.
std::vector<BodyInput> ReadBodies(const Field& bodies, const std::string& base_dir);

// "towfish, tow_vehicle" for messages ("none" when empty)
std::string BodyNames(const std::vector<core::SphereBody>& bodies);

// index of the body called `name` in `bodies`, -1 if none
int FindBody(const std::vector<core::SphereBody>& bodies, const std::string& name);

}  // namespace towsim::scene::internal
