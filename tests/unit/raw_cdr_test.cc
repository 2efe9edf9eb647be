// Raw CDR plumbing (sim_node/dds/raw_cdr): a sample serialized by Cyclone and written raw is
// received by an ordinary typed reader with identical values and the given source timestamp;
// a raw take returns the same bytes; the bytes are XCDR1 little endian as the CDR rules lay
// them out (checked by hand for the fields in front). One participant, DDS domain 80.

#include "dds/raw_cdr.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/qos.h"

namespace towsim::dds {
namespace {

constexpr uint32_t kDomain = 80;
constexpr double kDeliveryTimeout = 5.0;  // [s] local delivery is synchronous; a generous bound

std::string Config() { return "file://" TOWSIM_SOURCE_DIR "/config/cyclonedds.xml"; }

// an odometry sample with distinct values in every field the test looks at
struct OdomSample {
  OdometryMsg msg{};
  std::string frame = "world_ned", child = "towfish";
  OdomSample() {
    msg.header.stamp.sec = 12;
    msg.header.stamp.nanosec = 345000000u;
    msg.header.frame_id = frame.data();
    msg.child_frame_id = child.data();
    msg.pose.pose.position.x = 199.5793;
    msg.pose.pose.position.y = -0.25;
    msg.pose.pose.position.z = 21.0638;
    msg.pose.pose.orientation.w = 1.0;
    for (int i = 0; i < 36; ++i) msg.pose.covariance[i] = 0.5 * i;
    msg.twist.twist.linear.x = 6.0;
    msg.twist.twist.angular.z = -1e-3;
  }
};

uint32_t U32At(const std::vector<uint8_t>& b, size_t at) {
  return static_cast<uint32_t>(b[at]) | static_cast<uint32_t>(b[at + 1]) << 8 |
         static_cast<uint32_t>(b[at + 2]) << 16 | static_cast<uint32_t>(b[at + 3]) << 24;
}

class RawCdrTest : public ::testing::Test {
 protected:
  RawCdrTest() : participant_(kDomain, Config()) {}
  Participant participant_;
};

TEST_F(RawCdrTest, BytesAreXcdr1LittleEndianLaidOutByTheCdrRules) {
  RawType type(participant_, &nav_msgs_msg_dds__Odometry__desc);
  EXPECT_EQ(type.type_name(), "nav_msgs::msg::dds_::Odometry_");
  OdomSample s;
  const std::vector<uint8_t> b = CdrSample::FromSample(type, &s.msg).bytes();
  ASSERT_GT(b.size(), 40u);
  // encapsulation header CDR_LE = {0x00, 0x01}, options {0, 0}
  EXPECT_EQ(b[0], 0x00);
  EXPECT_EQ(b[1], 0x01);
  EXPECT_EQ(b[2] & 0xFC, 0x00);  // the low two bits may count the trailing padding
  EXPECT_EQ(b[3] & 0xFC, 0x00);
  // payload offsets from byte 4: stamp.sec int32 @0, stamp.nanosec uint32 @4, frame_id:
  // uint32 length incl. the NUL @8, then the characters
  EXPECT_EQ(U32At(b, 4), 12u);
  EXPECT_EQ(U32At(b, 8), 345000000u);
  EXPECT_EQ(U32At(b, 12), s.frame.size() + 1);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&b[16]), s.frame.size()), s.frame);
  EXPECT_EQ(b[16 + s.frame.size()], 0);
  // child_frame_id follows, aligned to 4
  const size_t child_at = 4 + ((12 + s.frame.size() + 1 + 3) / 4) * 4;
  EXPECT_EQ(U32At(b, child_at), s.child.size() + 1);
  // the position: the first double after the child frame id, aligned to 8 from byte 4
  const size_t pos_at = 4 + ((child_at - 4 + 4 + s.child.size() + 1 + 7) / 8) * 8;
  double x;
  std::memcpy(&x, &b[pos_at], 8);
  EXPECT_EQ(x, 199.5793);
}

