#pragma once
// Test helper: reads config/vehicles/*.yaml into core::VehicleParams with the key-for-field
// mapping the scene reader uses (docs/vehicles.md), so that the vehicle tests exercise the
// coefficient files themselves. Strict: an unknown or missing key throws std::runtime_error
// naming the file and the key. Angles in the file carry _deg; the params hold radians.

#include <string>

#include "core/vehicle_model.h"

namespace towsim::test {

core::VehicleParams ReadVehicleFile(const std::string& path);

// TOWSIM_SOURCE_DIR "/config/vehicles/" + name + ".yaml"
core::VehicleParams ReadProjectVehicle(const std::string& name);

}  // namespace towsim::test
