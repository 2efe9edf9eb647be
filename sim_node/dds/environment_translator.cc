#include "dds/environment_translator.h"

#include <utility>

#include "dds/translators.h"

namespace towsim::dds {

BodyEnvironmentMessage::BodyEnvironmentMessage(std::string frame_id)
    : msg{}, frame_id_(std::move(frame_id)) {
  msg.header.frame_id = frame_id_.data();
}

void ToBodyEnvironment(const core::Simulation& sim, int body, uint64_t step,
                       BodyEnvironmentMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  msg->step = step;
  msg->wave_elevation = sim.SurfaceElevationAt(body);
  const core::Vec3 u = sim.WaterVelocityAt(body);
  msg->current.x = u.x();
  msg->current.y = u.y();
  msg->current.z = u.z();
  msg->altitude = sim.BodyAltitude(body);  // NaN without a seabed
  msg->depth = sim.BodyDepth(body);
}

}  // namespace towsim::dds
