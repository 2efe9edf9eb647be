// The winch over DDS (docs/winch_dds.md) as processes over loopback: sim_node, the test
// controller (msgs/ only) sending WinchCommand on rt/<ns>/winch/command, the controllers
// (towfish_depth --winch, maneuver_runner --maneuver payout) and this test as a DDS participant.
// Domains 157-159, 163-168 and 191 (tests/integration/README.md).

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dds_observer.h"
#include "testing/csv_file.h"
#include "testing/dds_domain.h"
#include "testing/process.h"
#include "towed_cable_steady.h"
#include "towsim_msgs.h"

namespace towsim::testing {
namespace {

const std::string kSource = TOWSIM_SOURCE_DIR;
// a driven tow point, a sphere, the drum between 40 m and 100 m at 1 m/s (its script: pay
// out at 1 m/s from 1 s, drive to 70 m from 6 s, reel in at 0.5 m/s from 13 s)
const std::string kDriven = kSource + "/tests/integration/scenes/winch_driven.yaml";
// the winch commands of that script, for the test controller
const std::vector<std::string> kDrivenWinch = {"1=speed:1", "6=length:70", "13=speed:-0.5"};
constexpr double kProcessTimeout = 120.0;  // [s] of wall time: a run that takes longer hung
constexpr double kH = 0.05;                // the scenes' step [s]

std::vector<std::string> Controller(int domain, const std::vector<std::string>& winch,
                                    std::vector<std::string> extra = {}) {
  std::vector<std::string> argv = {TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(domain)};
  for (const std::string& w : winch) argv.insert(argv.end(), {"--winch", w});
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

class WinchDdsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // loopback only, never Cyclone's default; the children inherit it
    setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
  }
};

// a lockstep run of the driven scene (no script) with the test controller sending `winch`;
// returns the CSV directory
std::string LockstepRun(int domain, double duration, const std::vector<std::string>& winch,
                        std::vector<std::string> controller_extra = {},
                        std::string* node_out = nullptr) {
  const std::string dir = LogPrefix("d" + std::to_string(domain) + "_csv");
  Process node(
      SimNodeArgs(TOWSIM_SIM_NODE, kDriven, "lockstep", domain,
                  {"--duration", std::to_string(duration), "--set", "script=[]", "--csv", dir}),
      LogPrefix("d" + std::to_string(domain) + "_node"));
  Process controller(Controller(domain, winch, controller_extra),
                     LogPrefix("d" + std::to_string(domain) + "_controller"));
  EXPECT_TRUE(controller.Wait(kProcessTimeout)) << controller.command_line();
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  EXPECT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  if (node_out != nullptr) *node_out = node.out();
  return dir;
}

// winch.csv: t, paid_out_length, winch_speed, drum_tension, node_count
// (appended) command_mode, command_value, failsafe: the command in force during the step
struct WinchRow {
  double t = 0, length = 0, speed = 0, tension = 0;
  int nodes = 0;
  int mode = 0;
  double value = 0;
  int failsafe = 0;
};
std::vector<WinchRow> WinchRows(const std::string& dir, const std::string& file = "winch.csv") {
  const CsvTable csv = ReadCsv(dir + "/" + file);
  EXPECT_EQ(JoinCsvRow(csv.header),
            "t,paid_out_length,winch_speed,drum_tension,node_count,command_mode,command_value,"
            "failsafe");
  std::vector<WinchRow> rows;
  for (const auto& f : csv.rows) {
    if (f.size() != 8) {
      ADD_FAILURE() << file << " row " << JoinCsvRow(f);
      continue;
    }
    rows.push_back({std::stod(f[0]), std::stod(f[1]), std::stod(f[2]), std::stod(f[3]),
                    std::stoi(f[4]), std::stoi(f[5]), std::stod(f[6]), std::stoi(f[7])});
  }
  return rows;
}

// domains 157, 158: the same winch commands over DDS, twice: byte-identical files, and the
// winch did move (payout, a length target, reel-in; the node count changed)
TEST_F(WinchDdsTest, LockstepRunsWithTheWinchMovingAreBitIdentical) {
  constexpr double kDuration = 16.0;
  const std::string a = LockstepRun(157, kDuration, kDrivenWinch);
  const std::string b = LockstepRun(158, kDuration, kDrivenWinch);
  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv", "winch.csv"}) {
    const std::string fa = ReadFile(a + "/" + file), fb = ReadFile(b + "/" + file);
    EXPECT_FALSE(fa.empty()) << file;
    EXPECT_TRUE(fa == fb) << file << " differs between two lockstep runs (" << a << ", " << b
                          << ")";
  }
  const std::vector<WinchRow> rows = WinchRows(a);
  ASSERT_EQ(rows.size(), static_cast<size_t>(std::lround(kDuration * 10)) + 1);
  double max_length = 0.0, max_speed = 0.0, min_speed = 0.0;
  int min_nodes = 1 << 30, max_nodes = 0;
  for (const WinchRow& r : rows) {
    max_length = std::max(max_length, r.length);
    max_speed = std::max(max_speed, r.speed);
    min_speed = std::min(min_speed, r.speed);
    min_nodes = std::min(min_nodes, r.nodes);
    max_nodes = std::max(max_nodes, r.nodes);
  }
  // paid out to the 70 m target (1 m/s from 1 s, 0.5 m/s^2: 64 m at 6 s, then the length
  // command drives on to 70 m and stops there), then reeled in at 0.5 m/s: the drum moved
  constexpr double kLengthTol = 1e-6;  // [m] the drum stops exactly at a length target
  constexpr double kSpeedTol = 1e-12;  // [m/s] the speed limit, to rounding
  EXPECT_NEAR(max_length, 70.0, kLengthTol);
  EXPECT_NEAR(max_speed, 1.0, kSpeedTol);
  EXPECT_NEAR(min_speed, -0.5, kSpeedTol);
  EXPECT_GT(max_nodes, min_nodes);  // an element split (10 m elements from 60 m to 70 m)
}

