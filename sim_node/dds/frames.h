#pragma once
// The frames of the towsim topics and their tf tree (REP-103 / REP-105 with suffixed NED and
// FRD frames; docs/frames.md). Pure translators: no DDS entities, no clocks.
//
//   world            ENU (x east, y north, z up): the root viewers (Foxglove, rviz2) expect
//   world_ned        NED (x north, y east, z down): the physics' world frame W
//   <b>_frd          body b, forward-starboard-down: the physics' body frame B
//   <b>              body b, forward-left-up (REP-103's body axes)
//   <c>_start,       the attachment points of cable c: children of <b>_frd (an end on a body,
//   <c>_end          offset at_B, axes of B) or of world_ned (a fixed end, or a driven end at
//                    its moving point, axes of world_ned); a free end has no frame. The one
//                    cable is named "cable": cable_start, cable_end
//
//   /tf_static  world -> world_ned, <b>_frd -> <b>, <b>_frd | world_ned -> <c>_start | <c>_end
//               of the body-held and fixed ends (cables in the scene's order, the start
//               before the end)
//   /tf         world_ned -> <b>_frd: (p_WB, q_WB), the pose of the odometry of the same state;
//               then world_ned -> <c>_start | <c>_end of each driven end (the same order):
//               r(t) = position + velocity t (core/model.h, docs/frames.md), no rotation
//
// A transform "parent -> child" holds the pose of the child frame in the parent frame
// (geometry_msgs/Transform: translation = child origin in parent, rotation q_parent_child).

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/simulation.h"
#include "dds/messages.h"

namespace towsim::dds {

inline constexpr const char* kEnuWorldFrame = "world";
inline constexpr const char* kCableStartFrame = "cable_start";
inline constexpr const char* kCableEndFrame = "cable_end";

// "<b>_frd", the frame of odometry twists and cable forces
std::string FrdFrame(const std::string& body);
// "<c>_start" (end 0) or "<c>_end" (end 1): the frame of an end of the cable named `cable`
// ("cable": kCableStartFrame, kCableEndFrame)
std::string CableEndFrame(const std::string& cable, int end);

// q_world_worldned: NED in ENU, a half turn about (1, 1, 0)/sqrt(2) (x_N = y_E, y_N = x_E,
// z_N = -z_E)
Eigen::Quaterniond EnuFromNed();
// q_frd_flu: FLU in FRD, a half turn about x (y_L = -y_S, z_U = -z_D)
Eigen::Quaterniond FrdFromFlu();
// a point of world_ned in world (ENU): (y, x, -z)
core::Vec3 NedToEnu(const core::Vec3& p_W);

// A tf2_msgs/TFMessage with a fixed list of edges (parent, child); owns its strings and
// sequence, neither copyable nor movable (the struct points into the object)
class TransformsMessage {
 public:
  explicit TransformsMessage(const std::vector<std::pair<std::string, std::string>>& edges);
  TransformsMessage(const TransformsMessage&) = delete;
  TransformsMessage& operator=(const TransformsMessage&) = delete;
  int size() const { return static_cast<int>(transforms_.size()); }
  TransformStampedMsg& transform(int i) { return transforms_[static_cast<size_t>(i)]; }
  TfMsg msg;

 private:
  std::vector<std::string> names_;  // parent, child, parent, child, ...
  std::vector<TransformStampedMsg> transforms_;
};

// sets translation and rotation of a transform
void SetTransform(const core::Vec3& translation, const Eigen::Quaterniond& rotation,
                  TransformStampedMsg* out);

// the static transforms of sim's scene (listed above), stamped with sim.time()
std::unique_ptr<TransformsMessage> StaticTransforms(const core::Simulation& sim);

// the edges world_ned -> <b>_frd of every body, in body order, then world_ned -> <c>_start |
// <c>_end of every driven cable end
std::unique_ptr<TransformsMessage> BodyTransforms(const core::Simulation& sim);
// fills the edges of BodyTransforms from sim's state: (p_WB, q_WB) of each body, the driven
// point r(t) = position + velocity t of each driven end, stamped sim.time()
void ToBodyTransforms(const core::Simulation& sim, TransformsMessage* out);

}  // namespace towsim::dds
