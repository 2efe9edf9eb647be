// io/cdr_messages: every message type towsim publishes, serialized by Cyclone DDS itself
// (dds/raw_cdr: the bytes that go on the wire), decodes to exactly the values that were
// serialized; every truncation of those bytes and corrupt counts give a CdrError naming the
// field and offset, never a crash. One participant, DDS domain 90.
#include "io/cdr_messages.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/raw_cdr.h"
#include "io/cdr_reader.h"

namespace towsim::io::cdr {
namespace {

constexpr std::uint32_t kDomain = 90;

std::string Config() { return "file://" TOWSIM_SOURCE_DIR "/config/cyclonedds.xml"; }

class CdrMessagesTest : public ::testing::Test {
 protected:
  CdrMessagesTest() : participant_(kDomain, Config()) {}

  // the wire bytes of a sample of the generated C type with topic descriptor `desc`
  std::vector<std::uint8_t> Serialize(const dds_topic_descriptor_t* desc, const void* sample) {
    dds::RawType type(participant_, desc);
    return dds::CdrSample::FromSample(type, sample).bytes();
  }

  // every strict prefix that cuts into the fields throws CdrError with an offset <= its size
  // and the type name; prefixes that only drop trailing padding (count in the options'
  // low two bits, XCDR1) still decode
  template <class Decode>
  void ExpectTruncationsFail(const std::vector<std::uint8_t>& b, Decode decode,
                             const std::string& type) {
    const std::size_t padding = b[3] & 0x3;
    for (std::size_t n = 0; n < b.size(); ++n) {
      if (n >= b.size() - padding) {
        EXPECT_NO_THROW(decode(b.data(), n)) << type << " cut to " << n;
        continue;
      }
      try {
        decode(b.data(), n);
        ADD_FAILURE() << type << " cut to " << n << " of " << b.size() << " bytes decoded";
      } catch (const CdrError& e) {
        EXPECT_LE(e.offset(), n);
        EXPECT_NE(std::string(e.what()).find(type), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("at byte offset"), std::string::npos) << e.what();
      }
    }
  }

