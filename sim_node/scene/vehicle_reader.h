#pragma once
// A 6-DOF vehicle's model (type: vehicle): the keys of core::VehicleParams, one to one, in the
// units of the file (degrees where the key says _deg), validated and converted to SI.

#include "core/model.h"
#include "scene/body_reader.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads and checks the vehicle parameters from a body's keys (scene over model file).
core::VehicleParams ReadVehicleParams(const BodyKeys& keys);

// A commanded thrust [N] that `vehicle` can produce: it needs a propeller (or is 0) and lies in
// [-max_thrust / 4, max_thrust], the range the vehicle model clamps to. `field` is the value as
// written, for the message.
void CheckThrust(const Field& field, double thrust, const core::Vehicle& vehicle);

// A commanded deflection [rad] on `channel`: the vehicle has a surface on it (or the value is 0)
// and |deflection| <= the channel's max_deflection.
void CheckDeflection(const Field& field, double deflection, const core::Vehicle& vehicle,
                     core::Channel channel);

}  // namespace towsim::scene::internal
