#pragma once
// The water's motion at one point and time, and the one place a load takes it off its own
// velocity (environment_field.h builds the samples).

#include <Eigen/Core>

namespace towsim::core {

struct FlowSample {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // u_W [m/s]
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // du_W/dt [m/s^2]
};

// Velocity of a point moving at v_W relative to the local water: v_W - u_W. Every load (cable
// drag, sphere drag, vehicle hydrodynamics) takes the water off through this one function.
inline Eigen::Vector3d RelativeVelocity(const Eigen::Vector3d& v_W, const FlowSample& flow) {
  return v_W - flow.velocity;
}

}  // namespace towsim::core
