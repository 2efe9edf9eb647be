#pragma once
// The generated types of the wire contract (msgs/) by name, for the tools that create DDS
// endpoints from a recording or a list of topics (towsim_record, towsim_replay): the DDS type
// name ("nav_msgs::msg::dds_::Odometry_"), the ROS 2 type name rosbag2 writes
// ("nav_msgs/msg/Odometry") and the topic descriptor idlc generated.

#include <string>
#include <vector>

#include "dds/dds.h"

namespace towsim::app {

// every topic type of DESIGN §3
const std::vector<const dds_topic_descriptor_t*>& ContractTypes();

// the descriptor of a ROS 2 type name ("nav_msgs/msg/Odometry"); nullptr if not a contract type
const dds_topic_descriptor_t* DescriptorOfRos2Type(const std::string& ros2_type);

}  // namespace towsim::app
