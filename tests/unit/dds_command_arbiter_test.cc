// sim_node/dds/command_arbiter: last writer wins, reject / clamp, failsafe on timeout, lockstep
// readiness. Pure logic on simulation time.

#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "dds/command_arbiter.h"

namespace towsim::dds {
namespace {

constexpr double kTimeout = 0.5;  // [s], the default command_timeout
constexpr double kH = 0.05;       // [s], a step

CommandLimits Limits() {
  CommandLimits l;
  l.thrust_min = -3000.0;
  l.thrust_max = 12000.0;
  l.rudder_max = 0.5;
  l.elevator_max = 0.5;
  return l;
}

ActuatorCommandMsg Command(double thrust, uint64_t step, double rudder = 0.0) {
  ActuatorCommandMsg m{};
  m.step = step;
  m.thrust = thrust;
  m.rudder = rudder;
  return m;
}

CommandArbiter TwoVehicles(bool lockstep_second = true) {
  return CommandArbiter({{"tow_vehicle", Limits(), true}, {"towfish", Limits(), lockstep_second}},
                        kTimeout);
}

TEST(CommandArbiterTest, LastWriterWins) {
  CommandArbiter a = TwoVehicles();
  core::VehicleCommand c;
  EXPECT_FALSE(a.Take(0, &c));  // nothing held yet: the scene drives the vehicle
  a.Receive(0, Command(1000.0, 0), 0.0);
  a.Receive(0, Command(2000.0, 0), 0.0);
  ASSERT_TRUE(a.Take(0, &c));
  EXPECT_EQ(c.thrust, 2000.0);
  EXPECT_FALSE(a.Take(0, &c));  // given once
  EXPECT_EQ(a.received(), 2u);
}

TEST(CommandArbiterTest, RejectsNanKeepsHeldAndCounts) {
  CommandArbiter a = TwoVehicles();
  a.Receive(0, Command(1000.0, 0), 0.0);
  const CheckedCommand r = a.Receive(0, Command(std::numeric_limits<double>::quiet_NaN(), 1), kH);
  EXPECT_EQ(r.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(a.rejected(), 1u);
  EXPECT_EQ(a.held(0).thrust, 1000.0);
  EXPECT_EQ(a.last_event(), "tow_vehicle: command rejected (thrust is NaN)");
  // a rejected command does not count as one: the timeout runs from the last valid command
  a.CheckTimeouts(kTimeout);
  EXPECT_TRUE(a.failsafe(0));
}

TEST(CommandArbiterTest, ClampsAndCounts) {
  CommandArbiter a = TwoVehicles();
  a.Receive(1, Command(0.0, 0, 3.0), 0.0);
  EXPECT_EQ(a.clamped(), 1u);
  core::VehicleCommand c;
  ASSERT_TRUE(a.Take(1, &c));
  EXPECT_EQ(c.rudder, 0.5);
}

TEST(CommandArbiterTest, FailsafeAfterTimeoutUntilCommandsResume) {
  CommandArbiter a = TwoVehicles();
  a.Receive(0, Command(4500.0, 0, 0.2), 0.0);
  core::VehicleCommand c;
  EXPECT_EQ(a.CheckTimeouts(0.45), 0);
  EXPECT_FALSE(a.failsafe(0));
  EXPECT_EQ(a.last_failsafe_reason(), "");
  ASSERT_TRUE(a.Take(0, &c));
  EXPECT_EQ(c.thrust, 4500.0);
  // 10 steps of 0.05 s land on 0.5 only up to rounding
  double t = 0.0;
  for (int k = 0; k < 10; ++k) t += kH;
  EXPECT_EQ(a.CheckTimeouts(t), 1);  // entered now
  EXPECT_TRUE(a.failsafe(0));
  EXPECT_EQ(a.last_failsafe_reason(), "no command for 0.5 s of simulation time");
  EXPECT_FALSE(a.failsafe(1));  // never commanded: not armed
  EXPECT_EQ(a.failsafe_count(), 1u);
  EXPECT_EQ(a.failsafe_names(), std::vector<std::string>{"tow_vehicle"});
  // the failsafe command on every step: zero thrust, fins centred
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(a.Take(0, &c));
    EXPECT_EQ(c.thrust, 0.0);
    EXPECT_EQ(c.rudder, 0.0);
    EXPECT_EQ(c.elevator, 0.0);
  }
  EXPECT_EQ(a.CheckTimeouts(t + kH), 0);  // already in failsafe: not entered again
  EXPECT_EQ(a.failsafe_count(), 1u);      // one entry, not one per step
  // commands resume
  a.Receive(0, Command(3000.0, 12), t + kH);
  EXPECT_FALSE(a.failsafe(0));
  ASSERT_TRUE(a.Take(0, &c));
  EXPECT_EQ(c.thrust, 3000.0);
}

TEST(CommandArbiterTest, LockstepWaitsForEveryVehicleOfTheStep) {
  CommandArbiter a = TwoVehicles();
  EXPECT_FALSE(a.ReadyFor(0));
  EXPECT_EQ(a.Missing(0), (std::vector<int>{0, 1}));
  a.Receive(0, Command(0.0, 0), 0.0);
  EXPECT_FALSE(a.ReadyFor(0));
  a.Receive(1, Command(0.0, 0), 0.0);
  EXPECT_TRUE(a.ReadyFor(0));
  EXPECT_FALSE(a.ReadyFor(1));  // answers step 0, not 1
  a.Receive(0, Command(0.0, 1), kH);
  EXPECT_EQ(a.Missing(1), std::vector<int>{1});
}

TEST(CommandArbiterTest, LockstepIgnoresVehiclesNotWaitedFor) {
  CommandArbiter a = TwoVehicles(/*lockstep_second=*/false);
  a.Receive(0, Command(0.0, 0), 0.0);
  EXPECT_TRUE(a.ReadyFor(0));
}

TEST(CommandArbiterTest, LockstepTimeoutFailsafesCommandedVehiclesOnly) {
  CommandArbiter a = TwoVehicles();
  a.Receive(0, Command(100.0, 0), 0.0);
  a.Receive(1, Command(0.0, 0), 0.0);
  ASSERT_TRUE(a.ReadyFor(0));
  a.Receive(0, Command(100.0, 1), kH);  // towfish's controller died
  EXPECT_EQ(a.TimeOut(1), 1);
  EXPECT_TRUE(a.failsafe(1));
  EXPECT_EQ(a.lockstep_timeouts(), 1u);
  EXPECT_TRUE(a.ReadyFor(1));  // no longer waited for
  EXPECT_EQ(a.last_event(), "towfish: failsafe (lockstep: no command for step 1 in time)");
  EXPECT_EQ(a.last_failsafe_reason(), "lockstep: no command for step 1 in time");
  // it comes back
  a.Receive(1, Command(0.0, 2), 2 * kH);
  EXPECT_FALSE(a.failsafe(1));
  EXPECT_FALSE(a.ReadyFor(2));  // tow_vehicle has not answered step 2 yet
  // a vehicle never commanded is waited for without limit (its controller may be starting)
  CommandArbiter b = TwoVehicles();
  EXPECT_EQ(b.TimeOut(0), 0);
  EXPECT_FALSE(b.ReadyFor(0));
}

TEST(CommandArbiterTest, ResetForgetsEverything) {
  CommandArbiter a = TwoVehicles();
  a.Receive(0, Command(100.0, 40), 2.0);
  a.CheckTimeouts(3.0);
  ASSERT_TRUE(a.failsafe(0));
  a.Reset();
  EXPECT_FALSE(a.failsafe(0));
  EXPECT_FALSE(a.commanded(0));
  EXPECT_EQ(a.received(), 0u);
  EXPECT_EQ(a.failsafe_count(), 0u);
  EXPECT_EQ(a.last_failsafe_reason(), "");
  EXPECT_FALSE(a.ReadyFor(40));
  core::VehicleCommand c;
  EXPECT_FALSE(a.Take(0, &c));
}

}  // namespace
}  // namespace towsim::dds

