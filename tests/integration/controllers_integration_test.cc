// The controllers as processes over loopback DDS: sim_node in lockstep, the
// manoeuvre runner commanding the tow vehicle and the towfish depth controller commanding the
// towfish, three separate processes. Domains 61, 62 (tests/integration/README.md: 61-69 are
// the controllers' tests).

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "testing/process.h"

namespace towsim::testing {
namespace {

const std::string kSource = TOWSIM_SOURCE_DIR;
const std::string kCase2 = kSource + "/config/scenes/case2_uturn.yaml";
constexpr double kProcessTimeout = 60.0;  // [s] a run that takes longer has hung
constexpr double kDuration = 120.0;       // [s] simulated: the turn (55..~71 s) and after
constexpr double kTurnStart = 55.0;       // [s]
constexpr double kSettled = 60.0;         // [s] the fish has risen from its start at rest
constexpr double kCommandedDepth = 25.0;  // [m]

struct Sample {
  double t = 0, x = 0, y = 0, z = 0, yaw = 0;
};

struct UTurnRun {
  std::vector<Sample> tow, fish;  // from the node's bodies.csv (output rate)
  std::string runner_out, depth_out;
  std::string bodies_csv;  // the node's bodies.csv, verbatim
};

// the offline sim_node's bodies.csv of `scene` (its script) over `duration`
std::string OfflineBodiesCsv(const std::string& scene, double duration, const std::string& tag) {
  const std::string dir = LogPrefix(tag + "_offline_csv");
  Process offline({TOWSIM_SIM_NODE, "--scene", scene, "--mode", "offline", "--duration",
                   std::to_string(duration), "--csv", dir},
                  LogPrefix(tag + "_offline"));
  EXPECT_TRUE(offline.Wait(kProcessTimeout));
  EXPECT_EQ(offline.exit_code(), 0) << offline.err();
  return ReadFile(dir + "/bodies.csv");
}

// sim_node (lockstep, no script) + maneuver_runner + towfish_depth (--hold or --depth D)
UTurnRun RunUTurn(int domain, bool hold) {
  const std::string tag = hold ? "hold" : "depth";
  const std::string csv = LogPrefix(tag + "_csv");
  std::vector<std::string> depth_argv = {TOWSIM_TOWFISH_DEPTH, "--body", "towfish",
                                         "--domain", std::to_string(domain)};
  if (hold) {
    depth_argv.push_back("--hold");
  } else {
    depth_argv.insert(depth_argv.end(), {"--depth", std::to_string(kCommandedDepth)});
  }
  // the controllers first (they wait for the node's scene_info), then the node
  Process runner({TOWSIM_MANEUVER_RUNNER, "--body", "tow_vehicle", "--thrust", "4165",
                  "--rudder-deg", "20", "--start", "55", "--until-yaw-deg", "170", "--domain",
                  std::to_string(domain)},
                 LogPrefix(tag + "_runner"));
  Process depth(depth_argv, LogPrefix(tag + "_towfish_depth"));
  Process node({TOWSIM_SIM_NODE, "--scene", kCase2, "--mode", "lockstep", "--duration",
                std::to_string(kDuration), "--domain", std::to_string(domain), "--set",
                "script=[]", "--csv", csv},
               LogPrefix(tag + "_node"));
  UTurnRun run;
  EXPECT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_TRUE(runner.Wait(10.0)) << runner.command_line();
  EXPECT_EQ(runner.exit_code(), 0) << runner.err();
  EXPECT_TRUE(depth.Wait(10.0)) << depth.command_line();
  EXPECT_EQ(depth.exit_code(), 0) << depth.err();
  // every commanded body followed its controller: no failsafe, no lockstep timeout
  EXPECT_NE(node.out().find("failsafes 0,"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("lockstep timeouts 0,"), std::string::npos) << node.out();
  run.runner_out = runner.out();
  run.depth_out = depth.out();

  run.bodies_csv = ReadFile(csv + "/bodies.csv");
  std::stringstream in(run.bodies_csv);
  std::string row;
  std::getline(in, row);  // t,body,x,y,z,roll,pitch,yaw,...
  while (std::getline(in, row)) {
    std::stringstream s(row);
    std::string field;
    std::vector<std::string> f;
    while (std::getline(s, field, ',')) f.push_back(field);
    if (f.size() < 8) continue;
    Sample x;
    x.t = std::stod(f[0]);
    x.x = std::stod(f[2]);
    x.y = std::stod(f[3]);
    x.z = std::stod(f[4]);
    x.yaw = std::stod(f[7]);
    (f[1] == "tow_vehicle" ? run.tow : run.fish).push_back(x);
  }
  return run;
}

struct Excursion {
  double min = 1e300, max = -1e300, worst_offset = 0;  // over the turn and after [m]
  double range() const { return max - min; }
};

Excursion DepthExcursion(const std::vector<Sample>& fish, double from = kTurnStart) {
  Excursion e;
  for (const Sample& s : fish) {
    if (s.t < from - 1e-9) continue;
    e.min = std::min(e.min, s.z);
    e.max = std::max(e.max, s.z);
    e.worst_offset = std::max(e.worst_offset, std::abs(s.z - kCommandedDepth));
  }
  return e;
}

TEST(Controllers, UTurnCompletesAndTheDepthControllerHalvesTheTowfishExcursion) {
  const UTurnRun controlled = RunUTurn(61, false);
  const UTurnRun reference = RunUTurn(62, true);
  if (HasFailure()) return;

  for (const UTurnRun* run : {&controlled, &reference}) {
    ASSERT_FALSE(run->tow.empty());
    EXPECT_NEAR(run->tow.back().t, kDuration, 1e-6);  // the run completed
    double yaw_max = -1e9;
    for (const Sample& s : run->tow) yaw_max = std::max(yaw_max, s.yaw * 180.0 / M_PI);
    // the U-turn: the yaw passes 170 deg (and wraps past 180 deg to the reciprocal course)
    EXPECT_GE(yaw_max, 170.0 - 1e-9) << run->runner_out;
    EXPECT_GT(std::abs(run->tow.back().yaw) * 180.0 / M_PI, 165.0);
    EXPECT_NE(run->runner_out.find("turn ended at t = 7"), std::string::npos) << run->runner_out;
  }
  const Excursion with = DepthExcursion(controlled.fish);
  const Excursion without = DepthExcursion(reference.fish);
  // the turn alone, once the fish has risen from its start at rest (200 m below) and settled
  const Excursion turn_with = DepthExcursion(controlled.fish, kSettled);
  const Excursion turn_without = DepthExcursion(reference.fish, kSettled);
  std::printf("towfish depth t >= %g s: %.2f..%.2f m with the controller, %.2f..%.2f m "
              "without (range ratio %.3f)\n",
              kSettled, turn_with.min, turn_with.max, turn_without.min, turn_without.max,
              turn_with.range() / turn_without.range());
  EXPECT_LT(turn_with.range(), 0.5 * turn_without.range());
  std::printf("towfish depth t >= %g s: with the controller (commanded %g m) %.2f..%.2f m "
              "(range %.2f m, worst offset %.2f m); without %.2f..%.2f m (range %.2f m, worst "
              "offset %.2f m); range ratio %.3f\n",
              kTurnStart, kCommandedDepth, with.min, with.max, with.range(), with.worst_offset,
              without.min, without.max, without.range(), without.worst_offset,
              with.range() / without.range());
  EXPECT_LT(with.range(), 0.5 * without.range());
  EXPECT_LT(with.worst_offset, 0.5 * without.worst_offset);

  // the runner plays Case 2 exactly as the scene's script does: with the towfish's fins
  // centred, the lockstep run equals the offline one (bodies.csv byte for byte, 9 digits)
  const std::string offline = OfflineBodiesCsv(kCase2, kDuration, "case2");
  EXPECT_FALSE(offline.empty());
  EXPECT_TRUE(reference.bodies_csv == offline) << "lockstep and offline Case 2 differ";
}

// domain 63: Case 1 (constant thrust) by the runner in lockstep equals offline Case 1
TEST(Controllers, Case1ByTheRunnerInLockstepEqualsOffline) {
  const std::string case1 = kSource + "/config/scenes/case1_forward.yaml";
  const double duration = 60.0;
  const std::string csv = LogPrefix("lockstep_csv");
  Process runner({TOWSIM_MANEUVER_RUNNER, "--thrust", "4165", "--rudder-deg", "0", "--domain",
                  "63"},
                 LogPrefix("runner"));
  Process fish({TOWSIM_TOWFISH_DEPTH, "--hold", "--domain", "63"}, LogPrefix("towfish_depth"));
  Process node({TOWSIM_SIM_NODE, "--scene", case1, "--mode", "lockstep", "--duration",
                std::to_string(duration), "--domain", "63", "--set", "script=[]", "--csv", csv},
               LogPrefix("node"));
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  ASSERT_TRUE(runner.Wait(10.0));
  EXPECT_EQ(runner.exit_code(), 0) << runner.err();
  ASSERT_TRUE(fish.Wait(10.0));
  EXPECT_EQ(fish.exit_code(), 0) << fish.err();
  const std::string lockstep = ReadFile(csv + "/bodies.csv");
  const std::string offline = OfflineBodiesCsv(case1, duration, "case1");
  EXPECT_FALSE(lockstep.empty());
  EXPECT_TRUE(lockstep == offline) << "lockstep and offline Case 1 differ";
}

TEST(Controllers, WithoutCycloneDdsUriTheyExitWithAClearMessage) {
  for (const std::string exe : {TOWSIM_MANEUVER_RUNNER, TOWSIM_TOWFISH_DEPTH}) {
    Process p({exe, "--domain", "69", "--depth", "10"}, LogPrefix("no_uri"), {"CYCLONEDDS_URI="});
    ASSERT_TRUE(p.Wait(10.0));
    EXPECT_EQ(p.exit_code(), exe == TOWSIM_MANEUVER_RUNNER ? 2 : 1) << p.err();
    if (exe == TOWSIM_TOWFISH_DEPTH) {
      EXPECT_NE(p.err().find("CYCLONEDDS_URI is not set"), std::string::npos) << p.err();
    }
  }
  Process p({TOWSIM_MANEUVER_RUNNER, "--domain", "69"}, LogPrefix("no_uri_runner"),
            {"CYCLONEDDS_URI="});
  ASSERT_TRUE(p.Wait(10.0));
  EXPECT_EQ(p.exit_code(), 1);
  EXPECT_NE(p.err().find("CYCLONEDDS_URI is not set"), std::string::npos) << p.err();
}

TEST(Controllers, BadFlagsExit2) {
  Process p({TOWSIM_MANEUVER_RUNNER, "--rudder-deg", "abc"}, LogPrefix("bad"));
  ASSERT_TRUE(p.Wait(10.0));
  EXPECT_EQ(p.exit_code(), 2);
  Process q({TOWSIM_TOWFISH_DEPTH, "--domain", "69"}, LogPrefix("nodepth"));
  ASSERT_TRUE(q.Wait(10.0));
  EXPECT_EQ(q.exit_code(), 2);  // --depth is required
  EXPECT_NE(q.err().find("--depth"), std::string::npos);
}

TEST(Controllers, SigtermEndsAControllerWaitingForANode) {
  Process p({TOWSIM_TOWFISH_DEPTH, "--depth", "10", "--domain", "64"}, LogPrefix("sigterm"));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  p.Signal(SIGTERM);
  ASSERT_TRUE(p.Wait(5.0));
  EXPECT_EQ(p.exit_code(), 0) << p.err();  // a clean exit, before any node showed up
}

}  // namespace
}  // namespace towsim::testing
