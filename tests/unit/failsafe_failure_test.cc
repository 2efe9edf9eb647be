// sim_node/app/node/failsafe_failure: the reason --fail-on-failsafe gives for exit code 5,
// from a real CommandArbiter (which entries are in failsafe, and why). Pure.

#include "app/node/failsafe_failure.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/winch.h"
#include "dds/command_arbiter.h"

namespace towsim::app {
namespace {

constexpr double kTimeout = 0.5;  // [s], the default command_timeout

dds::ActuatorCommandMsg Command(uint64_t step) {
  dds::ActuatorCommandMsg m{};
  m.step = step;
  return m;
}

dds::CommandArbiter Arbiter() {
  core::WinchParams winch;
  winch.min_length = 10.0;
  winch.max_length = 200.0;
  winch.max_speed = 1.0;
  winch.max_acceleration = 0.5;
  std::vector<dds::CommandArbiter::Vehicle> entries = {{"tow_vehicle", {}, true},
                                                       {"towfish", {}, true}};
  entries.push_back(dds::CommandArbiter::Vehicle::Winch(winch, true));
  return dds::CommandArbiter(std::move(entries), kTimeout);
}

TEST(FailsafeFailureTest, EntriesNameTheBodiesAndTheWinchInFailsafe) {
  dds::CommandArbiter a = Arbiter();
  EXPECT_EQ(FailsafeEntries(a), "");
  a.Receive(1, Command(0), 0.0);
  ASSERT_EQ(a.CheckTimeouts(kTimeout), 1);
  EXPECT_EQ(FailsafeEntries(a), "body towfish");
  // step 10: the tow vehicle and the winch (heard from, rejected or not) time out too
  a.Receive(0, Command(9), 0.45);
  dds::WinchCommandMsg w{};
  w.step = 9;
  a.Receive(2, w, 0.45);
  ASSERT_EQ(a.TimeOut(10), 3);  // towfish, already in failsafe, is no longer waited for either
  EXPECT_EQ(FailsafeEntries(a), "body tow_vehicle, body towfish, the winch");
}

TEST(FailsafeFailureTest, CommandTimeoutSaysBodyTimeStepAndWhy) {
  dds::CommandArbiter a = Arbiter();
  a.Receive(1, Command(0), 0.0);
  ASSERT_EQ(a.CheckTimeouts(12.34), 1);
  EXPECT_EQ(FailsafeFailure(FailsafeEntries(a), 12.34, 1234, a.last_failsafe_reason()),
            "failsafe: body towfish at t = 12.34 s (step 1234): no command for 12.3 s of "
            "simulation time");
}

TEST(FailsafeFailureTest, LockstepTimeoutSaysBodyStepWaitAndLimit) {
  EXPECT_EQ(LockstepTimeoutFailure("body towfish", 61.7, 1234, 2.0004, 2.0, false),
            "lockstep timeout: body towfish at step 1234 (t = 61.7 s): no command after 2 s "
            "(--lockstep-timeout 2)");
  EXPECT_EQ(LockstepTimeoutFailure("body towfish", 0.0, 0, 30.01, 1.0, true),
            "lockstep timeout: body towfish at step 0 (t = 0 s): no command after 30 s (never "
            "heard from: is its controller running?)");
}

}  // namespace
}  // namespace towsim::app
