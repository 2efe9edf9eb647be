#pragma once
// A body's sensors with errors on the wire (docs/sensors.md, "Sensor models"): the true
// message a translator built (sensor_translators.h, translators.h) turned into what the
// sensor publishes by a core::SensorModel (bias, noise, latency, rate, dropout). Pure: no DDS
// entities, no clocks (tests/unit/sensor_errors_test.cc).
//
//   altimeter  Range.range [m], one channel; float32 on the wire (the error is added in double
//              to the float32 true range, then rounded); +-inf stay +-inf
//   pressure   FluidPressure.fluid_pressure [Pa], one channel
//   odometry   position x, y, z [m] (noise, bias) and linear velocity u, v, w [m/s]
//              (velocity_noise, velocity_bias), six independent channels; the orientation
//              and the angular velocity stay true (a navigation filter's attitude is far
//              better than its position)
// The header stamp stays the time of the step at which the message is published (a driver
// stamps a reading when it arrives: a latency shows as an older value under a newer stamp).
// Variance: Range.variance and FluidPressure.variance = noise^2; the odometry's pose and twist
// covariance diagonals (x, y, z; vx, vy, vz) = noise^2, velocity_noise^2.

#include <cstdint>

#include "core/model.h"
#include "core/sensor_model.h"
#include "dds/messages.h"

namespace towsim::dds {

enum class Sensor { kAltimeter, kPressure, kOdometry };

// the errors of body `body`'s sensor in `model`, nullptr when it has none (a perfect sensor)
const core::SensorErrors* FindSensorErrors(const core::Model& model, const std::string& body,
                                           Sensor sensor);

// the model of one sensor (its channels above); h the step [s]
core::SensorModel MakeSensorModel(const core::SensorErrors& errors, Sensor sensor, double h);

// step n of a modelled sensor: `msg` holds step n's true message; returns true when a sample
// is published at step n, `msg` then holding the published value (core::SensorModel::Step;
// `due`: the topic's publish step). Never allocates.
bool ApplySensorErrors(core::SensorModel* model, std::uint64_t n, bool due, RangeMsg* msg);
bool ApplySensorErrors(core::SensorModel* model, std::uint64_t n, bool due, FluidPressureMsg* msg);
bool ApplySensorErrors(core::SensorModel* model, std::uint64_t n, bool due, OdometryMsg* msg);

}  // namespace towsim::dds