// domain 159: the scene's script offline, and the same commands over DDS in lockstep (the node
// without a script): the same files to the last digit (status.csv differs in wall_us only)
TEST_F(WinchDdsTest, LockstepOverDdsEqualsTheOfflineScript) {
  constexpr double kDuration = 16.0;
  const std::string dds = LockstepRun(159, kDuration, kDrivenWinch);
  const std::string offline = LogPrefix("offline_csv");
  Process node({TOWSIM_SIM_NODE, "--scene", kDriven, "--mode", "offline", "--duration",
                std::to_string(kDuration), "--csv", offline},
               LogPrefix("offline"));
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv", "winch.csv"}) {
    const std::string fo = ReadFile(offline + "/" + file), fd = ReadFile(dds + "/" + file);
    EXPECT_FALSE(fo.empty()) << file;
    EXPECT_TRUE(fo == fd) << file << " differs: offline " << offline << ", lockstep " << dds;
  }
  // the script moved the drum (so that the equality says something)
  const std::vector<WinchRow> rows = WinchRows(offline);
  ASSERT_FALSE(rows.empty());
  EXPECT_GT(
      std::max_element(rows.begin(), rows.end(),
                       [](const WinchRow& x, const WinchRow& y) { return x.length < y.length; })
          ->length,
      69.0);
}

