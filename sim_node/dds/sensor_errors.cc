#include "dds/sensor_errors.h"

namespace towsim::dds {

const core::SensorErrors* FindSensorErrors(const core::Model& model, const std::string& body,
                                           Sensor sensor) {
  for (const core::BodySensors& s : model.sensors) {
    if (s.body != body) continue;
    const std::optional<core::SensorErrors>& e = sensor == Sensor::kAltimeter  ? s.altimeter
                                                 : sensor == Sensor::kPressure ? s.pressure
                                                                               : s.odometry;
    return e ? &*e : nullptr;
  }
  return nullptr;
}

core::SensorModel MakeSensorModel(const core::SensorErrors& e, Sensor sensor, double h) {
  if (sensor != Sensor::kOdometry) return core::SensorModel({e.noise}, {e.bias}, e, h);
  // position x, y, z then linear velocity u, v, w
  return core::SensorModel(
      {e.noise, e.noise, e.noise, e.velocity_noise, e.velocity_noise, e.velocity_noise},
      {e.bias, e.bias, e.bias, e.velocity_bias, e.velocity_bias, e.velocity_bias}, e, h);
}

bool ApplySensorErrors(core::SensorModel* model, std::uint64_t n, bool due, RangeMsg* msg) {
  const double truth = msg->range;  // the float32 true range, exactly
  double out = 0.0;
  if (!model->Step(n, due, &truth, &out)) return false;
  msg->range = static_cast<float>(out);
  msg->variance = static_cast<float>(model->sigma(0) * model->sigma(0));
  return true;
}

bool ApplySensorErrors(core::SensorModel* model, std::uint64_t n, bool due, FluidPressureMsg* msg) {
  const double truth = msg->fluid_pressure;
  double out = 0.0;
  if (!model->Step(n, due, &truth, &out)) return false;
  msg->fluid_pressure = out;
  msg->variance = model->sigma(0) * model->sigma(0);
  return true;
}

bool ApplySensorErrors(core::SensorModel* model, std::uint64_t n, bool due, OdometryMsg* msg) {
  auto& p = msg->pose.pose.position;
  auto& v = msg->twist.twist.linear;
  const double truth[6] = {p.x, p.y, p.z, v.x, v.y, v.z};
  double out[6];
  if (!model->Step(n, due, truth, out)) return false;
  p.x = out[0];
  p.y = out[1];
  p.z = out[2];
  v.x = out[3];
  v.y = out[4];
  v.z = out[5];
  // row-major 6 x 6: the diagonal of x, y, z (vx, vy, vz) at 0, 7, 14
  for (int i : {0, 7, 14}) {
    msg->pose.covariance[i] = model->sigma(0) * model->sigma(0);
    msg->twist.covariance[i] = model->sigma(3) * model->sigma(3);
  }
  return true;
}

}  // namespace towsim::dds
