#pragma once
// bodies.<name>.sensors: {altimeter: {...}, pressure: {...}, odometry: {...}}, each sensor's
// errors (core/sensor_model.h; docs/sensors.md "Sensor models", docs/scene_format.md):
//   noise           >= 0, the standard deviation [m for the altimeter, Pa for the pressure,
//                   m for the odometry's position]; default 0
//   bias            any finite number, same unit; default 0
//   velocity_noise  odometry only: >= 0 [m/s] on each linear velocity component; default 0
//   velocity_bias   odometry only: [m/s]; default 0
//   rate            > 0 [Hz], at most the step rate 1 / h; absent: the topic's publish rate
//   latency_steps   integer in [0, 100000] [steps]; default 0
//   dropout         in [0, 1); default 0
//   seed            integer in [0, 2^31 - 1]; absent: core::DefaultSensorSeed(body, sensor)
// A sensor that is absent is perfect; a sensor given as an empty map ({}) has no error either
// but is sampled as a modelled sensor (its rate, latency, dropout all default).

#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// the sensors of every body of the bodies map that has a `sensors` key, in document order;
// h the step [s] (the rate's upper bound)
std::vector<core::BodySensors> ReadSensors(const Field& bodies, double h);

}  // namespace towsim::scene::internal