// domain 167: sim_node --winch script in lockstep with a real controller for the towing vehicle
// (the test controller): the winch follows the scene's script, is neither waited for nor
// failsafed (the controller answers it for 5 s only, then never again), and the commands it
// did send are rejected and counted; the files equal the offline run of the same script to the
// last digit
TEST_F(WinchDdsTest, LockstepWithTheWinchScriptedEqualsTheOfflineScript) {
  const std::string scene = kSource + "/config/scenes/winch_tow.yaml";
  constexpr double kDuration = 15.0, kWinchUntil = 5.0;
  // the towing vehicle's thrust (the controller sends the same), pay out at 1 m/s from 1 s,
  // drive to 157.5 m from 6 s (the drum's 0.2 m/s^2: at 1 m/s and 152.5 m at 6 s, 2.5 s on at
  // 1 m/s, 5 s braking: there at 13.5 s)
  const std::string script =
      "script=[{at: 0, body: tow_vehicle, thrust: 1050}, {at: 1, winch_speed: 1.0}, "
      "{at: 6, winch_length: 157.5}]";
  const std::string dds = LogPrefix("lockstep_csv"), offline = LogPrefix("offline_csv");
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, scene, "lockstep", 167,
                           {"--duration", std::to_string(kDuration), "--set", script, "--winch",
                            "script", "--wait-for-controllers", "--csv", dds}),
               LogPrefix("node"));
  Process controller(Controller(167, {},
                                {"--command", "tow_vehicle@0=1050,0,0", "--winch-until",
                                 std::to_string(kWinchUntil)}),
                     LogPrefix("controller"));
  Process reference({TOWSIM_SIM_NODE, "--scene", scene, "--mode", "offline", "--duration",
                     std::to_string(kDuration), "--set", script, "--csv", offline},
                    LogPrefix("offline"));
  ASSERT_TRUE(controller.Wait(kProcessTimeout)) << controller.command_line();
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  ASSERT_TRUE(reference.Wait(kProcessTimeout));
  ASSERT_EQ(reference.exit_code(), 0) << reference.err();
  // 300 steps: the vehicle's 300 commands, and the winch's answers of steps 0 .. 99 (t < 5 s),
  // every one taken rejected (the winch's reader keeps the newest sample only and the node does
  // not wait for it, so a few are replaced before they are taken); no lockstep timeout (the
  // winch was not waited for), no failsafe
  const long steps = std::lround(kDuration / kH), winch_steps = std::lround(kWinchUntil / kH);
  unsigned long long received = 0, rejected = 0, clamped = 0;
  const size_t at = node.out().find("commands ");
  ASSERT_NE(at, std::string::npos) << node.out();
  ASSERT_EQ(std::sscanf(node.out().c_str() + at, "commands %llu (rejected %llu, clamped %llu)",
                        &received, &rejected, &clamped),
            3)
      << node.out();
  EXPECT_EQ(received - rejected, static_cast<unsigned long long>(steps)) << node.out();
  EXPECT_GT(rejected, 0u) << node.out();
  EXPECT_LE(rejected, static_cast<unsigned long long>(winch_steps)) << node.out();
  EXPECT_EQ(clamped, 0u) << node.out();
  EXPECT_NE(node.out().find("failsafes 0"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("lockstep timeouts 0"), std::string::npos) << node.out();
  EXPECT_NE(node.err().find("winch: command rejected (the winch follows the scene's script: "
                            "--winch script)"),
            std::string::npos)
      << node.err();
  // --wait-for-controllers waits for the towing vehicle only (if it had to wait at all)
  EXPECT_EQ(node.err().find("winch (rt/towsim/winch/command)"), std::string::npos) << node.err();
  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv", "winch.csv"}) {
    const std::string fo = ReadFile(offline + "/" + file), fd = ReadFile(dds + "/" + file);
    EXPECT_FALSE(fo.empty()) << file;
    EXPECT_TRUE(fo == fd) << file << " differs: offline " << offline << ", lockstep " << dds;
  }
  // the script moved the drum to its length target (so that the equality says something)
  const std::vector<WinchRow> rows = WinchRows(dds);
  ASSERT_EQ(rows.size(), static_cast<size_t>(steps / 2) + 1);  // output_rate 10 Hz
  constexpr double kLengthTol = 1e-6;  // [m] the drum stops exactly at a length target
  EXPECT_NEAR(rows.back().length, 157.5, kLengthTol);
  EXPECT_NEAR(rows.front().length, 150.0, kLengthTol);
}

