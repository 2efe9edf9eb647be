#pragma once
// DDS topic names of the towsim node (docs/contract.md §3). A ROS 2 topic /a/b travels on DDS as "rt/a/b";
// the node's topics live under a namespace (default /towsim) so that several systems share a
// domain, except the root topics (/clock, /tf), which ROS 2 tools expect at the root. The names
// come from the rows of wire/topic_table.h; the prefix "rt" is written here only.
//
//   TopicNames names("/towsim");
//   names.Name(Topic::kOdom, "towfish")  ->  "rt/towsim/towfish/odom"
//   names.Name(Topic::kCableState)       ->  "rt/towsim/cable/state"

#include <optional>
#include <string>

#include "wire/topic_table.h"

namespace towsim::wire {

inline constexpr const char* kDefaultNamespace = "/towsim";

// Checks a ROS 2 namespace: "/" or "/seg[/seg...]", each segment [A-Za-z_][A-Za-z0-9_]*, no
// trailing "/". Returns an empty string if valid, else what is wrong.
std::string CheckNamespace(const std::string& ns);

// Checks a body name for use in a topic name: [A-Za-z_][A-Za-z0-9_]*. Empty if valid.
std::string CheckBodyName(const std::string& name);

// the ROS 2 name of a DDS topic: "rt/towsim/towfish/odom" -> "/towsim/towfish/odom" (a name
// without "rt/" gets a leading "/")
std::string RosTopicName(const std::string& dds_topic);
// the DDS name of a ROS 2 topic: "/towsim/status" (or "towsim/status") -> "rt/towsim/status"
std::string DdsTopicName(const std::string& ros_topic);

class TopicNames {
 public:
  // ns: a namespace that passes CheckNamespace (not checked again here)
  explicit TopicNames(std::string ns);

  const std::string& ns() const { return ns_; }
  // "rt" + ns + "/" ("rt/" for the namespace "/"): what every name below the namespace starts
  // with
  const std::string& prefix() const { return prefix_; }

  // The DDS name of `topic`. `owner`: the body of a kBody row (required); the cable of a kCable
  // row and the winch of a kWinch row ("": the one cable or winch, kOneCable / kOneWinch);
  // ignored for kRoot and kNode rows.
  std::string Name(Topic topic, const std::string& owner = "") const;

  // the owner of `dds_topic` if it is a name of `topic` (kBody, kCable, kWinch rows): "towfish"
  // for Owner(Topic::kCommand, "rt/towsim/towfish/command"); nullopt otherwise
  std::optional<std::string> Owner(Topic topic, const std::string& dds_topic) const;

 private:
  std::string ns_;
  std::string prefix_;  // "rt" + ns + "/"
};

}  // namespace towsim::wire
