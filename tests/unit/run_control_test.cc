// app/node/run_control: every transition of the node's run control (docs/topics.md), the
// requests refused or ignored as the node refuses them, and the status states.
#include "app/node/run_control.h"

#include <gtest/gtest.h>

#include "dds/messages.h"

namespace towsim::app {
namespace {

using dds::ControlRequest;

constexpr uint8_t kRunning = towsim_msgs_msg_dds__SimStatus_Constants_STATE_RUNNING;
constexpr uint8_t kPaused = towsim_msgs_msg_dds__SimStatus_Constants_STATE_PAUSED;
constexpr uint8_t kWaiting = towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
constexpr uint8_t kFinished = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;
constexpr uint8_t kFailed = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
constexpr uint8_t kStopped = towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;

ControlRequest Request(ControlRequest::Kind kind, long steps = 0, double rate = 0.0) {
  ControlRequest r;
  r.kind = kind;
  r.steps = steps;
  r.rate = rate;
  return r;
}

RunControl Running() { return RunControl(RunControl::Options{false, false, 100, 1.0}); }
RunControl Paused() { return RunControl(RunControl::Options{true, false, 100, 1.0}); }

TEST(RunControlTest, StartsRunningOrPaused) {
  const RunControl running = Running();
  EXPECT_FALSE(running.holding());
  EXPECT_EQ(running.State(false), kRunning);
  const RunControl paused = Paused();
  EXPECT_TRUE(paused.holding());
  EXPECT_EQ(paused.State(false), kPaused);
  EXPECT_EQ(paused.State(true), kPaused);  // paused wins over lockstep waiting
}

TEST(RunControlTest, PauseAndResume) {
  RunControl c = Running();
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kPause)).changed);
  EXPECT_TRUE(c.holding());
  EXPECT_EQ(c.State(false), kPaused);
  // paused again: no change
  EXPECT_FALSE(c.Apply(Request(ControlRequest::kPause)).changed);
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kResume)).changed);
  EXPECT_FALSE(c.holding());
  EXPECT_EQ(c.State(false), kRunning);
  // running: RESUME ignored, nothing noted
  const RunControl::Effect again = c.Apply(Request(ControlRequest::kResume));
  EXPECT_FALSE(again.changed);
  EXPECT_FALSE(again.invalid);
  EXPECT_EQ(c.note(), "");
}

TEST(RunControlTest, StepWhilePausedRunsThatManyStepsThenHolds) {
  RunControl c = Paused();
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kStep, 2)).changed);
  EXPECT_FALSE(c.holding());
  EXPECT_EQ(c.State(false), kRunning);
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kStep, 1)).changed);  // budgets add up
  EXPECT_EQ(c.step_budget(), 3);
  c.Stepped();
  c.Stepped();
  EXPECT_FALSE(c.holding());
  c.Stepped();
  EXPECT_TRUE(c.holding());
  EXPECT_EQ(c.State(false), kPaused);
  c.Stepped();  // no budget left: stays at 0
  EXPECT_EQ(c.step_budget(), 0);
}

TEST(RunControlTest, PauseOrResumeDropsTheStepBudget) {
  RunControl c = Paused();
  c.Apply(Request(ControlRequest::kStep, 5));
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kPause)).changed);  // paused, budget dropped
  EXPECT_EQ(c.step_budget(), 0);
  EXPECT_TRUE(c.holding());
  c.Apply(Request(ControlRequest::kStep, 5));
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kResume)).changed);
  EXPECT_EQ(c.step_budget(), 0);
  EXPECT_FALSE(c.paused());
}

TEST(RunControlTest, StepWhileRunningIsRefusedAndNoted) {
  RunControl c = Running();
  const RunControl::Effect e = c.Apply(Request(ControlRequest::kStep, 3));
  EXPECT_FALSE(e.changed);
  EXPECT_FALSE(e.invalid);
  EXPECT_EQ(c.step_budget(), 0);
  EXPECT_EQ(c.note(), "sim_control: STEP ignored: the node is not paused");
  // the next valid request clears the note
  c.Apply(Request(ControlRequest::kPause));
  EXPECT_EQ(c.note(), "");
}

TEST(RunControlTest, InvalidRequestIsRefusedAndKeepsTheState) {
  RunControl c = Paused();
  c.Apply(Request(ControlRequest::kStep, 2));
  ControlRequest bad = Request(ControlRequest::kInvalid);
  bad.error = "SET_RATE rate = nan: must be a number in [0.001, 1e+06]";
  const RunControl::Effect e = c.Apply(bad);
  EXPECT_TRUE(e.invalid);
  EXPECT_FALSE(e.changed);
  EXPECT_FALSE(e.reset);
  EXPECT_EQ(c.note(), "sim_control: " + bad.error);
  EXPECT_EQ(c.step_budget(), 2);
  EXPECT_TRUE(c.paused());
  EXPECT_DOUBLE_EQ(c.rate(), 1.0);
}

TEST(RunControlTest, SetRateInEitherState) {
  RunControl c = Running();
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kSetRate, 0, 4.0)).changed);
  EXPECT_DOUBLE_EQ(c.rate(), 4.0);
  c.Apply(Request(ControlRequest::kPause));
  EXPECT_TRUE(c.Apply(Request(ControlRequest::kSetRate, 0, 0.5)).changed);
  EXPECT_DOUBLE_EQ(c.rate(), 0.5);
  EXPECT_TRUE(c.holding());  // still paused
}

TEST(RunControlTest, ResetAsksForANewRunAndDropsBudgetAndNote) {
  RunControl c = Paused();
  c.Apply(Request(ControlRequest::kStep, 4));
  const RunControl::Effect e = c.Apply(Request(ControlRequest::kReset));
  EXPECT_TRUE(e.reset);
  EXPECT_TRUE(e.changed);
  EXPECT_EQ(c.step_budget(), 4);  // until the node has built the new run
  c.Reset();
  EXPECT_EQ(c.step_budget(), 0);
  EXPECT_TRUE(c.paused());  // a reset keeps the node paused
  RunControl r = Running();
  r.Apply(Request(ControlRequest::kStep, 1));  // noted
  r.Reset();
  EXPECT_EQ(r.note(), "");
  EXPECT_FALSE(r.holding());
}

TEST(RunControlTest, WaitingForControllersAndLockstep) {
  RunControl c(RunControl::Options{false, true, -1, 1.0});
  EXPECT_TRUE(c.waiting_for_controllers());
  EXPECT_EQ(c.State(false), kWaiting);
  c.ControllersReady();
  EXPECT_EQ(c.State(false), kRunning);
  EXPECT_EQ(c.State(true), kWaiting);  // lockstep waits for this step's commands
}

TEST(RunControlTest, FinishedAfterTheStepsToRun) {
  const RunControl c = Running();
  EXPECT_FALSE(c.finished(99));
  EXPECT_TRUE(c.finished(100));
  const RunControl endless(RunControl::Options{false, false, -1, 1.0});
  EXPECT_FALSE(endless.finished(1000000));
}

TEST(RunControlTest, EndStates) {
  EXPECT_EQ(Running().EndState(), kFinished);
  RunControl stopped = Running();
  stopped.Stop();
  EXPECT_EQ(stopped.EndState(), kStopped);
  RunControl failed = Running();
  failed.Fail("solver failure at t = 1 s (step 10): not converged");
  EXPECT_TRUE(failed.failed());
  EXPECT_EQ(failed.EndState(), kFailed);
  failed.Stop();  // a failure stays the end state
  EXPECT_EQ(failed.EndState(), kFailed);
}

}  // namespace
}  // namespace towsim::app
