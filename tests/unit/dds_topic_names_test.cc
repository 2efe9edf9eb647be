// sim_node/dds/topic_names: ROS 2 topic names on DDS ("rt/" prefix), namespaces.

#include <gtest/gtest.h>

#include "dds/topic_names.h"

namespace towsim::dds {
namespace {

TEST(TopicNamesTest, DefaultNamespace) {
  const TopicNames n(kDefaultNamespace);
  EXPECT_EQ(n.odom("towfish"), "rt/towsim/towfish/odom");
  EXPECT_EQ(n.cable_force("tow_vehicle"), "rt/towsim/tow_vehicle/cable_force");
  EXPECT_EQ(n.command("tow_vehicle"), "rt/towsim/tow_vehicle/command");
  EXPECT_EQ(n.cable_state(), "rt/towsim/cable/state");
  EXPECT_EQ(n.status(), "rt/towsim/status");
  EXPECT_EQ(n.sim_control(), "rt/towsim/sim_control");
  EXPECT_EQ(n.winch_command(), "rt/towsim/winch/command");
  EXPECT_EQ(n.scene_info(), "rt/towsim/scene_info");
  EXPECT_EQ(n.clock(), "rt/clock");  // /clock stays at the root
}

TEST(TopicNamesTest, OtherNamespaces) {
  EXPECT_EQ(TopicNames("/fleet/a").status(), "rt/fleet/a/status");
  EXPECT_EQ(TopicNames("/").status(), "rt/status");
  EXPECT_EQ(TopicNames("/sys_2").clock(), "rt/clock");
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
}  // namespace towsim::dds
