// sim_node/dds/command_arbiter: last writer wins, reject / clamp, failsafe on timeout, lockstep
// readiness. Pure logic on simulation time.

#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "dds/command_arbiter.h"
#include "dds/vessel_pose_translator.h"

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

// --- external vessels (docs/vessels.md "External vessels") ---

// a vessel's pose message stamped t [s], at x north [m]
struct PoseMessage {
  explicit PoseMessage(double t, double x = 0.0) : m(kWorldFrame, "ship_frd") {
    core::VesselPose p;
    p.position.x() = x;
    p.velocity.x() = 2.0;
    ToPoseCommand(p, t, &m.msg);
  }
  OdometryMessage m;
};

CommandArbiter VehicleAndShip(bool ship_waited = true) {
  return CommandArbiter(
      {{"tow_vehicle", Limits(), true}, CommandArbiter::Vehicle::Vessel("ship", ship_waited)},
      kTimeout);
}

TEST(CommandArbiterTest, AVesselsPoseBelongsToTheStateNearestItsStamp) {
  CommandArbiter a = VehicleAndShip();
  // before the initial state (step -1): the vessel's pose of state 0, the vehicle not waited
  EXPECT_FALSE(a.ReadyFor(-1));
  EXPECT_EQ(a.Missing(-1), std::vector<int>{1});
  a.Receive(1, PoseMessage(0.0).m.msg, 0.0, 0, kH);
  EXPECT_TRUE(a.ReadyFor(-1));
  core::VesselPose pose;
  double t = -1.0;
  int64_t state = -1;
  ASSERT_TRUE(a.Take(1, &pose, &t, &state));
  EXPECT_EQ(state, 0);
  EXPECT_EQ(t, 0.0);
  EXPECT_FALSE(a.Take(1, &pose, &t, &state));  // given once
  // step 12 (state 12 at 0.6 s) waits for the command of step 12 and the pose of state 13
  a.Receive(0, Command(1000.0, 12), 0.6);
  EXPECT_FALSE(a.ReadyFor(12));
  // stamped in whole nanoseconds: 0.65 s is state 13 within half a step
  a.Receive(1, PoseMessage(0.65 + 0.2e-9, 5.0).m.msg, 0.6, 12, kH);
  EXPECT_TRUE(a.ReadyFor(12));
  ASSERT_TRUE(a.Take(1, &pose, &t, &state));
  EXPECT_EQ(state, 13);
  EXPECT_EQ(pose.position.x(), 5.0);
  EXPECT_TRUE(pose.given.has_value());
  // a later one releases the step too (state 14 >= 13)
  a.Receive(1, PoseMessage(0.7).m.msg, 0.6, 12, kH);
  EXPECT_TRUE(a.ReadyFor(12));
  // an older one (out of order) is counted and not held
  a.Receive(1, PoseMessage(0.55, 9.0).m.msg, 0.6, 12, kH);
  EXPECT_FALSE(a.Take(1, &pose, &t, &state) && pose.position.x() == 9.0);
  EXPECT_EQ(a.received(), 5u);
  EXPECT_EQ(a.rejected(), 0u);
}

TEST(CommandArbiterTest, AVesselsRejectedPoseIsCountedAndNotHeld) {
  CommandArbiter a = VehicleAndShip();
  PoseMessage bad(0.05);
  bad.m.msg.pose.pose.orientation.w = 2.0;
  const CheckedPose r = a.Receive(1, bad.m.msg, 0.0, 0, kH);
  EXPECT_EQ(r.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(a.rejected(), 1u);
  EXPECT_FALSE(a.ReadyFor(0));
  EXPECT_EQ(a.last_event().rfind("ship: command rejected (pose.pose.orientation: |q| = ", 0), 0u)
      << a.last_event();
}

TEST(CommandArbiterTest, StepsWithoutTheirPoseAreCountedOncePerRun) {
  CommandArbiter a = VehicleAndShip(false);      // realtime: not waited for
  EXPECT_EQ(a.Missing(0), std::vector<int>{0});  // the vehicle only
  // no pose yet: step 0 goes without one; its run of missing poses starts
  EXPECT_EQ(a.CountMissingPoses(0), 1);
  EXPECT_TRUE(a.late(1));
  EXPECT_EQ(a.last_event(), "ship: no pose for the end of step 0 (its last motion carried on)");
  EXPECT_EQ(a.CountMissingPoses(1), 0);  // still late: counted, not started again
  EXPECT_EQ(a.poses_missing(), 2u);
  a.Receive(1, PoseMessage(0.15).m.msg, 0.1, 2, kH);  // state 3: the end of step 2
  EXPECT_EQ(a.CountMissingPoses(2), 0);
  EXPECT_FALSE(a.late(1));
  EXPECT_EQ(a.poses_missing(), 2u);
  EXPECT_EQ(a.CountMissingPoses(3), 1);  // a new run
  EXPECT_EQ(a.poses_missing(), 3u);
}

TEST(CommandArbiterTest, AVesselWithoutPosesTimesOutIntoFailsafe) {
  CommandArbiter a = VehicleAndShip();
  a.Receive(1, PoseMessage(0.05).m.msg, 0.0, 0, kH);
  EXPECT_EQ(a.CheckTimeouts(kTimeout - kH), 0);
  EXPECT_EQ(a.CheckTimeouts(kTimeout), 1);
  EXPECT_TRUE(a.failsafe(1));
  EXPECT_EQ(a.last_failsafe_reason(),
            "no pose for 0.5 s of simulation time (its last motion carried on)");
  core::VesselPose pose;
  double t;
  int64_t state;
  EXPECT_FALSE(a.Take(1, &pose, &t, &state));  // no failsafe pose: the last motion goes on
  // lockstep: the pose of step 11's end did not come in time
  a.Receive(1, PoseMessage(0.55).m.msg, 0.5, 10, kH);
  EXPECT_FALSE(a.failsafe(1));  // poses resumed
  a.Receive(0, Command(1.0, 11), 0.55);
  EXPECT_EQ(a.TimeOut(11), 1);
  EXPECT_EQ(a.last_failsafe_reason(),
            "lockstep: no pose for the end of step 11 in time (its last motion carried on)");
  EXPECT_TRUE(a.ReadyFor(11));  // no longer waited for
  EXPECT_EQ(a.lockstep_timeouts(), 1u);
  a.Reset();
  EXPECT_EQ(a.poses_missing(), 0u);
  EXPECT_FALSE(a.ReadyFor(-1));
}

}  // namespace
}  // namespace towsim::dds