  dds::Participant participant_;
};

TEST_F(CdrMessagesTest, OdometryFromCycloneBytes) {
  dds::OdometryMsg m{};
  std::string frame = "world_ned", child = "towfish";  // lengths 10 and 8 with the NUL
  m.header.stamp.sec = -3;
  m.header.stamp.nanosec = 999999999u;
  m.header.frame_id = frame.data();
  m.child_frame_id = child.data();
  m.pose.pose.position = {199.57930000000002, -1.0 / 3.0, 1e-310};  // a subnormal too
  m.pose.pose.orientation = {0.1, -0.2, 0.3, std::sqrt(1.0 - 0.14)};
  for (int i = 0; i < 36; ++i) m.pose.covariance[i] = i * 0.125 - 2.0;
  m.twist.twist.linear = {6.0, -0.0, 1.7976931348623157e308};
  m.twist.twist.angular = {-1e-3, 2e-3, std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 36; ++i) m.twist.covariance[i] = -i * 1e-9;
  const auto b = Serialize(&nav_msgs_msg_dds__Odometry__desc, &m);
  const Odometry d = DecodeOdometry(b.data(), b.size());
  EXPECT_EQ(d.header.stamp.sec, -3);
  EXPECT_EQ(d.header.stamp.nanosec, 999999999u);
  EXPECT_EQ(d.header.frame_id, "world_ned");
  EXPECT_EQ(d.child_frame_id, "towfish");
  EXPECT_EQ(d.position.x, 199.57930000000002);
  EXPECT_EQ(d.position.y, -1.0 / 3.0);
  EXPECT_EQ(d.position.z, 1e-310);
  EXPECT_EQ(d.orientation.x, 0.1);
  EXPECT_EQ(d.orientation.y, -0.2);
  EXPECT_EQ(d.orientation.z, 0.3);
  EXPECT_EQ(d.orientation.w, std::sqrt(1.0 - 0.14));
  for (int i = 0; i < 36; ++i) EXPECT_EQ(d.pose_covariance[i], i * 0.125 - 2.0) << i;
  EXPECT_EQ(d.linear.x, 6.0);
  EXPECT_TRUE(std::signbit(d.linear.y));
  EXPECT_EQ(d.linear.z, 1.7976931348623157e308);
  EXPECT_EQ(d.angular.x, -1e-3);
  EXPECT_EQ(d.angular.y, 2e-3);
  EXPECT_EQ(d.angular.z, std::numeric_limits<double>::infinity());
  for (int i = 0; i < 36; ++i) EXPECT_EQ(d.twist_covariance[i], -i * 1e-9) << i;
  ExpectTruncationsFail(b, DecodeOdometry, "nav_msgs/msg/Odometry");
}

TEST_F(CdrMessagesTest, WrenchStampedAndClockFromCycloneBytes) {
  dds::WrenchStampedMsg w{};
  std::string frame = "tow_vehicle";  // 12 bytes with the NUL: the doubles need 4 of padding
  w.header.stamp.sec = 7;
  w.header.stamp.nanosec = 10000000u;
  w.header.frame_id = frame.data();
  w.wrench.force = {-1234.5, 0.25, 9.81e3};
  w.wrench.torque = {1.0 / 7.0, -2.0 / 7.0, 3.0 / 7.0};
  const auto bw = Serialize(&geometry_msgs_msg_dds__WrenchStamped__desc, &w);
  const WrenchStamped dw = DecodeWrenchStamped(bw.data(), bw.size());
  EXPECT_EQ(dw.header.stamp.seconds(), 7.01);
  EXPECT_EQ(dw.header.frame_id, "tow_vehicle");
  EXPECT_EQ(dw.force.x, -1234.5);
  EXPECT_EQ(dw.force.y, 0.25);
  EXPECT_EQ(dw.force.z, 9.81e3);
  EXPECT_EQ(dw.torque.x, 1.0 / 7.0);
  EXPECT_EQ(dw.torque.y, -2.0 / 7.0);
  EXPECT_EQ(dw.torque.z, 3.0 / 7.0);
  ExpectTruncationsFail(bw, DecodeWrenchStamped, "geometry_msgs/msg/WrenchStamped");

  dds::ClockMsg c{};
  c.clock.sec = 2147483647;
  c.clock.nanosec = 123456789u;
  const auto bc = Serialize(&rosgraph_msgs_msg_dds__Clock__desc, &c);
  const Clock dc = DecodeClock(bc.data(), bc.size());
  EXPECT_EQ(dc.clock.sec, 2147483647);
  EXPECT_EQ(dc.clock.nanosec, 123456789u);
  ExpectTruncationsFail(bc, DecodeClock, "rosgraph_msgs/msg/Clock");
}

TEST_F(CdrMessagesTest, BodyEnvironmentFromCycloneBytes) {
  std::string frame = "world_ned";  // 10 bytes with the NUL: step needs 2 of padding
  dds::BodyEnvironmentMsg m{};
  m.header.stamp.sec = 12;
  m.header.stamp.nanosec = 500000000u;
  m.header.frame_id = frame.data();
  m.step = 250;
  m.wave_elevation = -0.3125;
  m.current = {0.4, -1.0 / 3.0, 2.5e-3};
  m.altitude = std::numeric_limits<double>::quiet_NaN();  // no seabed
  m.depth = 19.6875;
  const auto b = Serialize(&towsim_msgs_msg_dds__BodyEnvironment__desc, &m);
  const BodyEnvironment d = DecodeBodyEnvironment(b.data(), b.size());
  EXPECT_EQ(d.header.stamp.seconds(), 12.5);
  EXPECT_EQ(d.header.frame_id, "world_ned");
  EXPECT_EQ(d.step, 250u);
  EXPECT_EQ(d.wave_elevation, -0.3125);
  EXPECT_EQ(d.current.x, 0.4);
  EXPECT_EQ(d.current.y, -1.0 / 3.0);
  EXPECT_EQ(d.current.z, 2.5e-3);
  EXPECT_TRUE(std::isnan(d.altitude));
  EXPECT_EQ(d.depth, 19.6875);
  ExpectTruncationsFail(b, DecodeBodyEnvironment, "towsim_msgs/msg/BodyEnvironment");
}

TEST_F(CdrMessagesTest, ActuatorStateFromCycloneBytes) {
  std::string frame = "tow_vehicle_frd";
  dds::ActuatorStateMsg m{};
  m.header.stamp.sec = 3;
  m.header.stamp.nanosec = 250000000u;
  m.header.frame_id = frame.data();
  m.step = 65;
  m.thrust_command = 4165.0;
  m.rudder_command = 0.3;
  m.elevator_command = -0.05;
  m.thrust = 4164.75;
  m.rudder = 1.0 / 7.0;
  m.elevator = -2.5e-3;
  m.failsafe = true;
  m.source = towsim_msgs_msg_dds__ActuatorState_Constants_SOURCE_FAILSAFE;
  const auto b = Serialize(&towsim_msgs_msg_dds__ActuatorState__desc, &m);
  const ActuatorState d = DecodeActuatorState(b.data(), b.size());
  EXPECT_EQ(d.header.stamp.seconds(), 3.25);
  EXPECT_EQ(d.header.frame_id, "tow_vehicle_frd");
  EXPECT_EQ(d.step, 65u);
  EXPECT_EQ(d.thrust_command, 4165.0);
  EXPECT_EQ(d.rudder_command, 0.3);
  EXPECT_EQ(d.elevator_command, -0.05);
  EXPECT_EQ(d.thrust, 4164.75);
  EXPECT_EQ(d.rudder, 1.0 / 7.0);
  EXPECT_EQ(d.elevator, -2.5e-3);
  EXPECT_TRUE(d.failsafe);
  EXPECT_EQ(d.source, 3);
  ExpectTruncationsFail(b, DecodeActuatorState, "towsim_msgs/msg/ActuatorState");
}

TEST_F(CdrMessagesTest, CableStateFromCycloneBytes) {
  constexpr int kNodes = 21;
  std::vector<geometry_msgs_msg_dds__Point_> p(kNodes);
  std::vector<geometry_msgs_msg_dds__Vector3_> v(kNodes);
  std::vector<double> t(kNodes);
  for (int i = 0; i < kNodes; ++i) {
    p[i] = {10.0 * i, -0.5 * i, 3.5 + i / 3.0};
    v[i] = {1.5, i * 1e-4, -i / 7.0};
    t[i] = 4500.0 - i * 17.125;
  }
  std::string frame = "world_ned";
  dds::CableStateMsg m{};
  m.header.stamp.sec = 100;
  m.header.frame_id = frame.data();
  m.step = 10000000000ull;  // beyond 32 bits
  m.positions = {kNodes, kNodes, p.data(), false};
  m.velocities = {kNodes, kNodes, v.data(), false};
  m.tensions = {kNodes, kNodes, t.data(), false};
  m.paid_out_length = 212.25;
  m.winch_speed = -0.75;
  m.drum_tension = 5123.5;
  m.node_count = kNodes;
  const auto b = Serialize(&towsim_msgs_msg_dds__CableState__desc, &m);
  const CableState d = DecodeCableState(b.data(), b.size());
  EXPECT_EQ(d.header.stamp.sec, 100);
  EXPECT_EQ(d.step, 10000000000ull);
  ASSERT_EQ(d.positions.size(), static_cast<std::size_t>(kNodes));
  ASSERT_EQ(d.velocities.size(), static_cast<std::size_t>(kNodes));
  ASSERT_EQ(d.tensions.size(), static_cast<std::size_t>(kNodes));
  for (int i = 0; i < kNodes; ++i) {
    EXPECT_EQ(d.positions[i].x, p[i].x);
    EXPECT_EQ(d.positions[i].y, p[i].y);
    EXPECT_EQ(d.positions[i].z, p[i].z);
    EXPECT_EQ(d.velocities[i].x, v[i].x);
    EXPECT_EQ(d.velocities[i].y, v[i].y);
    EXPECT_EQ(d.velocities[i].z, v[i].z);
    EXPECT_EQ(d.tensions[i], t[i]);
  }
  EXPECT_EQ(d.paid_out_length, 212.25);
  EXPECT_EQ(d.winch_speed, -0.75);
  EXPECT_EQ(d.drum_tension, 5123.5);
  EXPECT_EQ(d.node_count, static_cast<std::uint32_t>(kNodes));
  ExpectTruncationsFail(b, DecodeCableState, "towsim_msgs/msg/CableState");

  // a corrupt element count is refused before anything is allocated: the positions count
  // follows header (4 + 4 + 4 + 10 bytes, padded to 24) and step (8): body offset 32
  std::vector<std::uint8_t> bad = b;
  const std::size_t at = 4 + 32;
  ASSERT_EQ(bad[at], kNodes);
  bad[at] = bad[at + 1] = bad[at + 2] = bad[at + 3] = 0xFF;
  try {
    DecodeCableState(bad.data(), bad.size());
    ADD_FAILURE() << "a count of 2^32 - 1 was accepted";
  } catch (const CdrError& e) {
    EXPECT_NE(std::string(e.what()).find("CableState.positions: sequence of 4294967295"),
              std::string::npos)
        << e.what();
  }
  // extra bytes beyond the padding: not this type
  bad = b;
  bad.insert(bad.end(), 8, 0);
  EXPECT_THROW(DecodeCableState(bad.data(), bad.size()), CdrError);
}

TEST_F(CdrMessagesTest, SimStatusFromCycloneBytes) {
  std::string frame = "", run = "steady_tow-20240101-1", mode = "lockstep", msg = "ok";
  std::string b0 = "towfish", b1 = "a";
  char* bodies[2] = {b0.data(), b1.data()};
  dds::SimStatusMsg m{};
  m.header.stamp.sec = 1;
  m.header.stamp.nanosec = 500000000u;
  m.header.frame_id = frame.data();
  m.run_id = run.data();
  m.mode = mode.data();
  m.state = 3;
  m.health = 1;
  m.message = msg.data();
  m.step = 150;
  m.sim_time = 1.5;
  m.rate = 2.0;
  m.real_time_factor = 123.456;
  m.step_wall_time = 1.25e-4;
  m.lateness = -2e-6;
  m.lateness_max = 3e-3;
  m.overruns = 17;
  m.newton_iterations = -4;  // signed on the wire
  m.residual = 3.14e-9;
  m.coupling_iterations = 6;
  m.substeps = 1;
  m.failsafe_count = 2;
  m.failsafe_bodies = {2, 2, bodies, false};
  m.commands_received = 1000;
  m.commands_rejected = 3;
  m.commands_clamped = 5;
  m.lockstep_timeouts = 7;
  const auto b = Serialize(&towsim_msgs_msg_dds__SimStatus__desc, &m);
  const SimStatus d = DecodeSimStatus(b.data(), b.size());
  EXPECT_EQ(d.header.stamp.seconds(), 1.5);
  EXPECT_EQ(d.header.frame_id, "");
  EXPECT_EQ(d.run_id, run);
  EXPECT_EQ(d.mode, "lockstep");
  EXPECT_EQ(d.state, 3);
  EXPECT_EQ(d.health, 1);
  EXPECT_EQ(d.message, "ok");
  EXPECT_EQ(d.step, 150u);
  EXPECT_EQ(d.sim_time, 1.5);
  EXPECT_EQ(d.rate, 2.0);
  EXPECT_EQ(d.real_time_factor, 123.456);
  EXPECT_EQ(d.step_wall_time, 1.25e-4);
  EXPECT_EQ(d.lateness, -2e-6);
  EXPECT_EQ(d.lateness_max, 3e-3);
  EXPECT_EQ(d.overruns, 17u);
  EXPECT_EQ(d.newton_iterations, -4);
  EXPECT_EQ(d.residual, 3.14e-9);
  EXPECT_EQ(d.coupling_iterations, 6);
  EXPECT_EQ(d.substeps, 1);
  EXPECT_EQ(d.failsafe_count, 2u);
  EXPECT_EQ(d.failsafe_bodies, (std::vector<std::string>{"towfish", "a"}));
  EXPECT_EQ(d.commands_received, 1000u);
  EXPECT_EQ(d.commands_rejected, 3u);
  EXPECT_EQ(d.commands_clamped, 5u);
  EXPECT_EQ(d.lockstep_timeouts, 7u);
  ExpectTruncationsFail(b, DecodeSimStatus, "towsim_msgs/msg/SimStatus");
}

TEST_F(CdrMessagesTest, CommandControlAndSceneInfoFromCycloneBytes) {
  std::string frame = "x";
  dds::ActuatorCommandMsg a{};
  a.header.stamp.sec = 3;
  a.header.frame_id = frame.data();
  a.step = 42;
  a.thrust = 4500.0;
  a.rudder = -0.1745;
  a.elevator = 0.05;
  const auto ba = Serialize(&towsim_msgs_msg_dds__ActuatorCommand__desc, &a);
  const ActuatorCommand da = DecodeActuatorCommand(ba.data(), ba.size());
  EXPECT_EQ(da.header.frame_id, "x");
  EXPECT_EQ(da.step, 42u);
  EXPECT_EQ(da.thrust, 4500.0);
  EXPECT_EQ(da.rudder, -0.1745);
  EXPECT_EQ(da.elevator, 0.05);
  ExpectTruncationsFail(ba, DecodeActuatorCommand, "towsim_msgs/msg/ActuatorCommand");

  dds::WinchCommandMsg w{};
  w.header.frame_id = frame.data();
  w.step = 77;
  w.mode = towsim_msgs_msg_dds__WinchCommand_Constants_LENGTH;
  w.value = 250.5;
  const auto bw = Serialize(&towsim_msgs_msg_dds__WinchCommand__desc, &w);
  const WinchCommand dw = DecodeWinchCommand(bw.data(), bw.size());
  EXPECT_EQ(dw.step, 77u);
  EXPECT_EQ(dw.mode, 1);
  EXPECT_EQ(dw.value, 250.5);
  ExpectTruncationsFail(bw, DecodeWinchCommand, "towsim_msgs/msg/WinchCommand");

  dds::SimControlMsg c{};
  c.header.frame_id = frame.data();
  c.command = 5;
  c.steps = 4000000000u;
  c.rate = 0.5;
  const auto bc = Serialize(&towsim_msgs_msg_dds__SimControl__desc, &c);
  const SimControl dc = DecodeSimControl(bc.data(), bc.size());
  EXPECT_EQ(dc.command, 5);
  EXPECT_EQ(dc.steps, 4000000000u);
  EXPECT_EQ(dc.rate, 0.5);
  ExpectTruncationsFail(bc, DecodeSimControl, "towsim_msgs/msg/SimControl");

  std::string run = "r", scene = "case2_uturn", mode = "fast", b0 = "tow_vehicle", b1 = "towfish";
  char* bodies[2] = {b0.data(), b1.data()};
  dds::SceneInfoMsg s{};
  s.header.frame_id = frame.data();
  s.run_id = run.data();
  s.scene = scene.data();
  s.mode = mode.data();
  s.step_size = 0.01;
  s.duration = -1.0;
  s.command_timeout = 0.5;
  s.bodies = {2, 2, bodies, false};
  s.commanded_bodies = {1, 1, bodies, false};
  s.cable_nodes = 21;
  s.has_winch = true;
  s.winch_min_length = 100.0;
  s.winch_max_length = 300.0;
  s.winch_max_speed = 1.5;
  s.winch_max_acceleration = 0.25;
  const auto bs = Serialize(&towsim_msgs_msg_dds__SceneInfo__desc, &s);
  const SceneInfo ds = DecodeSceneInfo(bs.data(), bs.size());
  EXPECT_EQ(ds.scene, "case2_uturn");
  EXPECT_EQ(ds.mode, "fast");
  EXPECT_EQ(ds.step_size, 0.01);
  EXPECT_EQ(ds.duration, -1.0);
  EXPECT_EQ(ds.command_timeout, 0.5);
  EXPECT_EQ(ds.bodies, (std::vector<std::string>{"tow_vehicle", "towfish"}));
  EXPECT_EQ(ds.commanded_bodies, (std::vector<std::string>{"tow_vehicle"}));
  EXPECT_EQ(ds.cable_nodes, 21u);
  EXPECT_TRUE(ds.has_winch);
  EXPECT_EQ(ds.winch_min_length, 100.0);
  EXPECT_EQ(ds.winch_max_length, 300.0);
  EXPECT_EQ(ds.winch_max_speed, 1.5);
  EXPECT_EQ(ds.winch_max_acceleration, 0.25);
  EXPECT_TRUE(ds.cables.empty());

  // the network fields
  std::string c0 = "main", c1 = "tether", w0 = "winch";
  char* cables[2] = {c0.data(), c1.data()};
  char* winches[1] = {w0.data()};
  uint32_t counts[2] = {21, 11};
  s.cables = {2, 2, cables, false};
  s.cable_node_counts = {2, 2, counts, false};
  s.winches = {1, 1, winches, false};
  s.winch_cables = {1, 1, cables, false};
  const auto bn = Serialize(&towsim_msgs_msg_dds__SceneInfo__desc, &s);
  const SceneInfo dn = DecodeSceneInfo(bn.data(), bn.size());
  EXPECT_EQ(dn.cables, (std::vector<std::string>{"main", "tether"}));
  EXPECT_EQ(dn.cable_node_counts, (std::vector<std::uint32_t>{21, 11}));
  EXPECT_EQ(dn.winches, std::vector<std::string>{"winch"});
  EXPECT_EQ(dn.winch_cables, std::vector<std::string>{"main"});
  EXPECT_EQ(dn.winch_max_acceleration, 0.25);

  // a message of an earlier towsim ends after winch_max_acceleration: the four empty
  // sequences of `bs` (a u32 count each) cut off, it decodes with no cables listed; every
  // other cut fails
  constexpr std::size_t kNetworkFieldsEmpty = 4 * 4;  // [bytes]
  const std::size_t legacy = bs.size() - kNetworkFieldsEmpty;
  const SceneInfo dl = DecodeSceneInfo(bs.data(), legacy);
  EXPECT_EQ(dl.winch_max_acceleration, 0.25);
  EXPECT_TRUE(dl.cables.empty());
  const std::size_t padding = bn[3] & 0x3;  // the encapsulation options: end padding
  for (std::size_t n = 0; n < bn.size() - padding; ++n) {
    if (n >= legacy && n <= legacy + 3) continue;  // the earlier layout and its padding
    EXPECT_THROW(DecodeSceneInfo(bn.data(), n), CdrError) << "cut to " << n;
  }
}

}  // namespace
}  // namespace towsim::io::cdr