TEST_F(RawCdrTest, RawWriteIsReceivedByATypedReaderAndRawTakeGivesTheSameBytes) {
  RawType type(participant_, &nav_msgs_msg_dds__Odometry__desc);
  Topic topic(participant_, &nav_msgs_msg_dds__Odometry__desc, "rt/raw_cdr_test/odom");
  Qos qos = StateQos(16);
  Reader<OdometryMsg> typed(participant_, topic, qos);
  const dds_entity_t raw = dds_create_reader(participant_.get(), topic.get(), qos.get(), nullptr);
  ASSERT_GT(raw, 0);
  Entity raw_reader(raw);
  Writer<OdometryMsg> writer(participant_, topic, StateQos(1));

  OdomSample s;
  const CdrSample sample = CdrSample::FromSample(type, &s.msg);
  const std::vector<uint8_t> sent = sample.bytes();
  const dds_time_t stamp = 1'700'000'000'123'456'789LL;
  ASSERT_EQ(sample.Write(writer.get(), stamp), DDS_RETCODE_OK);

  int typed_count = 0, raw_count = 0;
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(kDeliveryTimeout);
  while ((typed_count == 0 || raw_count == 0) && std::chrono::steady_clock::now() < until) {
    typed_count += typed.TakeEach([&](const OdometryMsg& m, const dds_sample_info_t& info) {
      EXPECT_EQ(info.source_timestamp, stamp);
      EXPECT_EQ(m.header.stamp.sec, 12);
      EXPECT_EQ(m.header.stamp.nanosec, 345000000u);
      EXPECT_STREQ(m.header.frame_id, "world_ned");
      EXPECT_STREQ(m.child_frame_id, "towfish");
      EXPECT_EQ(m.pose.pose.position.x, 199.5793);  // bit-identical: no conversion
      EXPECT_EQ(m.pose.pose.position.y, -0.25);
      EXPECT_EQ(m.pose.pose.position.z, 21.0638);
      EXPECT_EQ(m.pose.pose.orientation.w, 1.0);
      for (int i = 0; i < 36; ++i) EXPECT_EQ(m.pose.covariance[i], 0.5 * i);
      EXPECT_EQ(m.twist.twist.linear.x, 6.0);
      EXPECT_EQ(m.twist.twist.angular.z, -1e-3);
    });
    raw_count += TakeRaw(raw, [&](const uint8_t* p, size_t n, const dds_sample_info_t& info) {
      EXPECT_EQ(info.source_timestamp, stamp);
      EXPECT_EQ(std::vector<uint8_t>(p, p + n), sent);
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(typed_count, 1);
  EXPECT_EQ(raw_count, 1);
}

TEST_F(RawCdrTest, BytesRoundTripThroughFromBytesAndDeserialize) {
  RawType type(participant_, &nav_msgs_msg_dds__Odometry__desc);
  OdomSample s;
  const std::vector<uint8_t> bytes = CdrSample::FromSample(type, &s.msg).bytes();
  const CdrSample again = CdrSample::FromBytes(type, bytes.data(), bytes.size());
  EXPECT_EQ(again.bytes(), bytes);

  OdometryMsg out{};
  ASSERT_TRUE(type.Deserialize(bytes.data(), bytes.size(), &out));
  EXPECT_STREQ(out.child_frame_id, "towfish");
  EXPECT_EQ(out.pose.pose.position.z, 21.0638);
  dds_sample_free(&out, &nav_msgs_msg_dds__Odometry__desc, DDS_FREE_CONTENTS);
}

TEST_F(RawCdrTest, BadBytesAreRejected) {
  RawType type(participant_, &nav_msgs_msg_dds__Odometry__desc);
  OdomSample s;
  const std::vector<uint8_t> bytes = CdrSample::FromSample(type, &s.msg).bytes();
  const uint8_t two[2] = {0, 1};
  EXPECT_THROW(CdrSample::FromBytes(type, two, 2), std::invalid_argument);
  // cut inside the pose: the payload ends before the fields it must hold
  EXPECT_THROW(CdrSample::FromBytes(type, bytes.data(), 60), std::invalid_argument);
  // a string length running past the end
  std::vector<uint8_t> bad = bytes;
  bad[12] = 0xFF;
  bad[13] = 0xFF;
  EXPECT_THROW(CdrSample::FromBytes(type, bad.data(), bad.size()), std::invalid_argument);
}

TEST_F(RawCdrTest, EveryTypeOfTheContractHasASertype) {
  const dds_topic_descriptor_t* all[] = {
      &rosgraph_msgs_msg_dds__Clock__desc,         &nav_msgs_msg_dds__Odometry__desc,
      &geometry_msgs_msg_dds__WrenchStamped__desc, &towsim_msgs_msg_dds__CableState__desc,
      &towsim_msgs_msg_dds__SimStatus__desc,       &towsim_msgs_msg_dds__SceneInfo__desc,
      &towsim_msgs_msg_dds__ActuatorCommand__desc, &towsim_msgs_msg_dds__SimControl__desc};
  for (const dds_topic_descriptor_t* d : all) {
    RawType type(participant_, d);
    EXPECT_NE(type.get(), nullptr) << d->m_typename;
    // a zeroed sample serializes and reads back
    std::vector<uint8_t> zero(d->m_size, 0);
    const std::vector<uint8_t> bytes = CdrSample::FromSample(type, zero.data()).bytes();
    EXPECT_GE(bytes.size(), 4u) << d->m_typename;
    std::vector<uint8_t> back(d->m_size, 0);
    EXPECT_TRUE(type.Deserialize(bytes.data(), bytes.size(), back.data())) << d->m_typename;
    dds_sample_free(back.data(), d, DDS_FREE_CONTENTS);
  }
}

}  // namespace
}  // namespace towsim::dds
