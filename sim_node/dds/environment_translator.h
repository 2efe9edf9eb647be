#pragma once
// The sea at a body on the wire (docs/environment.md, "On the wire"): a pure translator from the
// core's sea at body b's origin (Simulation::SurfaceElevationAt, WaterVelocityAt,
// BodyAltitude, BodyDepth) to towsim_msgs/BodyEnvironment, with the values and conventions of
// environment.csv's columns (io/csv_writer.h); no DDS entities, no clocks
// (tests/unit/environment_translator_test.cc).
//
//   wave_elevation  eta at the origin's (x, y), positive UP [m]
//   current         the water's velocity at the origin: current + wave orbital velocity, zero
//                   above the surface, world NED [m/s]
//   altitude        above the seabed straight below, d(x, y) - z [m]; NaN without a seabed
//                   (environment.csv leaves the field empty)
//   depth           below the instantaneous surface, z + eta [m]
//
// Header: stamp = simulation time, frame_id = world_ned (the velocity's frame).

#include <cstdint>
#include <string>

#include "core/simulation.h"
#include "dds/messages.h"

namespace towsim::dds {

class BodyEnvironmentMessage {
 public:
  // frame_id: the world frame
  explicit BodyEnvironmentMessage(std::string frame_id);
  BodyEnvironmentMessage(const BodyEnvironmentMessage&) = delete;
  BodyEnvironmentMessage& operator=(const BodyEnvironmentMessage&) = delete;
  BodyEnvironmentMsg msg;

 private:
  std::string frame_id_;
};

// the sea at body b's origin after `step` steps (above); never allocates
void ToBodyEnvironment(const core::Simulation& sim, int body, uint64_t step,
                       BodyEnvironmentMsg* msg);

}  // namespace towsim::dds
