#pragma once
// ROS 2 message definitions of the wire contract (msgs/, docs/contract.md §3) as rosbag2 stores them in
// MCAP: schema name "pkg/msg/Type", encoding "ros2msg", data the complete message definition
// (https://github.com/ros2/rosbag2/blob/rolling/docs/message_definition_encoding.md):
//
//   <the type's .msg text>
//   ================================================================================   (80 '=')
//   MSG: pkg/Dependency
//   <its .msg text>
//   ...
//
// Dependencies are listed once each, depth first, the direct dependencies of a type in sorted
// order, each separator preceded by a newline: what rosbag2_cpp's LocalMessageDefinitionSource
// produces from the installed .msg files. The standard types (builtin_interfaces, std_msgs,
// geometry_msgs, nav_msgs, rosgraph_msgs) are their ROS 2 field definitions; towsim_msgs are
// the files of msgs/towsim_msgs/msg, embedded at configure time (one source of truth).

#include <string>
#include <vector>

#include "io/mcap_writer.h"

namespace towsim::io {

// ROS 2 type name as rosbag2 writes it ("nav_msgs/msg/Odometry") for a DDS type name
// ("nav_msgs::msg::dds_::Odometry_"); throws std::invalid_argument for unknown types.
std::string Ros2TypeName(const std::string& dds_type_name);

// the ros2msg schema text of a type ("nav_msgs/msg/Odometry" or "nav_msgs/Odometry") with all
// its dependencies, as rosbag2 writes it; throws std::invalid_argument for unknown types
std::string Ros2MsgSchema(const std::string& ros2_type_name);

// the .msg text of one type alone ("pkg/msg/Name" or "pkg/Name"); throws std::invalid_argument
const std::string& Ros2MsgText(const std::string& ros2_type_name);

// every type with a .msg text, "pkg/msg/Name", sorted
std::vector<std::string> Ros2KnownTypes();

// writes the rosbag2 metadata record (name "rosbag2", key "serialized_metadata": the bag
// information YAML of rosbag2_storage, metadata version 8) from what `writer` holds so far —
// call it before Close(), after the last message. `ros2 bag info` reads it (and the summary).
void AddRosbag2Metadata(McapWriter& writer, const std::string& storage_identifier = "mcap");

// the YAML text AddRosbag2Metadata writes (exposed for tests)
std::string Rosbag2MetadataYaml(const McapWriter& writer, const std::string& storage_identifier);

}  // namespace towsim::io
