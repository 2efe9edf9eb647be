// sim_node/dds/winch_command: the winch's WinchCommand checked against its limits (the core's
// WinchCommandRange), without DDS entities.

#include <limits>

#include <gtest/gtest.h>

#include "dds/winch_command.h"

namespace towsim::dds {
namespace {

core::WinchParams Winch() {
  core::WinchParams w;
  w.min_length = 100.0;
  w.max_length = 300.0;
  w.max_speed = 1.5;
  w.max_acceleration = 0.25;
  return w;
}

WinchCommandMsg Command(uint8_t mode, double value, uint64_t step = 9) {
  WinchCommandMsg m{};
  m.step = step;
  m.mode = mode;
  m.value = value;
  return m;
}

constexpr uint8_t kSpeed = towsim_msgs_msg_dds__WinchCommand_Constants_SPEED;
constexpr uint8_t kLength = towsim_msgs_msg_dds__WinchCommand_Constants_LENGTH;

TEST(WinchCommandTest, AcceptsWithinTheLimits) {
  const CheckedWinchCommand s = FromWinchCommand(Command(kSpeed, -1.25), Winch());
  EXPECT_EQ(s.verdict, CheckedCommand::kAccepted);
  EXPECT_EQ(s.command.mode, core::WinchCommand::Mode::kSpeed);
  EXPECT_EQ(s.command.value, -1.25);
  EXPECT_EQ(s.step, 9u);
  const CheckedWinchCommand l = FromWinchCommand(Command(kLength, 250.0), Winch());
  EXPECT_EQ(l.verdict, CheckedCommand::kAccepted);
  EXPECT_EQ(l.command.mode, core::WinchCommand::Mode::kLength);
  EXPECT_EQ(l.command.value, 250.0);
}

TEST(WinchCommandTest, ClampsSpeedAndLengthToTheWinchsLimits) {
  const CheckedWinchCommand s = FromWinchCommand(Command(kSpeed, 4.0), Winch());
  EXPECT_EQ(s.verdict, CheckedCommand::kClamped);
  EXPECT_EQ(s.command.value, 1.5);
  EXPECT_EQ(s.reason, "winch speed 4 clamped to the winch's limits [-1.5, 1.5]");
  EXPECT_EQ(FromWinchCommand(Command(kSpeed, -4.0), Winch()).command.value, -1.5);
  const CheckedWinchCommand l = FromWinchCommand(Command(kLength, 20.0), Winch());
  EXPECT_EQ(l.verdict, CheckedCommand::kClamped);
  EXPECT_EQ(l.command.value, 100.0);
  EXPECT_EQ(l.reason, "winch length 20 clamped to the winch's limits [100, 300]");
  EXPECT_EQ(FromWinchCommand(Command(kLength, 1e9), Winch()).command.value, 300.0);
}

TEST(WinchCommandTest, RejectsNanInfinityAndUnknownModes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const CheckedWinchCommand n = FromWinchCommand(Command(kSpeed, nan), Winch());
  EXPECT_EQ(n.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(n.reason, "speed is NaN");
  const CheckedWinchCommand i = FromWinchCommand(Command(kLength, -inf), Winch());
  EXPECT_EQ(i.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(i.reason, "length is infinite");
  const CheckedWinchCommand m = FromWinchCommand(Command(7, 1.0), Winch());
  EXPECT_EQ(m.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(m.reason, "mode 7 is neither SPEED (0) nor LENGTH (1)");
}

}  // namespace
}  // namespace towsim::dds
