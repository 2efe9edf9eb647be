// app/foxglove/foxglove_commands: the rules a client's message must meet before it is written on
// DDS (docs/foxglove.md): every Teleop Twist field finite, nothing after the sample but padding,
// and the throttle of the notes on stderr.

#include "app/foxglove/foxglove_commands.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

TEST(FoxgloveCommands, NonFiniteTwistFieldNamesTheFirstOne) {
  geometry_msgs_msg_dds__Twist_ t{};
  EXPECT_EQ(NonFiniteTwistField(t), "");
  t.linear.x = 4165.0;
  t.angular.z = -0.2;
  EXPECT_EQ(NonFiniteTwistField(t), "");
  t.angular.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(NonFiniteTwistField(t), "angular.y is not finite (inf)");
  t.linear.x = std::nan("");
  EXPECT_EQ(NonFiniteTwistField(t), "linear.x is not finite (nan)");
}

TEST(FoxgloveCommands, OnlyPaddingToAMultipleOfFourMayFollowTheSample) {
  EXPECT_EQ(TrailingBytes(52, 52), "");  // a Twist: 4 + 6 x 8 bytes
  EXPECT_EQ(TrailingBytes(40, 40), "");
  EXPECT_EQ(TrailingBytes(33, 34), "");  // shorter: Cyclone's own rule
  EXPECT_EQ(TrailingBytes(37, 37), "");
  EXPECT_EQ(TrailingBytes(40, 37), "");  // 3 bytes of padding to 40
  EXPECT_EQ(TrailingBytes(41, 37), "4 bytes after the 37-byte sample (only padding to a "
                                   "multiple of 4 may follow)");
  EXPECT_EQ(TrailingBytes(60, 52), "8 bytes after the 52-byte sample (only padding to a "
                                   "multiple of 4 may follow)");
}

}  // namespace
}  // namespace towsim::app