// domain 168: --wait-for-controllers in lockstep on a scene whose only commanded part is the
// winch: the first step waits for the winch's controller, the log line names it and its
// topic, the status says waiting at step 0; the controller starts later, the run then goes
// through without a timeout or failsafe
TEST_F(WinchDdsTest, WaitForControllersWaitsForTheWinchInLockstep) {
  constexpr double kDuration = 2.0, kControllerLate = 1.0;  // [s]
  Observer watch(168);
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, kDriven, "lockstep", 168,
                           {"--duration", std::to_string(kDuration), "--set", "script=[]",
                            "--wait-for-controllers"}),
               LogPrefix("node"));
  constexpr uint8_t kWaitingState = towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
  Status s;
  ASSERT_TRUE(watch.WaitFor([](const Status& x) { return x.state == kWaitingState; }, &s));
  EXPECT_EQ(s.step, 0u);
  const std::string line =
      "sim_node: --wait-for-controllers: waiting for the first command of winch "
      "(rt/towsim/winch/command)";
  for (int i = 0; i < 100 && node.err().find(line) == std::string::npos; ++i) usleep(20000);
  EXPECT_NE(node.err().find(line), std::string::npos) << node.err();
  usleep(static_cast<useconds_t>(kControllerLate * 1e6));
  EXPECT_EQ(watch.statuses().back().step, 0u);  // still before the first step
  Process controller(Controller(168, {"0=speed:1"}), LogPrefix("controller"));
  ASSERT_TRUE(controller.Wait(kProcessTimeout)) << controller.command_line();
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  const long steps = std::lround(kDuration / kH);
  EXPECT_NE(node.out().find(std::to_string(steps) + " steps"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("failsafes 0"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("lockstep timeouts 0"), std::string::npos) << node.out();
}

constexpr uint8_t kSpeed = towsim_msgs_msg_dds__WinchCommand_Constants_SPEED;
constexpr uint8_t kHealthFailsafe = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE;
constexpr uint8_t kStopped = towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;

// domain 163: NaN and an unknown mode rejected, a speed beyond max_speed clamped, both counted
// in SimStatus with the vehicles' commands; no command for command_timeout: the winch's
// failsafe (realtime, where the node does not wait for the winch)
TEST_F(WinchDdsTest, BadWinchCommandsAreRejectedClampedCountedAndSilenceMeansFailsafe) {
  Observer watch(163);
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, kDriven, "realtime", 163,
                           {"--duration", "600", "--set", "script=[]"}),
               LogPrefix("node"));
  Status s;
  ASSERT_TRUE(watch.WaitFor([](const Status& x) { return x.step >= 1; }, &s));
  watch.WinchCommand(s.step, kSpeed, std::numeric_limits<double>::quiet_NaN());
  ASSERT_TRUE(watch.WaitFor([](const Status& x) { return x.commands_rejected == 1; }, &s));
  EXPECT_NE(s.message.find("winch: command rejected (speed is NaN)"), std::string::npos)
      << s.message;
  EXPECT_EQ(s.health, 0);  // a rejected command does not arm the timeout
  watch.WinchCommand(s.step, 9, 0.5);
  ASSERT_TRUE(watch.WaitFor([](const Status& x) { return x.commands_rejected == 2; }, &s));
  EXPECT_NE(s.message.find("mode 9 is neither SPEED (0) nor LENGTH (1)"), std::string::npos)
      << s.message;
  watch.WinchCommand(s.step, kSpeed, 100.0);  // beyond max_speed 1 m/s
  ASSERT_TRUE(watch.WaitFor([](const Status& x) { return x.commands_clamped == 1; }, &s));
  const double commanded_at = s.t;
  EXPECT_EQ(s.commands_received, 3u);
  EXPECT_NE(s.message.find("winch speed 100 clamped to the winch's limits [-1, 1]"),
            std::string::npos)
      << s.message;
  // silence: failsafe after command_timeout (0.5 s) of simulation time
  Status f;
  ASSERT_TRUE(watch.WaitFor([](const Status& x) { return x.health == kHealthFailsafe; }, &f));
  EXPECT_EQ(f.failsafe_bodies, std::vector<std::string>{"winch"});
  EXPECT_NEAR(f.t - commanded_at, 0.5, kH + 1e-9);  // within a step
  EXPECT_NE(f.message.find("winch: failsafe (no command for"), std::string::npos) << f.message;
  node.Signal(SIGINT);
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_TRUE(watch.WaitFor([](const Status& x) { return x.state == kStopped; }, nullptr));
  EXPECT_NE(node.out().find("commands 3 (rejected 2, clamped 1)"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("failsafes 1"), std::string::npos) << node.out();
}

