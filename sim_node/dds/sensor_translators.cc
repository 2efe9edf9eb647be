#include "dds/sensor_translators.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/wave_field.h"
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
  // along the beam (the body's z axis) to the bed: +inf no return, -inf the origin in the
  // bed (REP 117), the conventions of Simulation::BodyAltimeterRange
  msg->range = static_cast<float>(sim.BodyAltimeterRange(body, msg->max_range));
}

void ToPressure(const core::Simulation& sim, int body, FluidPressureMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  const core::Environment& sea = sim.model().environment;
  const core::Vec3 p = sim.body_position(body);
  // linear theory's total pressure: hydrostatic below the mean surface plus the waves'
  // dynamic pressure p_d = rho g sum a K(zeta) cos th (core/wave_field.h); dry above the
  // instantaneous surface (the air's); in a crest p_d(0) = rho g eta, so there p = rho g (z +
  // eta), zero at the surface
  const core::WaveKinematics w = sea.waves.Kinematics(p, sim.time());
  const double gauge = w.wet ? sea.water_density * sea.gravity * p.z() + w.dynamic_pressure : 0.0;
  msg->fluid_pressure = kAtmosphericPressure + std::max(0.0, gauge);
  msg->variance = 0.0;
}

}  // namespace towsim::dds