namespace towsim::dds {
namespace {

// a vehicle and the winch (entry 1), as the node builds them for a scene with cable.winch
CommandArbiter VehicleAndWinch() {
  core::WinchParams w;
  w.min_length = 100.0;
  w.max_length = 300.0;
  w.max_speed = 1.0;
  w.max_acceleration = 0.1;
  return CommandArbiter({{"tow_vehicle", Limits(), true}, CommandArbiter::Vehicle::Winch(w, true)},
                        kTimeout);
}

WinchCommandMsg WinchSpeed(double speed, uint64_t step) {
  WinchCommandMsg m{};
  m.step = step;
  m.mode = towsim_msgs_msg_dds__WinchCommand_Constants_SPEED;
  m.value = speed;
  return m;
}

TEST(CommandArbiterWinchTest, CheckedCountedAndHeldLikeAVehiclesCommand) {
  CommandArbiter a = VehicleAndWinch();
  EXPECT_EQ(a.vehicle(1).name, "winch");
  core::WinchCommand w;
  EXPECT_FALSE(a.Take(1, &w));  // nothing held: the scene's script drives the winch
  a.Receive(1, WinchSpeed(0.5, 0), 0.0);
  ASSERT_TRUE(a.Take(1, &w));
  EXPECT_EQ(w.mode, core::WinchCommand::Mode::kSpeed);
  EXPECT_EQ(w.value, 0.5);
  EXPECT_FALSE(a.Take(1, &w));  // given once
  // out of range: clamped; NaN: rejected, the held command stays; both counted with the
  // vehicles' commands
  a.Receive(1, WinchSpeed(3.0, 1), kH);
  a.Receive(1, WinchSpeed(std::numeric_limits<double>::quiet_NaN(), 2), 2 * kH);
  a.Receive(0, Command(1000.0, 2), 2 * kH);
  EXPECT_EQ(a.received(), 4u);
  EXPECT_EQ(a.clamped(), 1u);
  EXPECT_EQ(a.rejected(), 1u);
  EXPECT_EQ(a.last_event(), "winch: command rejected (speed is NaN)");
  ASSERT_TRUE(a.Take(1, &w));
  EXPECT_EQ(w.value, 1.0);
}

TEST(CommandArbiterWinchTest, FailsafeHoldsTheDrumAtSpeedZero) {
  CommandArbiter a = VehicleAndWinch();
  a.Receive(1, WinchSpeed(-0.8, 0), 0.0);
  core::WinchCommand w;
  ASSERT_TRUE(a.Take(1, &w));
  a.CheckTimeouts(kTimeout);
  EXPECT_TRUE(a.failsafe(1));
  EXPECT_EQ(a.failsafe_names(), std::vector<std::string>{"winch"});
  for (int k = 0; k < 2; ++k) {  // on every step of the failsafe
    ASSERT_TRUE(a.Take(1, &w));
    EXPECT_EQ(w.mode, core::WinchCommand::Mode::kSpeed);
    EXPECT_EQ(w.value, 0.0);
  }
}

TEST(CommandArbiterWinchTest, LockstepWaitsForTheWinchLikeForAVehicle) {
  CommandArbiter a = VehicleAndWinch();
  a.Receive(0, Command(0.0, 0), 0.0);
  EXPECT_FALSE(a.ReadyFor(0));
  EXPECT_EQ(a.Missing(0), std::vector<int>{1});
  a.Receive(1, WinchSpeed(0.0, 0), 0.0);
  EXPECT_TRUE(a.ReadyFor(0));
  // the winch's controller stops: after the lockstep timeout, failsafe and no longer waited for
  a.Receive(0, Command(0.0, 1), kH);
  EXPECT_EQ(a.TimeOut(1), 1);
  EXPECT_TRUE(a.failsafe(1));
  EXPECT_TRUE(a.ReadyFor(1));
  EXPECT_EQ(a.lockstep_timeouts(), 1u);
}

}  // namespace
}  // namespace towsim::dds
