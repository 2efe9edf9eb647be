#pragma once
// A Foxglove layout for a scene (docs/foxglove.md "A layout for any scene"): the JSON Foxglove
// (and Lichtblick) import with *Layout -> Import from file*, written by
// `towsim_foxglove --layout SCENE`; config/foxglove/towsim.json is its output for
// config/scenes/case1_forward.yaml.
//
// Panels, every topic named as the node names it (wire/topic_names.h):
//   3D!towsim        follows the frame of the first vehicle (else of the first body; `world`
//                    without bodies); its camera frames the whole system (CameraDistance)
//   Plot!depth       each body's depth: <ns>/<b>/odom.pose.pose.position.z (world_ned z)
//   Plot!tension     each cable's top and bottom node: <ns>/<c>/state.tensions[0] and
//                    .tensions[E] (E: the cable's element count, the bottom node's index);
//                    a winched cable's node count changes as the drum pays out
//                    (docs/winch.md), so its bottom node is .tensions[-1], the last element
//                    (Foxglove's message path syntax counts negative indices from the end)
//   Plot!speed       each vehicle's and vessel's surge speed u: odom.twist.twist.linear.x
//   Teleop!<v>       the first commanded vehicle's <ns>/<v>/command (docs/foxglove.md,
//                    "Publishing from Foxglove"): up = the largest thrust the scene's script
//                    gives it (else its propeller's max_thrust), left / right = 20 deg of
//                    rudder (at most its max_deflection), down = stop
// A panel without anything to show is left out (no vehicle: no speed plot, no Teleop).

#include <string>

#include "core/model.h"
#include "wire/topic_names.h"

namespace towsim::app {

// the vertical field of view of the 3D panel's camera [deg]
inline constexpr double kLayoutFovyDeg = 45.0;

// the reach of the system from the followed body [m]: the sum of the cables' unstretched
// lengths (a winched cable's max_length), an upper bound of the distance from the followed
// body to any point of the cables and bodies connected to it
double SystemReach(const core::Model& model);

// the 3D camera's distance from its target [m]: a sphere of radius R = SystemReach about the
// target fits in the vertical field of view fovy when d >= R / sin(fovy / 2); rounded up to
// 10 m
double CameraDistance(const core::Model& model);

// the layout JSON of `model` for a node of namespace `names` (two-space indent, a final
// newline)
std::string FoxgloveLayoutJson(const core::Model& model, const wire::TopicNames& names);

}  // namespace towsim::app
