// wire/decoders: each decoder turns a message, as a reader takes it, into a plain value with
// every field of the message it keeps (the strings and sequences copied).

#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "wire/decoders.h"

namespace towsim::wire {
namespace {

char* Text(const char* s) { return const_cast<char*>(s); }

TEST(WireDecodersTest, Stamp) {
  builtin_interfaces_msg_dds__Time_ stamp{12, 500000000};
  EXPECT_DOUBLE_EQ(StampSeconds(stamp), 12.5);
}

TEST(WireDecodersTest, Status) {
  char* failsafe[] = {Text("towfish")};
  towsim_msgs_msg_dds__SimStatus_ m{};
  m.run_id = Text("r2");
  m.mode = Text("lockstep");
  m.message = Text("note");
  m.state = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;
  m.health = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE;
  m.step = 40;
  m.sim_time = 2.0;
  m.rate = 1.5;
  m.failsafe_count = 3;
  m.failsafe_bodies = {1, 1, failsafe, false};
  m.commands_received = 7;
  m.commands_rejected = 2;
  m.commands_clamped = 1;
  m.lockstep_timeouts = 4;
  const SimStatus s = DecodeStatus(m);
  EXPECT_EQ(s.run_id, "r2");
  EXPECT_EQ(s.mode, "lockstep");
  EXPECT_EQ(s.message, "note");
  EXPECT_EQ(s.step, 40u);
  EXPECT_EQ(s.t, 2.0);
  EXPECT_EQ(s.rate, 1.5);
  EXPECT_EQ(s.failsafe_count, 3u);
  EXPECT_EQ(s.failsafe_bodies, std::vector<std::string>{"towfish"});
  EXPECT_EQ(s.commands_received, 7u);
  EXPECT_EQ(s.commands_rejected, 2u);
  EXPECT_EQ(s.commands_clamped, 1u);
  EXPECT_EQ(s.lockstep_timeouts, 4u);
  EXPECT_TRUE(s.finished());
  EXPECT_FALSE(s.failed());
  EXPECT_TRUE(s.terminal());
  EXPECT_FALSE(s.running());
  EXPECT_FALSE(s.paused());
  EXPECT_TRUE(s.failsafe());

  m.state = towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
  m.health = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_OK;
  m.message = nullptr;  // an absent string reads as ""
  const SimStatus w = DecodeStatus(m);
  EXPECT_TRUE(w.running());
  EXPECT_FALSE(w.terminal());
  EXPECT_FALSE(w.failsafe());
  EXPECT_EQ(w.message, "");

  m.state = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
  const SimStatus f = DecodeStatus(m);
  EXPECT_TRUE(f.failed());
  EXPECT_TRUE(f.terminal());
  EXPECT_FALSE(f.finished());
}

TEST(WireDecodersTest, SceneInfo) {
  char* bodies[] = {Text("tow_vehicle"), Text("towfish")};
  char* commanded[] = {Text("tow_vehicle")};
  towsim_msgs_msg_dds__SceneInfo_ m{};
  m.run_id = Text("r1");
  m.scene = Text("case1");
  m.mode = Text("fast");
  m.step_size = 0.05;
  m.duration = 60.0;
  m.command_timeout = 0.5;
  m.bodies = {2, 2, bodies, false};
  m.commanded_bodies = {1, 1, commanded, false};
  m.cable_nodes = 21;
  m.has_winch = true;
  m.winch_min_length = 10.0;
  m.winch_max_length = 300.0;
  m.winch_max_speed = 1.5;
  m.winch_max_acceleration = 0.25;
  const SceneInfo s = DecodeSceneInfo(m);
  EXPECT_EQ(s.run_id, "r1");
  EXPECT_EQ(s.scene, "case1");
  EXPECT_EQ(s.mode, "fast");
  EXPECT_EQ(s.step_size, 0.05);
  EXPECT_EQ(s.duration, 60.0);
  EXPECT_EQ(s.command_timeout, 0.5);
  EXPECT_EQ(s.bodies, (std::vector<std::string>{"tow_vehicle", "towfish"}));
  EXPECT_EQ(s.commanded_bodies, std::vector<std::string>{"tow_vehicle"});
  EXPECT_EQ(s.cable_nodes, 21u);
  EXPECT_TRUE(s.has_winch);
  EXPECT_EQ(s.winch_min_length, 10.0);
  EXPECT_EQ(s.winch_max_length, 300.0);
  EXPECT_EQ(s.winch_max_speed, 1.5);
  EXPECT_EQ(s.winch_max_acceleration, 0.25);
  // no network fields: none listed (a node that does not list them has the one cable)
  EXPECT_TRUE(s.cables.empty());
  EXPECT_TRUE(s.winches.empty());
  EXPECT_EQ(s.NodesOf("cable"), 0u);
}

TEST(WireDecodersTest, SceneInfoListsTheCablesAndWinches) {
  char* cables[] = {Text("main"), Text("tether")};
  uint32_t counts[] = {21, 11};
  char* winches[] = {Text("winch")};
  char* winch_cables[] = {Text("main")};
  towsim_msgs_msg_dds__SceneInfo_ m{};
  m.run_id = Text("r1");
  m.scene = Text("two_part_tow");
  m.mode = Text("fast");
  m.cable_nodes = 21;
  m.cables = {2, 2, cables, false};
  m.cable_node_counts = {2, 2, counts, false};
  m.winches = {1, 1, winches, false};
  m.winch_cables = {1, 1, winch_cables, false};
  const SceneInfo s = DecodeSceneInfo(m);
  EXPECT_EQ(s.cables, (std::vector<std::string>{"main", "tether"}));
  EXPECT_EQ(s.cable_node_counts, (std::vector<uint32_t>{21, 11}));
  EXPECT_EQ(s.winches, std::vector<std::string>{"winch"});
  EXPECT_EQ(s.winch_cables, std::vector<std::string>{"main"});
  EXPECT_EQ(s.NodesOf("main"), 21u);
  EXPECT_EQ(s.NodesOf("tether"), 11u);
  EXPECT_EQ(s.NodesOf("cable"), 0u);
}

TEST(WireDecodersTest, Odometry) {
  nav_msgs_msg_dds__Odometry_ m{};
  m.header.stamp = {3, 250000000};
  m.pose.pose.position = {1.0, -2.0, 30.0};
  m.pose.pose.orientation = {0.0, 0.0, 0.6, 0.8};
  m.twist.twist.linear = {2.5, 0.1, -0.2};
  m.twist.twist.angular = {0.01, 0.02, 0.03};
  const Odometry o = DecodeOdometry(m);
  EXPECT_EQ(o.t, 3.25);
  EXPECT_EQ(o.x, 1.0);
  EXPECT_EQ(o.y, -2.0);
  EXPECT_EQ(o.z, 30.0);
  EXPECT_EQ(o.qx, 0.0);
  EXPECT_EQ(o.qy, 0.0);
  EXPECT_EQ(o.qz, 0.6);
  EXPECT_EQ(o.qw, 0.8);
  EXPECT_EQ(o.u, 2.5);
  EXPECT_EQ(o.v, 0.1);
  EXPECT_EQ(o.w, -0.2);
  EXPECT_EQ(o.p, 0.01);
  EXPECT_EQ(o.q, 0.02);
  EXPECT_EQ(o.r, 0.03);
}

TEST(WireDecodersTest, Wrench) {
  geometry_msgs_msg_dds__WrenchStamped_ m{};
  m.header.stamp = {1, 0};
  m.wrench.force = {-1200.0, 3.0, 450.0};
  m.wrench.torque = {0.5, -6.0, 7.0};
  const Wrench f = DecodeWrench(m);
  EXPECT_EQ(f.t, 1.0);
  EXPECT_EQ(f.fx, -1200.0);
  EXPECT_EQ(f.fy, 3.0);
  EXPECT_EQ(f.fz, 450.0);
  EXPECT_EQ(f.mx, 0.5);
  EXPECT_EQ(f.my, -6.0);
  EXPECT_EQ(f.mz, 7.0);
}

TEST(WireDecodersTest, CableState) {
  geometry_msgs_msg_dds__Point_ positions[] = {{0.0, 0.0, 1.0}, {-5.0, 0.5, 4.0}};
  double tensions[] = {1500.0, 1320.0};
  towsim_msgs_msg_dds__CableState_ m{};
  m.header.stamp = {0, 500000000};
  m.step = 10;
  m.positions = {2, 2, positions, false};
  m.tensions = {2, 2, tensions, false};
  m.paid_out_length = 150.0;
  m.winch_speed = -0.5;
  m.drum_tension = 1510.0;
  m.node_count = 2;
  const CableState c = DecodeCableState(m);
  EXPECT_EQ(c.step, 10u);
  EXPECT_EQ(c.t, 0.5);
  EXPECT_EQ(c.x, (std::vector<double>{0.0, -5.0}));
  EXPECT_EQ(c.y, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(c.z, (std::vector<double>{1.0, 4.0}));
  EXPECT_EQ(c.tension, (std::vector<double>{1500.0, 1320.0}));
  EXPECT_EQ(c.paid_out_length, 150.0);
  EXPECT_EQ(c.winch_speed, -0.5);
  EXPECT_EQ(c.drum_tension, 1510.0);
  EXPECT_EQ(c.node_count, 2u);
  EXPECT_LT(CableState{}.t, 0.0);  // a default value is "none yet"
}

}  // namespace
}  // namespace towsim::wire
