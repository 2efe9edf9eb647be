// io/cdr_reader: XCDR1 by hand — both byte orders, alignment counted from the end of the
// encapsulation header, strings with their NUL, and clear errors for bad input.
#include "io/cdr_reader.h"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/cdr_messages.h"

namespace towsim::io::cdr {
namespace {

// the same ActuatorCommand in both byte orders: header {stamp {sec, nanosec}, frame_id "ab"},
// step u64, thrust f64, rudder f64, elevator f64
std::vector<std::uint8_t> Command(bool little) {
  std::vector<std::uint8_t> b = {0x00, static_cast<std::uint8_t>(little ? 0x01 : 0x00), 0, 0};
  auto put = [&](std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) {
      b.push_back(static_cast<std::uint8_t>(v >> 8 * (little ? i : n - 1 - i)));
    }
  };
  auto align = [&](std::size_t n) {
    while ((b.size() - 4) % n != 0) b.push_back(0xEE);  // padding, any value
  };
  put(static_cast<std::uint32_t>(-7), 4);  // sec
  put(250000000u, 4);                      // nanosec
  put(3, 4);                               // frame_id length with the NUL
  b.insert(b.end(), {'a', 'b', 0});        // body offset 12 + 3 = 15
  align(8);                                // -> 16
  put(0x0102030405060708ull, 8);           // step
  put(0x40B1940000000000ull, 8);           // thrust 4500.0
  put(0xBFB999999999999Aull, 8);           // rudder -0.1
  put(0x0000000000000000ull, 8);           // elevator 0.0
  return b;
}

TEST(CdrReader, BothByteOrdersAndAlignment) {
  for (const bool little : {true, false}) {
    SCOPED_TRACE(little ? "little endian" : "big endian");
    const auto b = Command(little);
    EXPECT_EQ(b.size(), 4u + 48u);
    const ActuatorCommand c = DecodeActuatorCommand(b.data(), b.size());
    EXPECT_EQ(c.header.stamp.sec, -7);
    EXPECT_EQ(c.header.stamp.nanosec, 250000000u);
    EXPECT_EQ(c.header.stamp.seconds(), -6.75);
    EXPECT_EQ(c.header.frame_id, "ab");
    EXPECT_EQ(c.step, 0x0102030405060708ull);
    EXPECT_EQ(c.thrust, 4500.0);
    EXPECT_EQ(c.rudder, -0.1);
    EXPECT_EQ(c.elevator, 0.0);
  }
}

std::string ErrorOf(const std::vector<std::uint8_t>& b) {
  try {
    DecodeActuatorCommand(b.data(), b.size());
  } catch (const CdrError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CdrReader, BadInputGivesClearErrors) {
  EXPECT_EQ(ErrorOf({}),
            "towsim_msgs/msg/ActuatorCommand: 0 bytes, too short for the 4-byte CDR "
            "encapsulation header (at byte offset 0)");
  auto b = Command(true);
  b[1] = 0x11;  // PLAIN_CDR2 little endian
  EXPECT_EQ(ErrorOf(b),
            "towsim_msgs/msg/ActuatorCommand: encapsulation 0x0011 is not XCDR1 (0x0000 big "
            "endian or 0x0001 little endian) (at byte offset 0)");
  b = Command(true);
  b[18] = 'c';  // the frame_id's NUL
  EXPECT_EQ(ErrorOf(b),
            "towsim_msgs/msg/ActuatorCommand.header.frame_id: string of 3 bytes without NUL (at "
            "byte offset 16)");
  b = Command(true);
  b[12] = 200;  // frame_id length beyond the buffer
  EXPECT_EQ(ErrorOf(b),
            "towsim_msgs/msg/ActuatorCommand.header.frame_id: needs 200 bytes, the payload has 36 "
            "left of 52 (at byte offset 16)");
  b = Command(true);
  b.resize(b.size() - 1);
  EXPECT_EQ(ErrorOf(b),
            "towsim_msgs/msg/ActuatorCommand.elevator: needs 8 bytes, the payload has 7 left of "
            "51 (at byte offset 44)");
}

}  // namespace
}  // namespace towsim::io::cdr
