#pragma once
// An external vessel's pose on the wire (docs/vessels.md "External vessels"): the topic
// rt/<ns>/<vessel>/pose_command carries nav_msgs/Odometry in exactly the frames of the node's
// own odometry (dds/translators.h ToOdometry), so that a program may feed a vessel's odometry
// back and get the same pose:
//   header.stamp          the simulation time the pose belongs to
//   header.frame_id       "world_ned" (kWorldFrame; empty is taken as it)
//   child_frame_id        "<vessel>_frd" (empty is taken as it)
//   pose.pose.position    p_WB: the vessel's reference point in the world frame W, NED [m]
//   pose.pose.orientation q_WB: body frame B (forward, starboard, down) -> W, unit
//   twist.twist.linear    [u v w]: the reference point's velocity in B [m/s]
//   twist.twist.angular   [p q r]: the angular velocity in B [rad/s]
//   covariances           ignored
// core::VesselPose holds ZYX Euler angles, the velocity in W and the Euler rates; from the
// message:
//   euler = EulerZYX(q_WB)                             (core/vehicle_model.h)
//   velocity = R_WB [u v w]
//   phi'   = p + (q sin phi + r cos phi) tan theta
//   theta' = q cos phi - r sin phi
//   psi'   = (q sin phi + r cos phi) / cos theta
// (the inverse of VesselPose::twist), and q_WB and [u v w p q r] are kept as given
// (VesselPose::given): the node reports and attaches the cable by them, bit for bit.
//
// Pure functions: no DDS entities, no clocks (tests/unit/dds_vessel_pose_test.cc).

#include <string>

#include "core/vessel_motion.h"
#include "dds/messages.h"
#include "dds/translators.h"

namespace towsim::dds {

// |q| must lie within 1 +- this to be taken as a rotation (double-precision quaternions from
// any rotation library are unit to ~1e-15; float ones to ~1e-7)
inline constexpr double kQuaternionNormTolerance = 1e-6;
// cos(pitch) below this: the Euler rates are singular (pitch within ~2e-6 deg of +-90 deg)
inline constexpr double kMinCosPitch = 1e-6;

struct CheckedPose {
  CheckedCommand::Verdict verdict = CheckedCommand::kAccepted;  // kAccepted or kRejected
  core::VesselPose pose;  // accepted: the pose (VesselPose::given set)
  double t = 0.0;         // header.stamp [s]
  std::string reason;     // kRejected: which field and why
};

// the message of an external vessel named `vessel`: rejected if a number is NaN or infinite,
// |q| is not 1 within kQuaternionNormTolerance, pitch is within kMinCosPitch of +-90 deg, or
// a frame is not the node's (frame_id "world_ned", child_frame_id "<vessel>_frd"; empty
// allowed)
CheckedPose FromPoseCommand(const OdometryMsg& msg, const std::string& vessel);

// the message for `pose` at time t [s] (what the node's odometry of a vessel with that pose
// says): stamp, position, attitude(), twist(); the frames are the message's (OdometryMessage)
void ToPoseCommand(const core::VesselPose& pose, double t, OdometryMsg* msg);

}  // namespace towsim::dds