// domain 164: the winch's controller stops answering at 4 s while the drum pays out at 1 m/s:
// after the lockstep timeout the winch is in failsafe, the drum brakes at max_acceleration to
// speed 0 and holds its length to the end of the run
TEST_F(WinchDdsTest, LockstepFailsafeHoldsTheWinchAtZeroSpeed) {
  constexpr double kDuration = 10.0, kSilentFrom = 4.0;
  constexpr double kBrake = 1.0 / 0.5;  // max_speed / max_acceleration [s] to stop
  std::string out;
  const std::string dir = LockstepRun(164, kDuration, {"0=speed:1"},
                                      {"--winch-until", std::to_string(kSilentFrom)}, &out);
  EXPECT_NE(out.find("failsafes 1"), std::string::npos) << out;
  EXPECT_NE(out.find("lockstep timeouts 1"), std::string::npos) << out;
  const std::vector<WinchRow> rows = WinchRows(dir);
  ASSERT_EQ(rows.size(), static_cast<size_t>(std::lround(kDuration * 10)) + 1);
  constexpr double kSpeedTol = 1e-12;  // [m/s] the drum's speed, to rounding
  constexpr double kHeldTol = 1e-9;    // [m] a held length, to the CSV's 9 digits
  double held = -1.0;
  for (const WinchRow& r : rows) {
    if (r.t > 2.0 && r.t < kSilentFrom - 1e-9) {
      EXPECT_NEAR(r.speed, 1.0, kSpeedTol) << "t = " << r.t;
    }
    if (r.t < kSilentFrom + kBrake + kH - 1e-9) continue;
    EXPECT_NEAR(r.speed, 0.0, kSpeedTol) << "t = " << r.t;
    if (held < 0.0) held = r.length;
    EXPECT_NEAR(r.length, held, kHeldTol * held) << "t = " << r.t;
  }
  // it paid out before: 60 m + about 1 m/s over 4 s less the ramps
  EXPECT_GT(held, 62.0);
}

// towfish_depth's log: t z elevator target_depth winch_speed
struct DepthLogLine {
  double t = 0, z = 0, elevator = 0, target = 0, winch_speed = 0;
};
std::vector<DepthLogLine> ReadDepthLog(const std::string& path) {
  std::vector<DepthLogLine> lines;
  std::stringstream in(ReadFile(path));
  DepthLogLine l;
  while (in >> l.t >> l.z >> l.elevator >> l.target >> l.winch_speed) lines.push_back(l);
  return lines;
}

