// sim_node --lockstep-timeout and --fail-on-failsafe as processes over loopback (docs/topics.md,
// "Commands and lockstep"; docs/command_line.md "Exit codes"): the node, the test controller
// pausing before one step (--pause STEP=S) and this test watching the status. Domains 94-97
// (README.md in this folder).

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dds_observer.h"
#include "testing/csv_file.h"
#include "testing/process.h"
#include "towsim_msgs.h"

namespace towsim::testing {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kCase1 = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml";
constexpr double kProcessTimeout = 60.0;  // [s] a run that takes longer has hung
constexpr double kStep = 0.05;            // case1_forward's time.step [s]
constexpr long kPausedStep = 10;          // the step the controller answers late
constexpr uint8_t kFailed = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
constexpr uint8_t kFinished = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

class LockstepTimeoutTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // loopback only, never Cyclone's default; the children inherit it
    setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
  }
};

struct PausedRun {
  int node_exit = -1;
  int controller_exit = -1;
  std::string out, err;  // the node's
  double wall = 0.0;     // [s] from the node's start to its end
};

// case1_forward in lockstep for 2 s (40 steps) with `node_extra`; the test controller answers
// every step, step kPausedStep after `pause` wall seconds
PausedRun PausedController(int domain, double pause, const std::vector<std::string>& node_extra) {
  std::vector<std::string> extra = {"--duration", "2"};
  extra.insert(extra.end(), node_extra.begin(), node_extra.end());
  const Clock::time_point start = Clock::now();
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, kCase1, "lockstep", domain, extra), LogPrefix("node"));
  Process controller({TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(domain), "--pause",
                      std::to_string(kPausedStep) + "=" + std::to_string(pause)},
                     LogPrefix("controller"));
  PausedRun r;
  EXPECT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  r.wall = Seconds(Clock::now() - start);
  EXPECT_TRUE(controller.Wait(kProcessTimeout)) << controller.command_line();
  r.node_exit = node.exit_code();
  r.controller_exit = controller.exit_code();
  r.out = node.out();
  r.err = node.err();
  return r;
}

// domain 94: a pause longer than --lockstep-timeout ends the run with exit 5 after the step
// that timed out, naming the bodies and the step on stderr and in the final status (FAILED),
// with the CSV written up to that step and the summary counting the timeouts
TEST_F(LockstepTimeoutTest, PauseLongerThanTheTimeoutExits5NamingBodyAndStep) {
  Observer watch(94);
  const std::string csv = LogPrefix("csv");
  const PausedRun r =
      PausedController(94, 1.5, {"--lockstep-timeout", "0.5", "--fail-on-failsafe", "--csv", csv});
  EXPECT_EQ(r.node_exit, 5) << r.err;
  EXPECT_EQ(r.controller_exit, 0);
  const std::string reason =
      "lockstep timeout: body tow_vehicle, body towfish at step 10 (t = 0.5 s)";
  EXPECT_NE(r.err.find("sim_node: error: " + reason), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(--lockstep-timeout 0.5) (--fail-on-failsafe)"), std::string::npos)
      << r.err;
  // the step that timed out was taken (failsafe commands), and no other
  EXPECT_NE(r.out.find("lockstep, 11 steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failsafes 2,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lockstep timeouts 2,"), std::string::npos) << r.out;

  Status end;
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.terminal(); }, &end));
  EXPECT_EQ(end.state, kFailed);
  EXPECT_EQ(end.health, towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_ERROR);
  EXPECT_EQ(end.failsafe_bodies, (std::vector<std::string>{"tow_vehicle", "towfish"}));
  EXPECT_EQ(end.lockstep_timeouts, 2u);
  EXPECT_EQ(end.step, 11u);
  EXPECT_NE(end.message.find(reason), std::string::npos) << end.message;

  // bodies.csv complete: every output time to the last state (step 11), both bodies each
  const CsvTable bodies = ReadCsv(csv + "/bodies.csv");
  ASSERT_GE(bodies.rows.size(), 2u);
  EXPECT_NEAR(std::strtod(bodies.rows.back()[0].c_str(), nullptr), 11 * kStep, 1e-9);
  EXPECT_EQ(bodies.rows.size(), 2u * 7u);  // t = 0, 0.1, ..., 0.5 and the last, 0.55

  // actuators.csv: the arbiter's failsafe flag of the step that led to each row: 0 up to
  // t = 0.5, 1 for both vehicles in the last row (step 11, taken in failsafe: zero thrust,
  // fins centred)
  const CsvTable actuators = ReadCsv(csv + "/actuators.csv");
  ASSERT_EQ(actuators.header.size(), 9u);
  EXPECT_EQ(actuators.header.back(), "failsafe");
  ASSERT_EQ(actuators.rows.size(), 2u * 7u);
  for (std::size_t i = 0; i < actuators.rows.size(); ++i) {
    const std::vector<std::string>& row = actuators.rows[i];
    ASSERT_EQ(row.size(), 9u);
    const bool last = i >= actuators.rows.size() - 2;
    EXPECT_EQ(row[8], last ? "1" : "0") << "row " << i << " at t = " << row[0];
    if (last) {
      EXPECT_EQ(row[2] + "," + row[3] + "," + row[4], "0,0,0") << row[1];
    }
  }
}

