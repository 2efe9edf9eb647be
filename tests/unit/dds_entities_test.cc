// sim_node/dds/entities and qos with a real participant on the loopback configuration
// (config/cyclonedds.xml; DDS domains 57 and 58, see tests/integration/README.md): matching,
// a round trip, transient-local scene info, the XCDR1 bytes of the ROS 2 types, setup errors.

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dds/ddsi/ddsi_serdata.h"
#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/qos.h"
#include "dds/translators.h"

namespace towsim::dds {
namespace {

constexpr uint32_t kDomain = 58;
constexpr uint32_t kBadConfigDomain = 57;
constexpr double kMatchTimeout = 10.0;  // [s], discovery over loopback takes milliseconds

class DdsEntitiesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // loopback only, never Cyclone's default (before any participant exists)
    setenv("CYCLONEDDS_URI", "file://" TOWSIM_SOURCE_DIR "/config/cyclonedds.xml", 1);
  }
};

template <class Pred>
bool WaitFor(Pred pred) {
  const auto start = std::chrono::steady_clock::now();
  while (!pred()) {
    if (std::chrono::steady_clock::now() - start > std::chrono::duration<double>(kMatchTimeout)) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

// matched() is the count Cyclone's publication-matched listener keeps (one atomic load per
// step): it follows a reader that comes and goes, as dds_get_publication_matched_status does
TEST_F(DdsEntitiesTest, MatchedFollowsReadersThatComeAndGo) {
  Participant p(kDomain, "");
  Topic t(p, &nav_msgs_msg_dds__Odometry__desc, "rt/test_match/towfish/odom");
  Writer<OdometryMsg> w(p, t, StateQos());
  EXPECT_FALSE(w.matched());
  for (int round = 0; round < 2; ++round) {
    {
      Reader<OdometryMsg> r(p, t, StateQos());
      ASSERT_TRUE(WaitFor([&] { return w.matched(); }));
      EXPECT_EQ(w.matched_count(), 1);
    }
    ASSERT_TRUE(WaitFor([&] { return !w.matched(); }));
    EXPECT_EQ(w.matched_count(), 0);
  }
  // a moved writer keeps its count (the listener writes to storage that does not move)
  Reader<OdometryMsg> r(p, t, StateQos());
  Writer<OdometryMsg> moved = std::move(w);
  ASSERT_TRUE(WaitFor([&] { return moved.matched(); }));
}

TEST_F(DdsEntitiesTest, WriterMatchesOnlyWithAReader) {
  Participant p(kDomain, "");
  Topic t(p, &towsim_msgs_msg_dds__ActuatorCommand__desc, "rt/test_match/tow_vehicle/command");
  Writer<ActuatorCommandMsg> w(p, t, CommandQos());
  EXPECT_FALSE(w.matched());  // nobody subscribes: the node builds nothing
  Reader<ActuatorCommandMsg> r(p, t, CommandQos());
  ASSERT_TRUE(WaitFor([&] { return w.matched(); }));
  EXPECT_EQ(w.matched_count(), 1);
  EXPECT_EQ(r.matched_count(), 1);

  ActuatorCommandMsg m{};
  m.step = 12;
  m.thrust = 4500.0;
  m.rudder = -0.1;
  m.header.frame_id = const_cast<char*>("tow_vehicle");
  w.Write(m);
  ActuatorCommandMsg got{};
  ASSERT_TRUE(WaitFor([&] {
    return r.TakeEach([&](const ActuatorCommandMsg& s, const dds_sample_info_t&) {
      got.step = s.step;
      got.thrust = s.thrust;
      got.rudder = s.rudder;
    }) > 0;
  }));
  EXPECT_EQ(got.step, 12u);
  EXPECT_EQ(got.thrust, 4500.0);
  EXPECT_EQ(got.rudder, -0.1);
}

TEST_F(DdsEntitiesTest, LateReaderGetsTheSceneInfo) {
  Participant p(kDomain, "");
  Topic t(p, &towsim_msgs_msg_dds__SceneInfo__desc, "rt/test_late/scene_info");
  Writer<SceneInfoMsg> w(p, t, SceneInfoQos());
  SceneInfoSample s;
  s.run_id = "run-1";
  s.scene = "case1_forward";
  s.bodies = {"tow_vehicle", "towfish"};
  SceneInfoMessage m;
  ToSceneInfo(s, &m);
  w.Write(m.msg);  // before anyone listens

  Participant late(kDomain, "");
  Topic t2(late, &towsim_msgs_msg_dds__SceneInfo__desc, "rt/test_late/scene_info");
  Reader<SceneInfoMsg> r(late, t2, SceneInfoQos());
  std::string scene;
  ASSERT_TRUE(WaitFor([&] {
    return r.TakeEach([&](const SceneInfoMsg& x, const dds_sample_info_t&) { scene = x.scene; }) >
           0;
  }));
  EXPECT_EQ(scene, "case1_forward");
}

// little-endian CDR (XCDR1): every primitive aligned to its size (at most 8) from the start of
// the payload, strings as uint32 length (with the terminating NUL) + bytes
class CdrLe {
 public:
  void Align(size_t n) {
    while (bytes_.size() % n != 0) bytes_.push_back(0);
  }
  void U32(uint32_t x) {
    Align(4);
    Put(&x, 4);
  }
  void I32(int32_t x) {
    Align(4);
    Put(&x, 4);
  }
  void F64(double x) {
    Align(8);
    Put(&x, 8);
  }
  void Str(const char* s) {
    U32(static_cast<uint32_t>(std::strlen(s) + 1));
    Put(s, std::strlen(s) + 1);
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  void Put(const void* p, size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    bytes_.insert(bytes_.end(), c, c + n);
  }
  std::vector<unsigned char> bytes_;
};

// the serialized form of one sample as it goes on the wire (encapsulation header + payload)
template <class T>
std::vector<unsigned char> Serialized(const Participant& p, const dds_topic_descriptor_t* desc,
                                      const std::string& name, const T& sample) {
  Topic t(p, desc, name);
  Writer<T> w(p, t, StateQos());
  Reader<T> r(p, t, StateQos(8));
  EXPECT_TRUE(WaitFor([&] { return w.matched(); }));
  w.Write(sample);
  std::vector<unsigned char> out;
  EXPECT_TRUE(WaitFor([&] {
    struct ddsi_serdata* d = nullptr;
    dds_sample_info_t info;
    if (dds_takecdr(r.get(), &d, 1, &info, DDS_ANY_STATE) != 1) return false;
    out.resize(ddsi_serdata_size(d));
    ddsi_serdata_to_ser(d, 0, out.size(), out.data());
    ddsi_serdata_unref(d);
    return true;
  }));
  return out;
}

TEST_F(DdsEntitiesTest, OdometryIsPlainCdrInTheRos2Layout) {
  Participant p(kDomain, "");
  OdometryMessage m(kWorldFrame, "fish");
  m.msg.header.stamp = ToTimeMsg(12.5);
  double x = 1.0;
  for (double* d :
       {&m.msg.pose.pose.position.x, &m.msg.pose.pose.position.y, &m.msg.pose.pose.position.z,
        &m.msg.pose.pose.orientation.x, &m.msg.pose.pose.orientation.y,
        &m.msg.pose.pose.orientation.z, &m.msg.pose.pose.orientation.w}) {
    *d = x++;
  }
  for (double& c : m.msg.pose.covariance) c = x++;
  for (double* d :
       {&m.msg.twist.twist.linear.x, &m.msg.twist.twist.linear.y, &m.msg.twist.twist.linear.z,
        &m.msg.twist.twist.angular.x, &m.msg.twist.twist.angular.y, &m.msg.twist.twist.angular.z}) {
    *d = x++;
  }
  for (double& c : m.msg.twist.covariance) c = x++;

  // nav_msgs/Odometry: header (stamp sec, nanosec, frame_id), child_frame_id,
  // pose (position xyz, orientation xyzw, covariance[36]), twist (linear, angular, covariance)
  CdrLe e;
  e.I32(12);
  e.U32(500000000u);
  e.Str("world_ned");
  e.Str("fish");
  for (double v = 1.0; v < x; v += 1.0) e.F64(v);

  const std::vector<unsigned char> wire =
      Serialized(p, &nav_msgs_msg_dds__Odometry__desc, "rt/test_cdr/odom", m.msg);
  ASSERT_GE(wire.size(), 4u);
  // encapsulation CDR_LE (0x0001): XCDR1, as ROS 2 writes and expects
  EXPECT_EQ(wire[0], 0x00);
  EXPECT_EQ(wire[1], 0x01);
  const std::vector<unsigned char> payload(wire.begin() + 4, wire.end());
  EXPECT_EQ(payload, e.bytes());
}

TEST_F(DdsEntitiesTest, CableStateSequencesAreCdrSequences) {
  Participant p(kDomain, "");
  CableStateMessage m(kWorldFrame, 2);
  m.msg.header.stamp = ToTimeMsg(0.05);
  m.msg.step = 1;
  double x = 1.0;
  for (uint32_t i = 0; i < 2; ++i) {
    m.msg.positions._buffer[i] = {x, x + 1, x + 2};
    m.msg.velocities._buffer[i] = {x + 3, x + 4, x + 5};
    m.msg.tensions._buffer[i] = x + 6;
    x += 10;
  }
  CdrLe e;
  e.I32(0);
  e.U32(50000000u);
  e.Str("world_ned");
  e.Align(8);
  e.U32(1);  // uint64 step, little endian: low word first
  e.U32(0);
  e.U32(2);
  for (double v : {1.0, 2.0, 3.0, 11.0, 12.0, 13.0}) e.F64(v);
  e.U32(2);
  for (double v : {4.0, 5.0, 6.0, 14.0, 15.0, 16.0}) e.F64(v);
  e.U32(2);
  for (double v : {7.0, 17.0}) e.F64(v);
  // the winch's appended fields: paid_out_length, winch_speed, drum_tension, node_count
  m.msg.paid_out_length = 150.5;
  m.msg.winch_speed = -0.25;
  m.msg.drum_tension = 4321.0;
  for (double v : {150.5, -0.25, 4321.0}) e.F64(v);
  e.U32(2);
  const std::vector<unsigned char> wire =
      Serialized(p, &towsim_msgs_msg_dds__CableState__desc, "rt/test_cdr/cable", m.msg);
  ASSERT_GE(wire.size(), 4u);
  EXPECT_EQ(wire[1], 0x01);
  EXPECT_EQ(std::vector<unsigned char>(wire.begin() + 4, wire.end()), e.bytes());
}

TEST_F(DdsEntitiesTest, SetupErrorsThrowWithCyclonesText) {
  // DDSI maps domain d to UDP port 7400 + 250 d: 300 is beyond 65535
  try {
    Participant p(300, "");
    FAIL() << "domain 300 was accepted";
  } catch (const DdsError& e) {
    EXPECT_NE(std::string(e.what()).find("DDS domain 300"), std::string::npos) << e.what();
  }
  try {
    Participant p(kBadConfigDomain, "file:///nonexistent/towsim/cyclonedds.xml");
    FAIL() << "a missing config file was accepted";
  } catch (const DdsError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/towsim/cyclonedds.xml"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace towsim::dds
