// The test fixture for controllers (controllers/testing, towsim::testing) against the
// build tree's sim_node: start-up paused, SimControl STEP, the latest samples of every topic,
// the samples equal to the node's own bodies.csv, stop with exit code and summary, a bad scene
// reported with the node's message, and parallel nodes on distinct automatic domain ids.
// Realtime mode too; --fail-on-failsafe by default (exit 5 on a stalled controller), and
// turned off. The log folders the fixture makes: removed after a passing test, kept after a
// failing one. Domains 170 and 171 (fixed), automatic ones from 200-231
// (tests/integration/README.md).

#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "testing/csv_file.h"
#include "testing/in_process_controller.h"
#include "testing/process.h"
#include "testing/sim_node.h"

namespace towsim::testing {
namespace {

std::string G9(double x) {  // the CSV's number format (docs/contract.md §5)
  char s[40];
  std::snprintf(s, sizeof s, "%.9g", x);
  return s;
}

// domain 170
TEST(SimNodeFixture, StartsPausedStepsAndStops) {
  SimNodeOptions o;
  o.scene = "steady_tow";  // config/scenes/steady_tow.yaml: a sphere towed at 6 m/s, no vehicles
  o.domain = 170;
  o.duration = 100.0;
  o.start_paused = true;
  SimNode node(o);
  EXPECT_EQ(node.domain(), 170);
  EXPECT_EQ(node.scene_info().scene, "steady_tow");
  EXPECT_EQ(node.scene_info().step_size, 0.05);
  EXPECT_EQ(node.scene_info().bodies, std::vector<std::string>{"towfish"});
  EXPECT_EQ(node.scene_info().cable_nodes, 21u);  // 20 elements
  // the initial state, exactly as the scene gives it
  ASSERT_TRUE(node.odometry("towfish").has_value());
  EXPECT_EQ(node.odometry("towfish")->t, 0.0);
  EXPECT_EQ(node.odometry("towfish")->z, 203.5);
  ASSERT_TRUE(node.status().has_value());
  EXPECT_TRUE(node.status()->paused());

  node.Step(5);
  ASSERT_TRUE(node.WaitForStatus([](const StatusSample& s) { return s.step == 5 && s.paused(); }));
  // 5 steps of 0.05 s (the stamp: sec + 1e-9 nanosec, rounded)
  ASSERT_TRUE(node.odometry("towfish").has_value());
  EXPECT_NEAR(node.odometry("towfish")->t, 0.25, 1e-12);
  // the cable state comes at the scene's output rate (10 Hz: every 2nd step), and the paused
  // node repeats every topic's state every 0.5 s: step 5's within a second
  for (int i = 0; i < 200 && !(node.cable_state() && node.cable_state()->step == 5); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(node.cable_state().has_value());
  EXPECT_EQ(node.cable_state()->step, 5u);
  EXPECT_EQ(node.cable_state()->tension.size(), 21u);
  ASSERT_TRUE(node.cable_force("towfish").has_value());
  // one sample per state: 0, 1, ..., 5 (the paused node's repetitions merged)
  const std::vector<OdometrySample> h = node.odometry_history("towfish");
  ASSERT_EQ(h.size(), 6u);
  for (size_t k = 0; k < h.size(); ++k) EXPECT_NEAR(h[k].t, 0.05 * k, 1e-12);

  const NodeResult end = node.Stop();
  EXPECT_EQ(end.exit_code, 0) << node.log();
  EXPECT_EQ(end.summary.rfind("sim_node: steady_tow: lockstep, 5 steps, 0.25 s simulated", 0), 0u)
      << end.summary;

  // the fixture's samples are the node's: its bodies.csv (10 Hz: t = 0, 0.1, 0.2, and the
  // final state 0.25) at 9 digits
  const CsvTable csv = ReadCsv(node.csv_dir() + "/bodies.csv");
  int rows = 0;
  for (const std::vector<std::string>& f : csv.rows) {
    const std::string row = JoinCsvRow(f);
    ASSERT_EQ(f.size(), 14u) << row;
    const double t = std::stod(f[0]);
    const OdometrySample* match = nullptr;
    for (const OdometrySample& x : h) {
      if (std::abs(x.t - t) < 1e-9) match = &x;
    }
    ASSERT_NE(match, nullptr) << row;
    EXPECT_EQ(f[2], G9(match->x)) << row;
    EXPECT_EQ(f[4], G9(match->z)) << row;
    EXPECT_EQ(f[8], G9(match->u)) << row;
    ++rows;
  }
  EXPECT_EQ(rows, 4);
}

// The log folders (SimNodeOptions::log_dir empty) and the LogPrefix files: each case below runs
// in a process of its own (this program again, the case enabled by name), so that its test has
// ended when they are looked at. Each prints its folder on a line "log_dir DIR" and its
// process log on a line "log_file FILE".
void RunShortNode(bool fail) {
  SimNodeOptions o;
  o.scene = "steady_tow";
  o.duration = 0.5;
  SimNode node(o);
  std::printf("log_dir %s\n", node.log_dir().c_str());
  Process probe({"/bin/true"}, LogPrefix("probe"));
  EXPECT_TRUE(probe.Wait(10.0));
  std::printf("log_file %s.out\n", LogPrefix("probe").c_str());
  EXPECT_EQ(node.Wait().exit_code, 0) << node.log();
  EXPECT_TRUE(std::filesystem::is_regular_file(node.csv_dir() + "/bodies.csv"));
  if (fail) ADD_FAILURE() << "this test fails on purpose (SimNodeFixture.LogFoldersGo...)";
}
TEST(SimNodeFixture, DISABLED_PassingCase) { RunShortNode(false); }
TEST(SimNodeFixture, DISABLED_FailingCase) { RunShortNode(true); }

struct CaseRun {
  int exit_code = -1;
  std::string output, log_dir, log_file;
};

CaseRun RunCase(const std::string& name) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string command = "'" + self + "' --gtest_also_run_disabled_tests --gtest_filter=" +
                              "SimNodeFixture.DISABLED_" + name + " 2>&1";
  CaseRun run;
  std::FILE* out = ::popen(command.c_str(), "r");
  if (out == nullptr) return run;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, out) != nullptr) {
    const std::string line = buffer;
    run.output += line;
    if (line.rfind("log_dir ", 0) == 0) run.log_dir = line.substr(8, line.size() - 9);
    if (line.rfind("log_file ", 0) == 0) run.log_file = line.substr(9, line.size() - 10);
  }
  const int status = ::pclose(out);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

TEST(SimNodeFixture, LogFoldersGoAfterAPassingTestAndStayAfterAFailingOne) {
  const CaseRun passing = RunCase("PassingCase");
  EXPECT_EQ(passing.exit_code, 0) << passing.output;
  ASSERT_FALSE(passing.log_dir.empty()) << passing.output;
  EXPECT_FALSE(std::filesystem::exists(passing.log_dir)) << passing.output;
  ASSERT_FALSE(passing.log_file.empty()) << passing.output;
  EXPECT_FALSE(std::filesystem::exists(passing.log_file)) << passing.output;

  const CaseRun failing = RunCase("FailingCase");
  EXPECT_EQ(failing.exit_code, 1) << failing.output;
  ASSERT_FALSE(failing.log_dir.empty()) << failing.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(failing.log_dir + "/csv/bodies.csv"))
      << failing.output;
  EXPECT_NE(
      failing.output.find("[towsim] the logs of the failed test are kept in " + failing.log_dir),
      std::string::npos)
      << failing.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(failing.log_file)) << failing.output;
  std::filesystem::remove_all(failing.log_dir);
  std::filesystem::remove(failing.log_file);
  std::filesystem::remove(failing.log_file.substr(0, failing.log_file.size() - 4) + ".err");
}