// domain 95: a pause shorter than --lockstep-timeout: no timeout, exit 0
TEST_F(LockstepTimeoutTest, PauseShorterThanTheTimeoutExits0) {
  Observer watch(95);
  const PausedRun r = PausedController(95, 1.0, {"--lockstep-timeout", "3", "--fail-on-failsafe"});
  EXPECT_EQ(r.node_exit, 0) << r.err;
  EXPECT_EQ(r.controller_exit, 0);
  EXPECT_NE(r.out.find("lockstep, 40 steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failsafes 0,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lockstep timeouts 0,"), std::string::npos) << r.out;
  Status end;
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.terminal(); }, &end));
  EXPECT_EQ(end.state, kFinished);
  EXPECT_GE(r.wall, 1.0);  // the pause was waited through
}

// domain 96: --lockstep-timeout 0 waits through a 5 s pause: no timeout, exit 0
TEST_F(LockstepTimeoutTest, ZeroWaitsThroughAFiveSecondPause) {
  const PausedRun r = PausedController(96, 5.0, {"--lockstep-timeout", "0", "--fail-on-failsafe"});
  EXPECT_EQ(r.node_exit, 0) << r.err;
  EXPECT_EQ(r.controller_exit, 0);
  EXPECT_NE(r.out.find("lockstep, 40 steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failsafes 0,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lockstep timeouts 0,"), std::string::npos) << r.out;
  EXPECT_GE(r.wall, 5.0);
}

// domain 97: outside lockstep, a failsafe after command_timeout (0.5 s of simulation time
// without a command) ends a --fail-on-failsafe run with exit 5, naming the body, t and step
TEST_F(LockstepTimeoutTest, CommandTimeoutFailsafeExits5InFastMode) {
  Observer watch(97);
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, kCase1, "fast", 97,
                           {"--duration", "2", "--paused", "--fail-on-failsafe"}),
               LogPrefix("node"));
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.step == 0; }, nullptr));
  watch.Command("towfish", 0, 0.0, 0.0, 0.0);  // one command, then silence
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  watch.Control(towsim_msgs_msg_dds__SimControl_Constants_RESUME);
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 5) << node.err();
  const std::string reason = "failsafe: body towfish at t = 0.5 s (step 10): no command for 0.5 s";
  EXPECT_NE(node.err().find(reason), std::string::npos) << node.err();
  EXPECT_NE(node.out().find("fast, 11 steps"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("failsafes 1,"), std::string::npos) << node.out();
  Status end;
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.terminal(); }, &end));
  EXPECT_EQ(end.state, kFailed);
  EXPECT_NE(end.message.find(reason), std::string::npos) << end.message;
}

}  // namespace
}  // namespace towsim::testing
