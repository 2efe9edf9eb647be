#include "core/winch_drive.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/initial_shape.h"
#include "core/state.h"
#include "core/system.h"
#include "steady_tow_model.h"

namespace towsim::core {
namespace {

// the drum's part of a step around a stand-in for the cable's step (it leaves the state as it
// is): the winch's state at the step's end is AdvanceWinch's (winch.h), the stand-in is called
// once without a brake, and nothing moves when the step fails
TEST(WinchDrive, DrumMotionAroundTheCablesStep) {
  const Model model = test::SteadyTowWithWinch();  // 150-260 m, 5 m/s, 5 m/s^2
  System system(model);
  State state;
  BuildInitialState(system, &state);
  WinchDrive drive(&system);
  ASSERT_TRUE(drive.has_winch());
  drive.Initialize(&state);
  const double l0 = model.cables[0].length;
  EXPECT_EQ(state.winches[0].length, l0);
  EXPECT_EQ(state.winches[0].speed, 0.0);
  EXPECT_EQ(state.winches[0].nodes, system.num_nodes());

  drive.SetCommand({WinchCommand::Mode::kSpeed, 10.0});  // clamped to max_speed
  EXPECT_EQ(drive.command().value, 5.0);
  drive.SetCommand({WinchCommand::Mode::kSpeed, std::numeric_limits<double>::quiet_NaN()});
  EXPECT_EQ(drive.command().value, 5.0);  // ignored

  int calls = 0;
  StepStatus result;  // what the stand-in returns
  auto step_system = [&](double) {
    ++calls;
    return result;
  };
  // h = 1/8 s: V = 0 + a h = 0.625 m/s, L = l0 + h (0 + V) / 2 = l0 + 0.0390625 m (exact)
  const double h = 0.125;
  result.code = StepStatus::kNotConverged;
  EXPECT_FALSE(drive.Step(h, &state, step_system).ok());
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(state.winches[0].length, l0);  // a failed step leaves the winch where it was
  EXPECT_EQ(state.winches[0].speed, 0.0);
  // the drum element's motion over the step: l_0 reaches l_0 + dL at t + h from rate 0
  EXPECT_EQ(state.winches[0].drum.accel, 2.0 * 0.0390625 / (h * h));

  result.code = StepStatus::kOk;
  EXPECT_TRUE(drive.Step(h, &state, step_system).ok());
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(state.winches[0].length, l0 + 0.0390625);
  EXPECT_EQ(state.winches[0].speed, 0.625);
  EXPECT_EQ(state.winches[0].drive_speed, 0.625);
  EXPECT_FALSE(state.winches[0].slipping);
  EXPECT_EQ(state.step, 0);  // the step count is the Simulation's
}

// without a winch the step is the cable's alone, and a command is ignored
TEST(WinchDrive, WithoutAWinchOnlyTheCablesStep) {
  const Model model = test::SteadyTowModel();
  System system(model);
  State state;
  BuildInitialState(system, &state);
  WinchDrive drive(&system);
  EXPECT_FALSE(drive.has_winch());
  drive.Initialize(&state);
  drive.SetCommand({WinchCommand::Mode::kSpeed, 1.0});
  EXPECT_EQ(drive.command().value, 0.0);
  int calls = 0;
  auto step_system = [&](double) {
    ++calls;
    return StepStatus();
  };
  EXPECT_TRUE(drive.Step(0.1, &state, step_system).ok());
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(state.winches[0].length, model.cables[0].length);
}

}  // namespace
}  // namespace towsim::core