// domain 165: towfish_depth --winch takes the towfish from its steady 23.5 m (150 m paid out,
// about 2.9 m/s) to 35 m: the elevators do the fast part, the winch pays out until the
// elevators are back near neutral, within the drum's speed and acceleration limits. The towing
// vehicle's constant thrust comes from the manoeuvre runner (case1), as lockstep waits for
// every commanded body.
TEST_F(WinchDdsTest, TowfishDepthWinchModeReachesACommandedDepthWithinTheWinchsLimits) {
  const std::string scene = kSource + "/tests/integration/scenes/winch_towfish.yaml";
  constexpr double kDuration = 300.0, kTarget = 35.0;
  const std::string dir = LogPrefix("csv"), log = LogPrefix("depth.log");
  Process node(
      SimNodeArgs(TOWSIM_SIM_NODE, scene, "lockstep", 165,
                  {"--duration", std::to_string(kDuration), "--set", "script=[]", "--csv", dir}),
      LogPrefix("node"));
  Process tow({TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--thrust", "1050", "--start", "0",
               "--domain", "165"},
              LogPrefix("tow"));
  Process depth({TOWSIM_TOWFISH_DEPTH, "--depth", "35", "--winch", "--domain", "165", "--log", log},
                LogPrefix("depth"));
  ASSERT_TRUE(depth.Wait(kProcessTimeout)) << depth.command_line();
  EXPECT_EQ(depth.exit_code(), 0) << depth.err();
  ASSERT_TRUE(tow.Wait(kProcessTimeout));
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_NE(node.out().find("failsafes 0"), std::string::npos) << node.out();

  const std::vector<DepthLogLine> lines = ReadDepthLog(log);
  // one line per step answered, 0 .. N-1; the run's end state N (FINISHED, which no command
  // answers) is logged only when the controller takes it before the node's last status
  // leaves, a race of process exit, not of the control
  const size_t steps = static_cast<size_t>(std::lround(kDuration / kH));
  ASSERT_GE(lines.size(), steps);
  ASSERT_LE(lines.size(), steps + 1);
  EXPECT_GT(std::abs(lines.front().z - kTarget), 4.0);  // a real change of depth
  // the last 100 s: at the commanded depth, the elevators near neutral (the winch rests once
  // |deeper demand| < deadband / elevator_depth = 0.5 m / 25 m/rad = 0.02 rad; the integral of
  // the elevator loop approaches it from outside)
  constexpr double kDepthTol = 0.3;     // [m] the deadband plus the slow residual swing
  constexpr double kNeutralTol = 0.03;  // [rad] 1.5 x the winch's resting band
  for (const DepthLogLine& l : lines) {
    if (l.t < kDuration - 100.0) continue;
    EXPECT_NEAR(l.z, kTarget, kDepthTol) << "t = " << l.t;
    EXPECT_LT(std::abs(l.elevator), kNeutralTol) << "t = " << l.t;
  }
  // the drum did the slow part within its limits (scene: 1 m/s, 0.2 m/s^2, 100 m .. 300 m)
  const std::vector<WinchRow> rows = WinchRows(dir);
  ASSERT_FALSE(rows.empty());
  constexpr double kLimitTol = 1e-9;  // the drum's limits, to rounding and the CSV's digits
  double max_speed = 0.0, max_acceleration = 0.0;
  for (size_t i = 0; i < rows.size(); ++i) {
    max_speed = std::max(max_speed, std::abs(rows[i].speed));
    if (i > 0) {
      max_acceleration = std::max(max_acceleration, std::abs(rows[i].speed - rows[i - 1].speed) /
                                                        (rows[i].t - rows[i - 1].t));
    }
    EXPECT_GE(rows[i].length, 100.0);
    EXPECT_LE(rows[i].length, 300.0);
  }
  EXPECT_LE(max_speed, 1.0 + kLimitTol);
  EXPECT_LE(max_acceleration, 0.2 * (1.0 + 1e-6));
  EXPECT_GT(max_speed, 0.5);             // it did pay out, at a good fraction of its limit
  EXPECT_GT(rows.back().length, 180.0);  // 11.5 m deeper takes tens of metres more cable
  std::printf("towfish_depth --winch: z %.3f m, elevator %.4f rad, length %.3f m at t = %g s\n",
              lines.back().z, lines.back().elevator, rows.back().length, rows.back().t);
}

// "key: value" lines of a flat YAML results file
std::map<std::string, double> ReadSheet(const std::string& path) {
  std::map<std::string, double> m;
  std::stringstream in(ReadFile(path));
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(": ");
    if (colon == std::string::npos) continue;
    char* end = nullptr;
    const std::string value = line.substr(colon + 2);
    const double x = std::strtod(value.c_str(), &end);
    if (end != value.c_str()) m[line.substr(0, colon)] = x;
  }
  return m;
}

