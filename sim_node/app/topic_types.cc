#include "app/topic_types.h"

#include <stdexcept>

#include "dds/messages.h"
#include "io/ros2_schemas.h"

namespace towsim::app {

const std::vector<const dds_topic_descriptor_t*>& ContractTypes() {
  static const std::vector<const dds_topic_descriptor_t*> types = {
      &rosgraph_msgs_msg_dds__Clock__desc,         &nav_msgs_msg_dds__Odometry__desc,
      &geometry_msgs_msg_dds__WrenchStamped__desc, &towsim_msgs_msg_dds__CableState__desc,
      &towsim_msgs_msg_dds__SimStatus__desc,       &towsim_msgs_msg_dds__SceneInfo__desc,
      &towsim_msgs_msg_dds__ActuatorCommand__desc, &towsim_msgs_msg_dds__SimControl__desc,
      &towsim_msgs_msg_dds__WinchCommand__desc,
      &sensor_msgs_msg_dds__Range__desc,           &sensor_msgs_msg_dds__FluidPressure__desc,
      &tf2_msgs_msg_dds__TFMessage__desc,          &visualization_msgs_msg_dds__MarkerArray__desc};
  return types;
}

const dds_topic_descriptor_t* DescriptorOfRos2Type(const std::string& ros2_type) {
  for (const dds_topic_descriptor_t* d : ContractTypes()) {
    try {
      if (io::Ros2TypeName(d->m_typename) == ros2_type) return d;
    } catch (const std::invalid_argument&) {
    }
  }
  return nullptr;
}

std::vector<NodeTopic> NodeTopics(const dds::TopicNames& names,
                                  const std::vector<std::string>& bodies, bool with_scene_info) {
  std::vector<NodeTopic> all;
  if (with_scene_info) {
    all.push_back({names.scene_info(), &towsim_msgs_msg_dds__SceneInfo__desc, true});
  }
  all.insert(all.end(), {
                            {names.clock(), &rosgraph_msgs_msg_dds__Clock__desc},
                            {names.status(), &towsim_msgs_msg_dds__SimStatus__desc},
                            {names.cable_state(), &towsim_msgs_msg_dds__CableState__desc},
                            {names.sim_control(), &towsim_msgs_msg_dds__SimControl__desc},
                            {names.winch_command(), &towsim_msgs_msg_dds__WinchCommand__desc},
                            {names.tf(), &tf2_msgs_msg_dds__TFMessage__desc},
                            {names.tf_static(), &tf2_msgs_msg_dds__TFMessage__desc, true},
                            {names.markers(), &visualization_msgs_msg_dds__MarkerArray__desc},
                        });
  for (const std::string& b : bodies) {
    all.push_back({names.odom(b), &nav_msgs_msg_dds__Odometry__desc});
    all.push_back({names.cable_force(b), &geometry_msgs_msg_dds__WrenchStamped__desc});
    all.push_back({names.altitude(b), &sensor_msgs_msg_dds__Range__desc});
    all.push_back({names.pressure(b), &sensor_msgs_msg_dds__FluidPressure__desc});
    all.push_back({names.command(b), &towsim_msgs_msg_dds__ActuatorCommand__desc});
  }
  return all;
}

}  // namespace towsim::app
