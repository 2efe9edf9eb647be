// wire/topic_names and wire/topic_table: ROS 2 topic names on DDS ("rt/" prefix), namespaces,
// scopes. Every name the node uses, exactly, for the default namespace, the root and a nested
// one: these are the wire contract (docs/contract.md §3, docs/topics.md) and must not change.

#include <string>

#include <gtest/gtest.h>

#include "wire/topic_names.h"

namespace towsim::wire {
namespace {

// the node's topics of one body, in a namespace whose prefix is `p` ("rt/towsim/")
void ExpectNames(const TopicNames& n, const std::string& p) {
  EXPECT_EQ(n.prefix(), p);
  EXPECT_EQ(n.Name(Topic::kSceneInfo), p + "scene_info");
  EXPECT_EQ(n.Name(Topic::kStatus), p + "status");
  EXPECT_EQ(n.Name(Topic::kCableState), p + "cable/state");
  EXPECT_EQ(n.Name(Topic::kCableStartForce), p + "cable/start_force");
  EXPECT_EQ(n.Name(Topic::kCableEndForce, "tether"), p + "tether/end_force");
  EXPECT_EQ(n.Name(Topic::kSimControl), p + "sim_control");
  EXPECT_EQ(n.Name(Topic::kWinchCommand), p + "winch/command");
  EXPECT_EQ(n.Name(Topic::kMarkers), p + "markers");
  EXPECT_EQ(n.Name(Topic::kOdom, "towfish"), p + "towfish/odom");
  EXPECT_EQ(n.Name(Topic::kCableForce, "tow_vehicle"), p + "tow_vehicle/cable_force");
  EXPECT_EQ(n.Name(Topic::kAltitude, "towfish"), p + "towfish/altitude");
  EXPECT_EQ(n.Name(Topic::kPressure, "towfish"), p + "towfish/pressure");
  EXPECT_EQ(n.Name(Topic::kEnvironment, "towfish"), p + "towfish/environment");
  EXPECT_EQ(n.Name(Topic::kCommand, "tow_vehicle"), p + "tow_vehicle/command");
  EXPECT_EQ(n.Name(Topic::kPoseCommand, "ship"), p + "ship/pose_command");
  // the root topics stay at the root in every namespace
  EXPECT_EQ(n.Name(Topic::kClock), "rt/clock");
  EXPECT_EQ(n.Name(Topic::kTf), "rt/tf");
  EXPECT_EQ(n.Name(Topic::kTfStatic), "rt/tf_static");
}

TEST(TopicNamesTest, DefaultNamespace) {
  const TopicNames n(kDefaultNamespace);
  EXPECT_EQ(n.ns(), "/towsim");
  ExpectNames(n, "rt/towsim/");
}

TEST(TopicNamesTest, RootNamespace) { ExpectNames(TopicNames("/"), "rt/"); }

TEST(TopicNamesTest, NestedNamespace) { ExpectNames(TopicNames("/fleet/a"), "rt/fleet/a/"); }

// a cable or winch of another name (the per-cable topics of a network) is a name of its row
TEST(TopicNamesTest, CableAndWinchScopes) {
  const TopicNames n("/towsim");
  EXPECT_EQ(n.Name(Topic::kCableState, kOneCable), "rt/towsim/cable/state");
  EXPECT_EQ(n.Name(Topic::kCableState, "bridle"), "rt/towsim/bridle/state");
  EXPECT_EQ(n.Name(Topic::kWinchCommand, "aft_winch"), "rt/towsim/aft_winch/command");
  EXPECT_THROW(n.Name(Topic::kOdom), std::invalid_argument);  // a body topic needs its body
}

TEST(TopicNamesTest, OwnerOfAName) {
  const TopicNames n("/towsim");
  EXPECT_EQ(n.Owner(Topic::kCommand, "rt/towsim/towfish/command"), "towfish");
  EXPECT_EQ(n.Owner(Topic::kCommand, "rt/towsim/a/b/command"), "a/b");
  EXPECT_EQ(n.Owner(Topic::kCommand, "rt/towsim/winch/command"), "winch");
  EXPECT_EQ(n.Owner(Topic::kCableState, "rt/towsim/cable/state"), "cable");
  EXPECT_EQ(n.Owner(Topic::kCommand, "rt/towsim//command"), std::nullopt);
  EXPECT_EQ(n.Owner(Topic::kCommand, "rt/other/towfish/command"), std::nullopt);
  EXPECT_EQ(n.Owner(Topic::kCommand, "rt/towsim/towfish/odom"), std::nullopt);
  EXPECT_EQ(n.Owner(Topic::kStatus, "rt/towsim/status"), std::nullopt);  // no owner
  EXPECT_EQ(TopicNames("/").Owner(Topic::kOdom, "rt/towfish/odom"), "towfish");
}

TEST(TopicNamesTest, RosAndDdsNames) {
  EXPECT_EQ(RosTopicName("rt/towsim/towfish/odom"), "/towsim/towfish/odom");
  EXPECT_EQ(RosTopicName("rt/clock"), "/clock");
  EXPECT_EQ(RosTopicName("ros_discovery_info"), "/ros_discovery_info");
  EXPECT_EQ(RosTopicName("/already"), "/already");
  EXPECT_EQ(DdsTopicName("/towsim/status"), "rt/towsim/status");
  EXPECT_EQ(DdsTopicName("towsim/status"), "rt/towsim/status");
  EXPECT_EQ(DdsTopicName("/clock"), "rt/clock");
}

// one row per topic, each with a type, and the direction and QoS the node uses
TEST(TopicTableTest, RowsOfTheContract) {
  const std::vector<TopicSpec>& table = TopicTable();
  ASSERT_EQ(table.size(), 19u);
  EXPECT_EQ(table.front().topic, Topic::kSceneInfo);  // scene_info first
  for (size_t i = 0; i < table.size(); ++i) {
    EXPECT_NE(table[i].type, nullptr) << table[i].name;
    EXPECT_EQ(&SpecOf(table[i].topic), &table[i]) << table[i].name;  // one row per topic
  }
  EXPECT_EQ(SpecOf(Topic::kSceneInfo).qos, QosProfile::kLatched);
  EXPECT_EQ(SpecOf(Topic::kTfStatic).qos, QosProfile::kLatched);
  EXPECT_EQ(SpecOf(Topic::kCommand).qos, QosProfile::kCommand);
  EXPECT_EQ(SpecOf(Topic::kWinchCommand).qos, QosProfile::kCommand);
  EXPECT_EQ(SpecOf(Topic::kSimControl).qos, QosProfile::kControl);
  EXPECT_EQ(SpecOf(Topic::kOdom).qos, QosProfile::kState);
  EXPECT_EQ(SpecOf(Topic::kCommand).direction, Direction::kIn);
  EXPECT_EQ(SpecOf(Topic::kSimControl).direction, Direction::kIn);
  EXPECT_EQ(SpecOf(Topic::kWinchCommand).direction, Direction::kIn);
  EXPECT_EQ(SpecOf(Topic::kOdom).direction, Direction::kOut);
  EXPECT_EQ(SpecOf(Topic::kPoseCommand).direction, Direction::kIn);
  EXPECT_EQ(SpecOf(Topic::kPoseCommand).scope, Scope::kBody);
  EXPECT_EQ(SpecOf(Topic::kPoseCommand).type, SpecOf(Topic::kOdom).type);  // nav_msgs/Odometry
  EXPECT_EQ(SpecOf(Topic::kCableState).scope, Scope::kCable);
  // a held end's force: the type of a body's cable_force, one per cable
  EXPECT_EQ(SpecOf(Topic::kCableStartForce).scope, Scope::kCable);
  EXPECT_EQ(SpecOf(Topic::kCableEndForce).scope, Scope::kCable);
  EXPECT_EQ(SpecOf(Topic::kCableStartForce).type, SpecOf(Topic::kCableForce).type);
  EXPECT_EQ(SpecOf(Topic::kCableEndForce).direction, Direction::kOut);
  EXPECT_EQ(SpecOf(Topic::kCableEndForce).qos, QosProfile::kState);
  EXPECT_EQ(SpecOf(Topic::kWinchCommand).scope, Scope::kWinch);
  EXPECT_STREQ(SpecOf(Topic::kOdom).type->m_typename, "nav_msgs::msg::dds_::Odometry_");
  // a commanded vehicle's actuators: out, per body, the odometry's QoS
  EXPECT_EQ(SpecOf(Topic::kActuatorState).scope, Scope::kBody);
  EXPECT_EQ(SpecOf(Topic::kActuatorState).direction, Direction::kOut);
  EXPECT_EQ(SpecOf(Topic::kActuatorState).qos, SpecOf(Topic::kOdom).qos);
  EXPECT_STREQ(SpecOf(Topic::kActuatorState).name, "actuator_state");
  EXPECT_STREQ(SpecOf(Topic::kActuatorState).type->m_typename,
               "towsim_msgs::msg::dds_::ActuatorState_");
}

TEST(TopicNamesTest, ChecksNamespaces) {
  EXPECT_EQ(CheckNamespace("/towsim"), "");
  EXPECT_EQ(CheckNamespace("/"), "");
  EXPECT_EQ(CheckNamespace("/a/_b2"), "");
  EXPECT_EQ(CheckNamespace("towsim"), "must start with '/' (e.g. /towsim)");
  EXPECT_EQ(CheckNamespace(""), "must start with '/' (e.g. /towsim)");
  EXPECT_EQ(CheckNamespace("/towsim/"), "must not end with '/'");
  EXPECT_EQ(CheckNamespace("/a//b"), "segment '' must match [A-Za-z_][A-Za-z0-9_]*");
  EXPECT_EQ(CheckNamespace("/2d"), "segment '2d' must match [A-Za-z_][A-Za-z0-9_]*");
  EXPECT_EQ(CheckNamespace("/a-b"), "segment 'a-b' must match [A-Za-z_][A-Za-z0-9_]*");
}

TEST(TopicNamesTest, ChecksBodyNames) {
  EXPECT_EQ(CheckBodyName("tow_vehicle"), "");
  EXPECT_NE(CheckBodyName("tow vehicle"), "");
  EXPECT_NE(CheckBodyName("1fish"), "");
  EXPECT_NE(CheckBodyName(""), "");
}

}  // namespace
}  // namespace towsim::wire
