#include "wire/topic_table.h"

#include <stdexcept>

#include "geometry_msgs.h"
#include "nav_msgs.h"
#include "rosgraph_msgs.h"
#include "sensor_msgs.h"
#include "tf2_msgs.h"
#include "towsim_msgs.h"
#include "visualization_msgs.h"

namespace towsim::wire {
namespace {

std::vector<TopicSpec> BuildTable() {
  using T = Topic;
  using S = Scope;
  using Q = QosProfile;
  constexpr Direction kOut = Direction::kOut, kIn = Direction::kIn;
  return {
      {T::kSceneInfo, S::kNode, "scene_info", &towsim_msgs_msg_dds__SceneInfo__desc, Q::kLatched,
       kOut},
      // /clock at the root, where ROS 2 nodes with use_sim_time look
      {T::kClock, S::kRoot, "clock", &rosgraph_msgs_msg_dds__Clock__desc, Q::kState, kOut},
      {T::kStatus, S::kNode, "status", &towsim_msgs_msg_dds__SimStatus__desc, Q::kState, kOut},
      {T::kCableState, S::kCable, "state", &towsim_msgs_msg_dds__CableState__desc, Q::kState, kOut},
      // the force at a cable end that forces.csv has a row of (docs/topics.md "Cable end
      // forces"): an end held by a fixed or driven support (frame world_ned, the force on the
      // support, moment 0), or an end on a body held by two or more cable ends (frame <b>_frd,
      // the force and moment of that end alone about the body origin)
      {T::kCableStartForce, S::kCable, "start_force", &geometry_msgs_msg_dds__WrenchStamped__desc,
       Q::kState, kOut},
      {T::kCableEndForce, S::kCable, "end_force", &geometry_msgs_msg_dds__WrenchStamped__desc,
       Q::kState, kOut},
      {T::kSimControl, S::kNode, "sim_control", &towsim_msgs_msg_dds__SimControl__desc, Q::kControl,
       kIn},
      // the winch at the cable's start (docs/winch_dds.md)
      {T::kWinchCommand, S::kWinch, "command", &towsim_msgs_msg_dds__WinchCommand__desc,
       Q::kCommand, kIn},
      // tf at the root, where tf2 listeners and viewers look (docs/frames.md)
      {T::kTf, S::kRoot, "tf", &tf2_msgs_msg_dds__TFMessage__desc, Q::kState, kOut},
      {T::kTfStatic, S::kRoot, "tf_static", &tf2_msgs_msg_dds__TFMessage__desc, Q::kLatched, kOut},
      {T::kMarkers, S::kNode, "markers", &visualization_msgs_msg_dds__MarkerArray__desc, Q::kState,
       kOut},
      {T::kOdom, S::kBody, "odom", &nav_msgs_msg_dds__Odometry__desc, Q::kState, kOut},
      {T::kCableForce, S::kBody, "cable_force", &geometry_msgs_msg_dds__WrenchStamped__desc,
       Q::kState, kOut},
      {T::kAltitude, S::kBody, "altitude", &sensor_msgs_msg_dds__Range__desc, Q::kState, kOut},
      {T::kPressure, S::kBody, "pressure", &sensor_msgs_msg_dds__FluidPressure__desc, Q::kState,
       kOut},
      {T::kEnvironment, S::kBody, "environment", &towsim_msgs_msg_dds__BodyEnvironment__desc,
       Q::kState, kOut},
      // a commanded vehicle's command in force and actuator states, its actuators.csv row
      // (docs/topics.md "Actuator state"): only for the vehicles that have a command topic
      {T::kActuatorState, S::kBody, "actuator_state", &towsim_msgs_msg_dds__ActuatorState__desc,
       Q::kState, kOut},
      {T::kCommand, S::kBody, "command", &towsim_msgs_msg_dds__ActuatorCommand__desc, Q::kCommand,
       kIn},
      // an external vessel's pose (docs/vessels.md "External vessels"): its odometry as the
      // node publishes it on odom, stamped with the time the pose belongs to
      {T::kPoseCommand, S::kBody, "pose_command", &nav_msgs_msg_dds__Odometry__desc, Q::kCommand,
       kIn},
  };
}

}  // namespace

const std::vector<TopicSpec>& TopicTable() {
  static const std::vector<TopicSpec> table = BuildTable();
  return table;
}

const TopicSpec& SpecOf(Topic topic) {
  for (const TopicSpec& s : TopicTable()) {
    if (s.topic == topic) return s;
  }
  throw std::logic_error("wire::SpecOf: a Topic without a row in wire/topic_table.cc");
}

}  // namespace towsim::wire
