#include "dds/sensor_translators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "dds/translators.h"

namespace towsim::dds {

RangeMessage::RangeMessage(std::string frame_id) : msg{}, frame_id_(std::move(frame_id)) {
  msg.header.frame_id = frame_id_.data();
  msg.radiation_type = sensor_msgs_msg_dds__Range_Constants_ULTRASOUND;
  msg.field_of_view = kAltimeterFieldOfView;
  msg.min_range = 0.0f;
  msg.max_range = kAltimeterMaxRange;
  msg.variance = 0.0f;  // unknown
}

FluidPressureMessage::FluidPressureMessage(std::string frame_id)
    : msg{}, frame_id_(std::move(frame_id)) {
  msg.header.frame_id = frame_id_.data();
}

void ToAltitude(const core::Simulation& sim, int body, RangeMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  const double altitude = sim.body_altitude(body);  // NaN without a seabed
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (std::isnan(altitude) || altitude > msg->max_range) {
    msg->range = kInf;  // REP 117: no echo
  } else if (altitude < msg->min_range) {
    msg->range = -kInf;  // REP 117: too close (the origin is in the bed)
  } else {
    msg->range = static_cast<float>(altitude);
  }
}

void ToPressure(const core::Simulation& sim, int body, FluidPressureMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  const core::Environment& sea = sim.model().environment;
  const double depth = std::max(0.0, sim.body_depth(body));  // above the surface: the air's
  msg->fluid_pressure = kAtmosphericPressure + sea.water_density * sea.gravity * depth;
  msg->variance = 0.0;
}

}  // namespace towsim::dds
