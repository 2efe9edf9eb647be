#pragma once
// DDS topic names of the towsim node (DESIGN §3). A ROS 2 topic /a/b travels on DDS as "rt/a/b";
// the node's topics live under a namespace (default /towsim) so that several systems share a
// domain, except /clock, which ROS 2 nodes with use_sim_time expect at the root.
//
//   TopicNames names("/towsim");
//   names.odom("towfish")  ->  "rt/towsim/towfish/odom"

#include <string>

namespace towsim::dds {

inline constexpr const char* kDefaultNamespace = "/towsim";

// Checks a ROS 2 namespace: "/" or "/seg[/seg...]", each segment [A-Za-z_][A-Za-z0-9_]*, no
// trailing "/". Returns an empty string if valid, else what is wrong.
std::string CheckNamespace(const std::string& ns);

// Checks a body name for use in a topic name: [A-Za-z_][A-Za-z0-9_]*. Empty if valid.
std::string CheckBodyName(const std::string& name);

class TopicNames {
 public:
  // ns: a namespace that passes CheckNamespace (not checked again here)
  explicit TopicNames(std::string ns);

  const std::string& ns() const { return ns_; }
  std::string clock() const { return "rt/clock"; }
  std::string odom(const std::string& body) const { return prefix_ + body + "/odom"; }
  std::string cable_force(const std::string& body) const { return prefix_ + body + "/cable_force"; }
  std::string command(const std::string& body) const { return prefix_ + body + "/command"; }
  std::string altitude(const std::string& body) const { return prefix_ + body + "/altitude"; }
  std::string pressure(const std::string& body) const { return prefix_ + body + "/pressure"; }
  std::string environment(const std::string& body) const {
    return prefix_ + body + "/environment";
  }
  std::string cable_state() const { return prefix_ + "cable/state"; }
  // the winch at the cable's start (towsim_msgs/WinchCommand, docs/winch_dds.md)
  std::string winch_command() const { return prefix_ + "winch/command"; }
  std::string status() const { return prefix_ + "status"; }
  std::string sim_control() const { return prefix_ + "sim_control"; }
  std::string scene_info() const { return prefix_ + "scene_info"; }
  // tf at the root, where tf2 listeners and viewers look (docs/frames.md)
  std::string tf() const { return "rt/tf"; }
  std::string tf_static() const { return "rt/tf_static"; }
  std::string markers() const { return prefix_ + "markers"; }

 private:
  std::string ns_;
  std::string prefix_;  // "rt" + ns + "/"
};

}  // namespace towsim::dds
