#include "scene/sensor_reader.h"

#include <limits>
#include <string>

namespace towsim::scene::internal {
namespace {

core::SensorErrors ReadSensor(const std::string& body, const std::string& sensor,
                              const Field& field, MapKind kind, double h) {
  const MapReader map(field, kind);
  core::SensorErrors e;
  e.noise = map.Number("noise", Range::AtLeast(0.0), 0.0);
  e.bias = map.Number("bias", Range::Any(), 0.0);
  if (kind == MapKind::kOdometry) {
    e.velocity_noise = map.Number("velocity_noise", Range::AtLeast(0.0), 0.0);
    e.velocity_bias = map.Number("velocity_bias", Range::Any(), 0.0);
  }
  if (map.Has("rate")) {
    // a sensor samples at most once per step
    const Field rate = map.Get("rate");
    e.rate = rate.Number(Range::Above(0.0));
    if (e.rate > 1.0 / h * (1.0 + 1e-12)) {
      rate.Fail("must be <= the step rate 1 / time.step = " + FormatNumber(1.0 / h) +
                " Hz (a sensor samples at most once per step)");
    }
  }
  e.latency_steps = map.Integer("latency_steps", Range::Closed(0, 100000), 0);
  e.dropout = map.Number("dropout", Range{0.0, 1.0, false, true}, 0.0);
  e.seed = map.Has("seed") ? static_cast<std::uint64_t>(map.Integer(
                                 "seed", Range::Closed(0, std::numeric_limits<int>::max())))
                           : core::DefaultSensorSeed(body, sensor);
  return e;
}

}  // namespace

std::vector<core::BodySensors> ReadSensors(const Field& bodies, double h) {
  std::vector<core::BodySensors> out;
  const MapReader map(bodies, MapKind::kBodies);
  for (const auto& [name, field] : map.entries()) {
    const MapReader body(field, MapKind::kBody);
    if (!body.Has("sensors")) continue;
    const MapReader sensors(body.Get("sensors"), MapKind::kSensors);
    core::BodySensors s;
    s.body = name;
    for (const auto& [sensor, value] : sensors.entries()) {
      const MapKind kind = sensor == "odometry" ? MapKind::kOdometry : MapKind::kSensor;
      const core::SensorErrors e = ReadSensor(name, sensor, value, kind, h);
      if (sensor == "altimeter") s.altimeter = e;
      if (sensor == "pressure") s.pressure = e;
      if (sensor == "odometry") s.odometry = e;
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace towsim::scene::internal