// the steady towed-cable solution (tests/reference/towed_cable_steady.h) of the winch_tow
// scene's cable and sphere at `length`, towed at `speed`: the sphere's depth below the tow point
double SteadyDepth(double length, double speed) {
  reference::TowedCableProblem p;  // Park & Kim's cable, the 416 kg sphere (the defaults)
  p.length = length;
  p.tow_velocity = Eigen::Vector3d(speed, 0.0, 0.0);
  return reference::SolveTowedCableSteady(p).depth;
}

// domain 166: the payout trial (150 m -> 250 m at 1 m/s towing at 3 m/s, hold 100 s, reel in)
// on config/scenes/winch_tow.yaml: the sheet's lengths are the trial's, and its depths at the
// end of the approach (150 m), of the hold (250 m) and of the run (150 m again) are the steady
// solution's at those lengths and the measured speed
TEST_F(WinchDdsTest, PayoutManoeuvreSheetAgreesWithTheSteadySolution) {
  const std::string scene = kSource + "/config/scenes/winch_tow.yaml";
  const std::string results = LogPrefix("sheet.yaml"), plot = LogPrefix("sheet.svg");
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, scene, "lockstep", 166, {"--duration", "450"}),
               LogPrefix("node"));
  Process runner({TOWSIM_MANEUVER_RUNNER, "--maneuver", "payout", "--domain", "166", "--results",
                  results, "--plot", plot},
                 LogPrefix("runner"));
  ASSERT_TRUE(runner.Wait(kProcessTimeout)) << runner.command_line();
  EXPECT_EQ(runner.exit_code(), 0) << runner.err();
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_NE(runner.out().find("payout 150 m -> 250 m at 1 m/s"), std::string::npos) << runner.out();
  EXPECT_NE(ReadFile(plot).find("<polyline"), std::string::npos);

  const std::map<std::string, double> sheet = ReadSheet(results);
  for (const char* key : {"approach_length", "hold_length", "final_length", "approach_depth",
                          "hold_depth", "final_depth", "hold_speed", "max_length"}) {
    ASSERT_EQ(sheet.count(key), 1u) << key << " missing from " << results;
  }
  // the lengths: exact stops at the length targets (the drum's length command)
  constexpr double kLengthTol = 1e-3;  // [m] the sheet's 6 decimals of the CSV-free length
  EXPECT_NEAR(sheet.at("approach_length"), 150.0, kLengthTol);
  EXPECT_NEAR(sheet.at("hold_length"), 250.0, kLengthTol);
  EXPECT_NEAR(sheet.at("max_length"), 250.0, kLengthTol);
  EXPECT_NEAR(sheet.at("final_length"), 150.0, kLengthTol);
  EXPECT_NEAR(sheet.at("hold_speed"), 3.0, 0.05);  // the speed hold

  // the depths against the steady solution: the drum sits 0.2 m below the vehicle's origin
  // (the scene's start.at); the hold's 100 s and the 50 s after the reel-in leave the sphere
  // still settling (the cable's slow mode, tens of seconds at 3 m/s), and the tow vehicle's
  // speed varies by a few mm/s: a few percent of the depth
  constexpr double kSteadyRelTol = 0.05;
  for (const char* phase : {"approach", "hold", "final"}) {
    const std::string p = phase;
    const double below = sheet.at(p + "_depth") - (sheet.at(p + "_tow_depth") + 0.2);
    const double steady = SteadyDepth(sheet.at(p + "_length"), sheet.at(p + "_speed"));
    EXPECT_NEAR(below, steady, kSteadyRelTol * steady) << phase;
    std::printf(
        "payout sheet, end of %s: length %.3f m, depth below the drum %.3f m, steady %.3f "
        "m (%.2f %%)\n",
        phase, sheet.at(p + "_length"), below, steady, 100.0 * (below / steady - 1.0));
  }
}