// domain 171: the node exits 2 before scene_info; the exception carries its message
TEST(SimNodeFixture, ABadSceneThrowsWithTheNodesMessage) {
  SimNodeOptions o;
  o.scene = "steady_tow";
  o.domain = 171;
  o.set = {"cable.elements=0"};
  try {
    SimNode node(o);
    FAIL() << "the node started";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("sim_node exited (code 2) before scene_info"), std::string::npos) << what;
    EXPECT_NE(what.find("cable.elements = 0"), std::string::npos) << what;
  }
}

// automatic ids: two nodes at once on different domains, each seeing only its own node
TEST(SimNodeFixture, ParallelNodesGetDistinctDomains) {
  SimNodeOptions o;
  o.scene = "steady_tow";
  o.duration = 0.5;
  SimNode a(o), b(o);
  EXPECT_NE(a.domain(), b.domain());
  for (const SimNode* n : {&a, &b}) {
    EXPECT_GE(n->domain(), kFirstAutoDomain);
    EXPECT_LE(n->domain(), kLastAutoDomain);
  }
  const NodeResult ra = a.Wait(), rb = b.Wait();
  EXPECT_EQ(ra.exit_code, 0) << a.log();
  EXPECT_EQ(rb.exit_code, 0) << b.log();
  // 10 steps each: had they shared a domain, each fixture would hold both nodes' statuses
  for (const SimNode* n : {&a, &b}) {
    const std::vector<StatusSample> s = n->status_history();
    ASSERT_FALSE(s.empty());
    EXPECT_TRUE(s.back().finished());
    EXPECT_EQ(s.back().step, 10u);
    for (const StatusSample& x : s) EXPECT_EQ(x.run_id, s.front().run_id);
  }
}

