#include "dds/vessel_pose_translator.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string_view>
#include <utility>

#include "core/vehicle_model.h"

namespace towsim::dds {
namespace {

bool Finite(std::initializer_list<double> values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

std::string_view View(const char* s) { return s == nullptr ? std::string_view() : s; }

CheckedPose Reject(std::string reason) {
  CheckedPose c;
  c.verdict = CheckedCommand::kRejected;
  c.reason = std::move(reason);
  return c;
}

}  // namespace

CheckedPose FromPoseCommand(const OdometryMsg& msg, const std::string& vessel) {
  const std::string_view frame = View(msg.header.frame_id);
  if (!frame.empty() && frame != kWorldFrame) {
    return Reject("header.frame_id '" + std::string(frame) + "': must be " + kWorldFrame +
                  " (NED, as the node's odometry)");
  }
  const std::string body_frame = vessel + "_frd";
  const std::string_view child = View(msg.child_frame_id);
  if (!child.empty() && child != body_frame) {
    return Reject("child_frame_id '" + std::string(child) + "': must be " + body_frame +
                  " (the twist in the body frame forward, starboard, down)");
  }
  const auto& p = msg.pose.pose.position;
  const auto& o = msg.pose.pose.orientation;
  const auto& lin = msg.twist.twist.linear;
  const auto& ang = msg.twist.twist.angular;
  if (!Finite({p.x, p.y, p.z})) return Reject("pose.pose.position: NaN or infinite");
  if (!Finite({o.x, o.y, o.z, o.w})) return Reject("pose.pose.orientation: NaN or infinite");
  if (!Finite({lin.x, lin.y, lin.z})) return Reject("twist.twist.linear: NaN or infinite");
  if (!Finite({ang.x, ang.y, ang.z})) return Reject("twist.twist.angular: NaN or infinite");
  const Eigen::Quaterniond q_WB(o.w, o.x, o.y, o.z);
  if (std::abs(q_WB.norm() - 1.0) > kQuaternionNormTolerance) {
    char text[128];
    std::snprintf(text, sizeof text,
                  "pose.pose.orientation: |q| = %.9g, must be 1 within %g (a rotation)",
                  q_WB.norm(), kQuaternionNormTolerance);
    return Reject(text);
  }
  CheckedPose c;
  core::VesselPose& pose = c.pose;
  pose.euler = core::EulerZYX(q_WB);
  const double phi = pose.euler.x(), theta = pose.euler.y();
  if (std::cos(theta) < kMinCosPitch) {
    char text[128];
    std::snprintf(text, sizeof text,
                  "pose.pose.orientation: pitch %.9g rad: must be within (-pi/2, pi/2) (the "
                  "Euler rates are singular at +-90 deg)",
                  theta);
    return Reject(text);
  }
  c.t = FromTimeMsg(msg.header.stamp);
  pose.position = core::Vec3(p.x, p.y, p.z);
  const core::Vec3 v_B(lin.x, lin.y, lin.z);
  pose.velocity = q_WB * v_B;
  // the Euler rates from the body rates (the inverse of VesselPose::twist)
  const double rp = ang.x, rq = ang.y, rr = ang.z;
  const double s = rq * std::sin(phi) + rr * std::cos(phi);
  pose.euler_rate = core::Vec3(rp + s * std::tan(theta), rq * std::cos(phi) - rr * std::sin(phi),
                               s / std::cos(theta));
  core::VesselPose::Given given;
  given.q_WB = q_WB;
  given.twist << lin.x, lin.y, lin.z, ang.x, ang.y, ang.z;
  pose.given = given;
  return c;
}

void ToPoseCommand(const core::VesselPose& pose, double t, OdometryMsg* msg) {
  msg->header.stamp = ToTimeMsg(t);
  msg->pose.pose.position.x = pose.position.x();
  msg->pose.pose.position.y = pose.position.y();
  msg->pose.pose.position.z = pose.position.z();
  const Eigen::Quaterniond q_WB = pose.attitude();
  msg->pose.pose.orientation.x = q_WB.x();
  msg->pose.pose.orientation.y = q_WB.y();
  msg->pose.pose.orientation.z = q_WB.z();
  msg->pose.pose.orientation.w = q_WB.w();
  const Eigen::Matrix<double, 6, 1> nu = pose.twist();
  msg->twist.twist.linear.x = nu(0);
  msg->twist.twist.linear.y = nu(1);
  msg->twist.twist.linear.z = nu(2);
  msg->twist.twist.angular.x = nu(3);
  msg->twist.twist.angular.y = nu(4);
  msg->twist.twist.angular.z = nu(5);
}

}  // namespace towsim::dds
