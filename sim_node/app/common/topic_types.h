#pragma once
// The generated types of the wire contract (msgs/) by name, for the tools that create DDS
// endpoints from a recording or a list of topics (towsim_record, towsim_replay): the DDS type
// name ("nav_msgs::msg::dds_::Odometry_"), the ROS 2 type name rosbag2 writes
// ("nav_msgs/msg/Odometry") and the topic descriptor idlc generated.

#include <string>
#include <vector>

#include "dds/dds.h"
#include "wire/topic_names.h"

namespace towsim::app {

// every topic type of docs/contract.md §3 (those of wire/topic_table.h)
const std::vector<const dds_topic_descriptor_t*>& ContractTypes();

// the descriptor of a ROS 2 type name ("nav_msgs/msg/Odometry"); nullptr if not a contract type
const dds_topic_descriptor_t* DescriptorOfRos2Type(const std::string& ros2_type);

// one topic of a node: its DDS name ("rt/towsim/towfish/odom"), type and durability
struct NodeTopic {
  std::string dds_name;
  const dds_topic_descriptor_t* descriptor = nullptr;
  bool transient_local = false;  // scene_info and /tf_static
};

// every topic of a towsim node of namespace `names` with these bodies and cables (the table of
// wire/topic_table.h: /clock, status, <cable>/state of each cable, sim_control, /tf,
// /tf_static, markers, and per body odom, cable_force, altitude, pressure and command);
// scene_info first when `with_scene_info`. `cables`: SceneInfo.cables; empty: the one cable
// ("cable", the scene info of a towsim that did not list its cables). `winches`:
// SceneInfo.winches, each winch's <w>/command; empty: the one winch's winch/command
std::vector<NodeTopic> NodeTopics(const wire::TopicNames& names,
                                  const std::vector<std::string>& bodies,
                                  bool with_scene_info = false,
                                  const std::vector<std::string>& cables = {},
                                  const std::vector<std::string>& winches = {});

}  // namespace towsim::app