// realtime mode (automatic id): 2 s of simulated time at --rate 10 is 0.2 s of wall time
TEST(SimNodeFixture, RealtimeModeRunsPaced) {
  SimNodeOptions o;
  o.scene = "steady_tow";
  o.mode = "realtime";
  o.rate = 10.0;
  o.duration = 2.0;
  SimNode node(o);
  const NodeResult end = node.Wait();
  EXPECT_EQ(end.exit_code, 0) << node.log();
  EXPECT_EQ(end.summary.rfind("sim_node: steady_tow: realtime, 40 steps, 2 s simulated", 0), 0u)
      << end.summary;
  const std::optional<StatusSample> last = node.status();
  ASSERT_TRUE(last.has_value());
  EXPECT_TRUE(last->finished());
  EXPECT_EQ(last->mode, "realtime");
}

// automatic ids: the fixture passes --fail-on-failsafe, so a controller that stalls longer than
// the lockstep timeout (here 1 s at step 5, limit 0.3 s) fails the run: exit 5 after step 5,
// the final status FAILED naming the body and the step. With fail_on_failsafe = false the node
// runs on to the end (exit 0), the body in failsafe for one step.
TEST(SimNodeFixture, AStalledControllerFailsTheRunUnlessTurnedOff) {
  for (const bool fail : {true, false}) {
    SCOPED_TRACE(fail ? "fail_on_failsafe" : "not fail_on_failsafe");
    SimNodeOptions o;
    o.scene = "case1_forward";  // two commanded vehicles, 0.05 s steps
    o.duration = 1.0;
    o.lockstep_timeout = 0.3;
    o.fail_on_failsafe = fail;
    SimNode node(o);
    controllers::ClientOptions fish;
    fish.body = "towfish";
    InProcessController fish_ctl(
        node, fish, [](const controllers::BodyState&) { return controllers::Actuation{}; });
    controllers::ClientOptions tow;
    tow.body = "tow_vehicle";
    bool stalled = false;  // the law runs on the controller's thread only
    InProcessController tow_ctl(node, tow, [&stalled](const controllers::BodyState& s) {
      if (s.step == 5 && !stalled) {
        stalled = true;
        std::this_thread::sleep_for(std::chrono::seconds(1));
      }
      return controllers::Actuation{};
    });
    const NodeResult end = node.Wait();
    const std::optional<StatusSample> last = node.status();
    ASSERT_TRUE(last.has_value());
    if (fail) {
      EXPECT_EQ(end.exit_code, 5) << node.log();
      EXPECT_EQ(end.summary.rfind("sim_node: case1_forward: lockstep, 6 steps", 0), 0u)
          << end.summary;
      EXPECT_TRUE(last->failed());
      EXPECT_NE(last->message.find("lockstep timeout: body tow_vehicle at step 5"),
                std::string::npos)
          << last->message;
    } else {
      EXPECT_EQ(end.exit_code, 0) << node.log();
      EXPECT_TRUE(last->finished());
      EXPECT_EQ(last->step, 20u);
    }
    EXPECT_NE(end.summary.find("failsafes 1,"), std::string::npos) << end.summary;
    EXPECT_NE(end.summary.find("lockstep timeouts 1,"), std::string::npos) << end.summary;
    fish_ctl.Join();
    tow_ctl.Join();
  }
}

}  // namespace
}  // namespace towsim::testing