// domain 191: two winches (tests/integration/scenes/two_winches.yaml) in lockstep, each
// commanded by the test controller on its own rt/<ns>/<winch>/command and waited for under its
// own name; the node without a script. Each drum follows its commands: the files equal the
// offline run of the scene's script (the same commands) to the last digit, the command columns
// included (the arbiter's choice over DDS, the script's offline), and the drums end where the
// commands take them (port at its 70 m target, starboard paying out at 0.25 m/s)
TEST_F(WinchDdsTest, TwoWinchesCommandedByNameEachFollowTheirCommands) {
  const DomainLease lease(191);
  const int domain = lease.id();
  constexpr double kDuration = 20.0;
  const std::string scene = kSource + "/tests/integration/scenes/two_winches.yaml";
  const std::string dds = LogPrefix("d191_csv");
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, scene, "lockstep", domain,
                           {"--duration", std::to_string(kDuration), "--set", "script=[]",
                            "--wait-for-controllers", "--csv", dds}),
               LogPrefix("d191_node"));
  Process controller(
      Controller(domain, {"port_winch@1=speed:1", "starboard_winch@2=speed:-1",
                          "port_winch@6=length:70", "starboard_winch@10=speed:0.25"}),
      LogPrefix("d191_controller"));
  ASSERT_TRUE(controller.Wait(kProcessTimeout)) << controller.command_line();
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  // lockstep waited for both winches by name, and never timed out nor fell to failsafe
  EXPECT_NE(node.err().find("port_winch (rt/towsim/port_winch/command), starboard_winch "
                            "(rt/towsim/starboard_winch/command)"),
            std::string::npos)
      << node.err();
  EXPECT_NE(node.out().find("failsafes 0"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("lockstep timeouts 0"), std::string::npos) << node.out();

  const std::string offline = LogPrefix("two_winches_offline_csv");
  Process off({TOWSIM_SIM_NODE, "--scene", scene, "--mode", "offline", "--duration",
               std::to_string(kDuration), "--csv", offline},
              LogPrefix("two_winches_offline"));
  ASSERT_TRUE(off.Wait(kProcessTimeout));
  ASSERT_EQ(off.exit_code(), 0) << off.err();
  for (const char* file : {"bodies.csv", "port.csv", "starboard.csv", "forces.csv",
                           "port_winch.csv", "starboard_winch.csv"}) {
    const std::string fo = ReadFile(offline + "/" + file), fd = ReadFile(dds + "/" + file);
    EXPECT_FALSE(fo.empty()) << file;
    EXPECT_TRUE(fo == fd) << file << " differs: offline " << offline << ", lockstep " << dds;
  }
  EXPECT_FALSE(std::filesystem::exists(dds + "/winch.csv")) << "no winch.csv with two winches";
  // the drums where their commands take them (the analytic profiles of
  // tests/reference/winch_network_core_test.cc): port stopped at its 70 m target, starboard
  // 60 - 1 * 5 / 2 - 1 * 3 = 54.5 m at 10 s, then at +0.25 m/s after 6.25 s of braking at 0.2
  constexpr double kLengthTol = 1e-6;  // [m] the drum's kinematics, to rounding
  const std::vector<WinchRow> port = WinchRows(dds, "port_winch.csv");
  const std::vector<WinchRow> star = WinchRows(dds, "starboard_winch.csv");
  ASSERT_FALSE(port.empty());
  ASSERT_FALSE(star.empty());
  EXPECT_NEAR(port.back().length, 70.0, kLengthTol);
  EXPECT_EQ(port.back().mode, 1);
  EXPECT_EQ(port.back().value, 70.0);
  EXPECT_NEAR(star.back().length, 52.15625 + 0.25 * (kDuration - 16.25), kLengthTol);
  EXPECT_EQ(star.back().mode, 0);
  EXPECT_EQ(star.back().value, 0.25);
  for (const auto& row : star) {
    if (std::abs(row.t - 10.0) < 1e-9) EXPECT_NEAR(row.length, 54.5, kLengthTol);
    EXPECT_EQ(row.failsafe, 0);
  }
}

}  // namespace
}  // namespace towsim::testing
