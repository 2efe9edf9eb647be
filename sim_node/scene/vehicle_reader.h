#pragma once
// A 6-DOF vehicle's model (type: vehicle): the keys of core::VehicleParams, one to one, in the
// units of the file (degrees where the key says _deg), validated and converted to SI.

#include "core/model.h"
#include "scene/body_reader.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Reads and checks the vehicle parameters from a body's keys (scene over model file).
core::VehicleParams ReadVehicleParams(const BodyKeys& keys);

// The command fields given in `map` (a script entry or bodies.<name>.command): thrust [N],
// rudder [rad] or rudder_deg [deg] (not both), elevator or elevator_deg; each one checked
// against `vehicle` (CheckThrust, CheckDeflection) and written to `command`, the others left
// alone. Returns which fields were given.
struct CommandFields {
  bool thrust = false, rudder = false, elevator = false;
  bool any() const { return thrust || rudder || elevator; }
};
CommandFields ReadCommand(const MapReader& map, const core::Vehicle& vehicle,
                          core::VehicleCommand* command);

// A commanded thrust [N] that `vehicle` can produce: it needs a propeller (or is 0) and lies in
// [-max_thrust / 4, max_thrust], the range the vehicle model clamps to. `field` is the value as
// written, for the message.
void CheckThrust(const Field& field, double thrust, const core::Vehicle& vehicle);

// A commanded deflection [rad] on `channel`: the vehicle has a surface on it (or the value is 0)
// and |deflection| <= the channel's max_deflection.
void CheckDeflection(const Field& field, double deflection, const core::Vehicle& vehicle,
                     core::Channel channel);

}  // namespace towsim::scene::internal
