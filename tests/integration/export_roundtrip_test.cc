// towsim_export: a run recorded by `sim_node --record` and exported with
// `towsim_export --csv` gives the node's own `--csv` files of the same run, byte for byte
// (same rows, every number equal to its 9 printed digits), with the publish rates of the scene
// set to the CSV output rate; forces.csv with the support reactions of cable ends held by fixed
// / driven points ("cable.start", from rt/<ns>/cable/start_force) and a network's
// per-attachment rows. --info lists the topics; a damaged recording exits 2 naming the offset.
// A sea scene's environment topic comes back as the node's environment.csv; the commands
// towsim_record captured come back as commands.csv; a network's cables as their <cable>.csv.
// The actuator_state topics come back as the node's actuators.csv, and as the actuators.csv of
// the same scene and script run offline.
// DDS domains 91, 92, 134, 188, 194, 195, 198 and 216, and one automatic (DomainLease).
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/cdr_messages.h"
#include "io/mcap_reader.h"
#include "testing/dds_domain.h"
#include "testing/process.h"

namespace {

using towsim::testing::Process;
using towsim::testing::ReadFile;
namespace fs = std::filesystem;

constexpr double kTimeout = 60.0;  // [s] per process; the runs take < 2 s

class ExportRoundTrip : public ::testing::Test {
 protected:
  ExportRoundTrip() {
    setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("towsim_export_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~ExportRoundTrip() override { fs::remove_all(dir_); }

  // runs `sim_node` in fast mode with --csv and --record, every topic at the output rate
  // (`scene` relative to the source tree, or absolute), `extra` flags after them
  void RecordRun(const std::string& scene, int domain, double duration,
                 const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {TOWSIM_SIM_NODE,
                                     "--scene",
                                     SceneFile(scene),
                                     "--mode",
                                     "fast",
                                     "--domain",
                                     std::to_string(domain),
                                     "--duration",
                                     std::to_string(duration),
                                     "--csv",
                                     (dir_ / "node").string(),
                                     "--record",
                                     (dir_ / "run.mcap").string(),
                                     "--set",
                                     "publish.odom=10",
                                     "--set",
                                     "publish.cable_force=10",
                                     "--set",
                                     "publish.cable_state=10",
                                     "--set",
                                     "publish.status=10",
                                     "--set",
                                     "publish.sensors=10"};
    args.insert(args.end(), extra.begin(), extra.end());
    Process node(args, (dir_ / "node").string());
    ASSERT_TRUE(node.Wait(kTimeout)) << node.command_line();
    ASSERT_EQ(node.exit_code(), 0) << node.err();
  }

  // the same scene with `sim_node --mode offline` (no DDS), its CSV files in dir_/offline
  void OfflineRun(const std::string& scene, double duration,
                  const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {TOWSIM_SIM_NODE, "--scene",    SceneFile(scene),
                                     "--mode",        "offline",    "--duration",
                                     std::to_string(duration), "--csv", (dir_ / "offline").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    Process node(args, (dir_ / "offline").string());
    ASSERT_TRUE(node.Wait(kTimeout)) << node.command_line();
    ASSERT_EQ(node.exit_code(), 0) << node.err();
  }

  static std::string SceneFile(const std::string& scene) {
    return scene.front() == '/' ? scene : std::string(TOWSIM_SOURCE_DIR) + "/" + scene;
  }

  Process Export(std::vector<std::string> args, const std::string& log) {
    args.insert(args.begin(), TOWSIM_EXPORT);
    return Process(args, (dir_ / log).string());
  }

  fs::path dir_;
};

std::vector<std::string> Lines(const std::string& path) {
  std::vector<std::string> out;
  std::istringstream in(ReadFile(path));
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// the first /towsim/<body>/actuator_state message of each stamp of a recording, by stamp [ns]
std::map<std::int64_t, towsim::io::cdr::ActuatorState> ActuatorStates(const std::string& mcap,
                                                                      const std::string& body) {
  const towsim::io::McapReader reader = towsim::io::McapReader::Open(mcap);
  std::map<std::int64_t, towsim::io::cdr::ActuatorState> states;
  reader.ForEachMessage([&](const towsim::io::McapMessage& m) {
    if (reader.channels().at(m.channel_id).topic != "/towsim/" + body + "/actuator_state") return;
    auto a = towsim::io::cdr::DecodeActuatorState(m.data.data(), m.data.size());
    const std::int64_t stamp =
        static_cast<std::int64_t>(a.header.stamp.sec) * 1'000'000'000 + a.header.stamp.nanosec;
    states.emplace(stamp, std::move(a));
  });
  return states;
}

// the `source` of those (towsim_msgs/ActuatorState SOURCE_*: 0 none, 1 script, 2 DDS,
// 3 failsafe)
std::map<std::int64_t, int> ActuatorSources(const std::string& mcap, const std::string& body) {
  std::map<std::int64_t, int> sources;
  for (const auto& [stamp, a] : ActuatorStates(mcap, body)) sources[stamp] = a.source;
  return sources;
}

void ExpectSameCsv(const fs::path& node, const fs::path& exported, std::size_t rows_per_file_min) {
  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv", "status.csv"}) {
    SCOPED_TRACE(file);
    const auto a = Lines((node / file).string());
    const auto b = Lines((exported / file).string());
    EXPECT_GE(a.size(), rows_per_file_min);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i], b[i]) << "first difference at line " << i + 1;
    }
  }
}

TEST_F(ExportRoundTrip, SteadyTowRecordedAndExportedEqualsTheNodesCsv) {
  RecordRun("config/scenes/steady_tow.yaml", 91, 20.0);
  Process exp = Export(
      {(dir_ / "run.mcap").string(), "--csv", (dir_ / "exported").string(), "--info"}, "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  // 20 s at 10 Hz: 201 row sets (t = 0 included)
  ExpectSameCsv(dir_ / "node", dir_ / "exported", 202);
  // the driven start's reaction (rt/towsim/cable/start_force) comes back: one row per row set
  const std::string forces = ReadFile((dir_ / "exported/forces.csv").string());
  std::size_t supports = 0;
  for (auto at = forces.find(",cable.start,"); at != std::string::npos;
       at = forces.find(",cable.start,", at + 1)) {
    ++supports;
  }
  EXPECT_EQ(supports, 201u);
  EXPECT_EQ(forces.find(",cable.end,"), std::string::npos);  // the towfish's end: a body's
  // --info: like ros2 bag info
  const std::string info = exp.out();
  EXPECT_NE(info.find("Storage id:        mcap"), std::string::npos) << info;
  EXPECT_NE(info.find("Topic: /towsim/towfish/odom | Type: nav_msgs/msg/Odometry | Count: 201 | "
                      "Serialization Format: cdr"),
            std::string::npos)
      << info;
  EXPECT_NE(info.find("Topic: /towsim/cable/state | Type: towsim_msgs/msg/CableState | Count: "
                      "201"),
            std::string::npos)
      << info;
  EXPECT_NE(info.find("Topic: /towsim/cable/start_force | Type: geometry_msgs/msg/WrenchStamped | "
                      "Count: 201"),
            std::string::npos)
      << info;
  EXPECT_EQ(info.find("/towsim/cable/end_force"), std::string::npos) << info;
  EXPECT_NE(info.find("MCAP profile:      ros2"), std::string::npos) << info;
  EXPECT_NE(info.find("Metadata records:  rosbag2"), std::string::npos) << info;
}

TEST_F(ExportRoundTrip, TwoVehiclesRecordedAndExportedEqualsTheNodesCsv) {
  // both cable ends on bodies: every row comes back, Euler angles and body rates non-zero
  RecordRun("config/scenes/case1_forward.yaml", 92, 10.0);
  Process exp =
      Export({(dir_ / "run.mcap").string(), "--csv=" + (dir_ / "exported").string()}, "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  ExpectSameCsv(dir_ / "node", dir_ / "exported", 101);
  EXPECT_EQ(ReadFile((dir_ / "node/forces.csv").string()),
            ReadFile((dir_ / "exported/forces.csv").string()));
  // calm water: neither the node nor the export writes environment.csv (no such topic)
  EXPECT_FALSE(fs::exists(dir_ / "node/environment.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "exported/environment.csv"));
  // sim_node --record holds no commands (it publishes none): no commands.csv; the node's own
  // actuators.csv comes back from the actuator_state topics (both vehicles take commands)
  EXPECT_TRUE(fs::exists(dir_ / "node/actuators.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "exported/commands.csv"));
  EXPECT_EQ(ReadFile((dir_ / "node/actuators.csv").string()),
            ReadFile((dir_ / "exported/actuators.csv").string()));
  // no controller: the tow vehicle's command is the script's from the first step on (its
  // entry at t = 0 fires before step 1), the towfish's the scene's initial one throughout
  const auto tow = ActuatorSources((dir_ / "run.mcap").string(), "tow_vehicle");
  const auto fish = ActuatorSources((dir_ / "run.mcap").string(), "towfish");
  ASSERT_EQ(tow.size(), 101u);
  ASSERT_EQ(fish.size(), 101u);
  for (const auto& [stamp, source] : tow) EXPECT_EQ(source, stamp == 0 ? 0 : 1) << stamp;
  for (const auto& [stamp, source] : fish) EXPECT_EQ(source, 0) << stamp;
}

// the offline script run against the DDS run (docs/recording.md "Verified"): Case 1 with a
// script that moves every actuator column (thrust, both vehicles' rudders and elevators, one
// entry behind a `when` condition), run once by `sim_node --mode offline --csv` and once in
// fast mode over DDS, recorded and exported: the offline actuators.csv is the export's byte for
// byte. Without a controller the fast node's vehicles take the scene's script as the offline
// run's do (docs/contract.md "4. Running modes"), the same step on the same state: the two runs
// agree bit for bit, so to every printed digit; bodies.csv, cable.csv and forces.csv too. DDS
// domain: automatic (DomainLease, 200-231).
TEST_F(ExportRoundTrip, OfflineScriptRunsActuatorsCsvEqualsTheExportOfTheRecordedDdsRun) {
  const towsim::testing::DomainLease lease;
  constexpr double kDuration = 10.0;  // [s]
  const std::vector<std::string> script = {
      "--set",
      "script=[{at: 0, body: tow_vehicle, thrust: 4165},"
      " {at: 2, body: tow_vehicle, rudder_deg: 10},"
      " {at: 3, body: towfish, elevator_deg: -5, rudder_deg: 4},"
      " {at: 4, when: \"tow_vehicle.yaw_deg >= 1\", body: tow_vehicle, rudder_deg: -5,"
      " elevator_deg: 3, thrust: 3000}]"};
  RecordRun("config/scenes/case1_forward.yaml", lease.id(), kDuration, script);
  // the same scene: the publish rates RecordRun sets are DDS keys, the offline run's too
  std::vector<std::string> offline = {"--set", "publish.odom=10",         "--set",
                                      "publish.cable_force=10", "--set", "publish.cable_state=10",
                                      "--set", "publish.status=10",       "--set",
                                      "publish.sensors=10"};
  offline.insert(offline.end(), script.begin(), script.end());
  OfflineRun("config/scenes/case1_forward.yaml", kDuration, offline);
  Process exp = Export({(dir_ / "run.mcap").string(), "--csv", (dir_ / "exported").string()},
                       "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();

  const auto a = Lines((dir_ / "offline/actuators.csv").string());
  const auto b = Lines((dir_ / "exported/actuators.csv").string());
  ASSERT_EQ(a.size(), 1 + 2 * 101u) << "two vehicles at t = 0, 0.1, ..., 10";
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(b[i], a[i]) << "first difference at line " << i + 1;
  }
  EXPECT_EQ(ReadFile((dir_ / "offline/actuators.csv").string()),
            ReadFile((dir_ / "exported/actuators.csv").string()));
  // not a comparison of zeros: every command column of both vehicles moved (the fins' state
  // follows them), and the conditional entry fired
  std::map<std::string, std::vector<bool>> moved;  // body -> columns 2..7 ever non-zero
  bool conditional = false;
  for (std::size_t i = 1; i < a.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream in(a[i]);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 9u) << a[i];
    auto& m = moved.try_emplace(f[1], 6, false).first->second;
    for (int c = 0; c < 6; ++c) m[c] = m[c] || std::stod(f[2 + c]) != 0.0;
    conditional = conditional || (f[1] == "tow_vehicle" && f[2] == "3000");
    EXPECT_EQ(f[8], "0") << "no failsafe: " << a[i];
  }
  EXPECT_EQ(moved["tow_vehicle"], std::vector<bool>(6, true));
  // the towfish has no propeller: thrust command and thrust stay 0
  EXPECT_EQ(moved["towfish"], (std::vector<bool>{false, true, true, false, true, true}));
  EXPECT_TRUE(conditional) << "the entry behind `when` never fired";
  // the whole run agrees, not the actuators only
  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv"}) {
    EXPECT_EQ(ReadFile((dir_ / "offline" / file).string()),
              ReadFile((dir_ / "exported" / file).string()))
        << file;
  }
}

// the commands a controller sent, recorded by towsim_record beside a lockstep node (Case 1,
// test_controller with a rudder step at 0.5 s), exported as commands.csv: one row per
// command with the step it answers, and the command answering step k is the one the node's
// actuators.csv shows in force at step k + 1 (same printed digits). DDS domain 198.
TEST_F(ExportRoundTrip, RecordedCommandsExportedAsCommandsCsvMatchTheNodesActuatorsCsv) {
  constexpr int kDomain = 198;
  constexpr double kStep = 0.05;  // case1_forward.yaml time.step [s]
  const std::string rec_file = (dir_ / "rec.mcap").string();
  Process rec({TOWSIM_RECORD, "--output", rec_file, "--domain", std::to_string(kDomain), "--quiet"},
              (dir_ / "rec").string());
  // the lockstep node waits for the controller; the recorder starts on the node's scene_info
  Process node({TOWSIM_SIM_NODE, "--scene",
                std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml", "--mode",
                "lockstep", "--domain", std::to_string(kDomain), "--duration", "2", "--csv",
                (dir_ / "node").string()},
               (dir_ / "node").string());
  for (int i = 0; i < 1000 && rec.running() &&
                  rec.err().find("towsim_record: recording") == std::string::npos;
       ++i) {
    ::usleep(20'000);
  }
  ASSERT_NE(rec.err().find("towsim_record: recording"), std::string::npos) << rec.err();
  ::usleep(1'000'000);  // the recorder's readers match the node's writers, then the controller's
  Process controller({TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(kDomain), "--command",
                      "tow_vehicle@0=4165,0,0", "--command", "tow_vehicle@0.5=4165,0.3,-0.05"},
                     (dir_ / "controller").string());
  ASSERT_TRUE(node.Wait(kTimeout)) << node.command_line();
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  ASSERT_TRUE(rec.Wait(20.0)) << "the recorder did not end with the node's run";
  ASSERT_EQ(rec.exit_code(), 0) << rec.err();
  controller.Wait(20.0);

  Process exp = Export({rec_file, "--csv", (dir_ / "exported").string()}, "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  EXPECT_NE(exp.err().find(", commands "), std::string::npos) << exp.err();
  const auto commands = Lines((dir_ / "exported/commands.csv").string());
  ASSERT_FALSE(commands.empty());
  EXPECT_EQ(commands[0], "t,body,step,thrust,rudder,elevator");
  // (body, step) -> "thrust,rudder,elevator" as printed
  std::map<std::pair<std::string, long>, std::string> sent;
  for (std::size_t i = 1; i < commands.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream in(commands[i]);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 6u) << commands[i];
    const long step = std::stol(f[2]);
    EXPECT_NEAR(std::stod(f[0]), step * kStep, 1e-9) << "t = the stamp of step k: " << commands[i];
    sent[{f[1], step}] = f[3] + "," + f[4] + "," + f[5];
  }
  // 40 steps, two commanded vehicles
  EXPECT_GE(sent.size(), 80u);
  EXPECT_EQ((sent[{"tow_vehicle", 5}]), "4165,0,0");
  EXPECT_EQ((sent[{"tow_vehicle", 10}]), "4165,0.3,-0.05");
  EXPECT_EQ((sent[{"towfish", 10}]), "0,0,0");

  const auto actuators = Lines((dir_ / "node/actuators.csv").string());
  ASSERT_EQ(actuators.size(), 1 + 2 * 21u) << "two vehicles at t = 0, 0.1, ..., 2";
  int matched = 0;
  for (std::size_t i = 1; i < actuators.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream in(actuators[i]);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 9u) << actuators[i];
    EXPECT_EQ(f[8], "0") << "no failsafe: " << actuators[i];
    const long k = std::lround(std::stod(f[0]) / kStep);
    if (k == 0) continue;
    const auto it = sent.find({f[1], k - 1});
    ASSERT_NE(it, sent.end()) << "no command recorded for " << f[1] << " at step " << k - 1;
    EXPECT_EQ(f[2] + "," + f[3] + "," + f[4], it->second) << actuators[i];
    ++matched;
  }
  EXPECT_EQ(matched, 2 * 20);
}

// the actuators on the wire (docs/topics.md "Actuator state"): a lockstep run of Case 1 with
// test_controller's rudder step (0.3 rad at step 10), recorded by the node itself (--record),
// exported: the actuator_state topics give the node's own actuators.csv, every row and every
// printed digit. And the rudder follows its command as the actuator law says (sim_node/core/
// actuator.h): at rest until the command, then at the rate limit max_rate_deg = 20 deg/s
// (config/vehicles/tow_vehicle.yaml) until 3 deg short of it (the fin servo's lag T = 0.05 s
// takes over where (u - x) / T < max_rate: 0.349 rad/s * 0.05 s = 0.0175 rad), then on to the
// command, within 2e-8 rad of it at 2 s (0.0175 rad * exp(-0.69 s / 0.05 s)). DDS domain 194.
TEST_F(ExportRoundTrip, RecordedActuatorStateExportedEqualsTheNodesActuatorsCsv) {
  const towsim::testing::DomainLease lease(194);
  constexpr double kStep = 0.05;                          // case1_forward.yaml time.step [s]
  constexpr double kRudderCommand = 0.3;                  // [rad], from step 10 on
  constexpr double kCommandTime = 10 * kStep;             // the state the command answers [s]
  constexpr double kMaxRate = 20.0 * M_PI / 180.0;        // tow_vehicle.yaml max_rate_deg [rad/s]
  constexpr double kLagStart = kRudderCommand - kMaxRate * 0.05;  // lag from here on [rad]
  // 9 printed digits of numbers below 1 rad, and RK4, exact on the rate-limited (constant
  // rate) stretch up to rounding
  constexpr double kPrintTol = 1e-8;  // [rad]
  constexpr double kSettledTol = 1e-6;  // [rad]: the lag's residue at 2 s is 2e-8 rad
  Process node({TOWSIM_SIM_NODE, "--scene",
                std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml", "--mode",
                "lockstep", "--domain", std::to_string(lease.id()), "--duration", "2", "--csv",
                (dir_ / "node").string(), "--record", (dir_ / "run.mcap").string(), "--set",
                "publish.odom=10", "--set", "publish.status=10"},
               (dir_ / "node").string());
  Process controller({TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(lease.id()), "--command",
                      "tow_vehicle@0=4165,0,0", "--command", "tow_vehicle@0.5=4165,0.3,-0.05"},
                     (dir_ / "controller").string());
  ASSERT_TRUE(node.Wait(kTimeout)) << node.command_line();
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  controller.Wait(20.0);

  Process exp = Export({(dir_ / "run.mcap").string(), "--csv", (dir_ / "exported").string(),
                        "--info"},
                       "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  EXPECT_NE(exp.err().find(", actuators 42"), std::string::npos) << exp.err();
  EXPECT_NE(exp.out().find("Topic: /towsim/tow_vehicle/actuator_state | Type: "
                           "towsim_msgs/msg/ActuatorState | Count: "),
            std::string::npos)
      << exp.out();
  const auto node_rows = Lines((dir_ / "node/actuators.csv").string());
  const auto exported = Lines((dir_ / "exported/actuators.csv").string());
  ASSERT_EQ(node_rows.size(), 1 + 2 * 21u) << "two vehicles at t = 0, 0.1, ..., 2";
  ASSERT_EQ(exported.size(), node_rows.size());
  for (std::size_t i = 0; i < node_rows.size(); ++i) {
    ASSERT_EQ(exported[i], node_rows[i]) << "first difference at line " << i + 1;
  }

  // the tow vehicle's rudder against the actuator law
  double last_t = -1.0, last_rudder = 0.0;
  int moving = 0;
  for (std::size_t i = 1; i < exported.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream in(exported[i]);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 9u) << exported[i];
    if (f[1] != "tow_vehicle") continue;
    const double t = std::stod(f[0]), command = std::stod(f[3]), rudder = std::stod(f[6]);
    EXPECT_EQ(f[8], "0") << "no failsafe: " << exported[i];
    if (t <= kCommandTime + 1e-9) {
      EXPECT_EQ(rudder, 0.0) << exported[i];
    } else {
      EXPECT_EQ(command, kRudderCommand) << exported[i];
      const double ramp = kMaxRate * (t - kCommandTime);
      if (ramp <= kLagStart) {
        EXPECT_NEAR(rudder, ramp, kPrintTol) << "at the rate limit: " << exported[i];
        ++moving;
      } else {
        EXPECT_LE(rudder, kRudderCommand + kPrintTol) << exported[i];
        EXPECT_GE(rudder, kLagStart - kPrintTol) << exported[i];
      }
    }
    if (last_t >= 0.0) {
      EXPECT_LE(std::abs(rudder - last_rudder), kMaxRate * (t - last_t) + kPrintTol)
          << "faster than the rate limit: " << exported[i];
    }
    last_t = t;
    last_rudder = rudder;
  }
  EXPECT_EQ(moving, 8) << "t = 0.6 .. 1.3 s on the rate limit";
  // the controller's commands from the first step on: source DDS (2); none (0) at t = 0
  for (const char* body : {"tow_vehicle", "towfish"}) {
    const auto sources = ActuatorSources((dir_ / "run.mcap").string(), body);
    ASSERT_EQ(sources.size(), 21u) << body;
    for (const auto& [stamp, source] : sources) {
      EXPECT_EQ(source, stamp == 0 ? 0 : 2) << body << " at " << stamp << " ns";
    }
  }
  EXPECT_NEAR(last_t, 2.0, 1e-9);
  EXPECT_NEAR(last_rudder, kRudderCommand, kSettledTol) << "settled on the command at 2 s";
}

// the failsafe on the wire: a lockstep run of Case 1 whose controller answers step 10 a second
// late (test_controller --pause 10=1) beside --lockstep-timeout 0.3: both vehicles go to
// failsafe at step 10, and the recorded actuator_state, exported, still gives the node's
// actuators.csv line for line, its failsafe column included; on the wire a vehicle in failsafe
// holds the failsafe command (source 3: zero thrust, fins centred) and no other does. DDS
// domain 195.
TEST_F(ExportRoundTrip, FailsafeOnTheWireExportedEqualsTheNodesActuatorsCsv) {
  const towsim::testing::DomainLease lease(195);
  constexpr int kSourceFailsafe = 3;  // towsim_msgs/ActuatorState SOURCE_FAILSAFE
  Process node({TOWSIM_SIM_NODE, "--scene",
                std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml", "--mode",
                "lockstep", "--domain", std::to_string(lease.id()), "--duration", "2",
                "--lockstep-timeout", "0.3", "--csv", (dir_ / "node").string(), "--record",
                (dir_ / "run.mcap").string(), "--set", "publish.odom=10", "--set",
                "publish.status=10"},
               (dir_ / "node").string());
  Process controller({TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(lease.id()), "--pause",
                      "10=1"},
                     (dir_ / "controller").string());
  ASSERT_TRUE(node.Wait(kTimeout)) << node.command_line();
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  controller.Wait(20.0);
  EXPECT_NE(node.out().find("lockstep timeouts"), std::string::npos) << node.out();

  Process exp = Export({(dir_ / "run.mcap").string(), "--csv", (dir_ / "exported").string()},
                       "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  const auto node_rows = Lines((dir_ / "node/actuators.csv").string());
  const auto exported = Lines((dir_ / "exported/actuators.csv").string());
  ASSERT_EQ(node_rows.size(), 1 + 2 * 21u);
  ASSERT_EQ(exported.size(), node_rows.size());
  int failsafe_rows = 0;
  for (std::size_t i = 0; i < node_rows.size(); ++i) {
    ASSERT_EQ(exported[i], node_rows[i]) << "first difference at line " << i + 1;
    failsafe_rows += i > 0 && node_rows[i].substr(node_rows[i].rfind(',')) == ",1";
  }
  EXPECT_GE(failsafe_rows, 2) << "both vehicles in failsafe at t = 0.6 s at least";
  int failsafe_messages = 0;
  for (const char* body : {"tow_vehicle", "towfish"}) {
    for (const auto& [stamp, a] : ActuatorStates((dir_ / "run.mcap").string(), body)) {
      EXPECT_EQ(a.failsafe, a.source == kSourceFailsafe) << body << " at " << stamp << " ns";
      if (!a.failsafe) continue;
      ++failsafe_messages;
      EXPECT_EQ(a.thrust_command, 0.0) << body << " at " << stamp << " ns";
      EXPECT_EQ(a.rudder_command, 0.0) << body << " at " << stamp << " ns";
      EXPECT_EQ(a.elevator_command, 0.0) << body << " at " << stamp << " ns";
    }
  }
  EXPECT_EQ(failsafe_messages, failsafe_rows);
}

// the sea on the wire (docs/environment.md): the steady tow in regular head waves, a sheared
// current and over a flat seabed; the node's <body>/environment topic, recorded and exported,
// gives the node's own environment.csv byte for byte (every number to its 9 printed digits).
// DDS domain 188.
TEST_F(ExportRoundTrip, SeaSceneEnvironmentTopicExportedEqualsTheNodesEnvironmentCsv) {
  std::string scene = ReadFile(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/steady_tow.yaml");
  const std::string calm = "current: [0, 0, 0]}";
  ASSERT_NE(scene.find(calm), std::string::npos);
  scene.replace(scene.find(calm), calm.size(),
                "current: {profile: [[0, [0.6, 0.1, 0]], [250, [0.1, 0, 0]]]},\n"
                "  waves: {regular: {height: 2, period: 9, direction_deg: 180}},\n"
                "  seabed: {depth: 250}}");
  const std::string model = "../vehicles/";
  ASSERT_NE(scene.find(model), std::string::npos);
  scene.replace(scene.find(model), model.size(),
                std::string(TOWSIM_SOURCE_DIR) + "/config/vehicles/");
  const fs::path scene_file = dir_ / "sea.yaml";
  std::ofstream(scene_file) << scene;
  RecordRun(scene_file.string(), 188, 5.0);
  Process exp = Export(
      {(dir_ / "run.mcap").string(), "--csv", (dir_ / "exported").string(), "--info"}, "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  ExpectSameCsv(dir_ / "node", dir_ / "exported", 51);
  const auto a = Lines((dir_ / "node/environment.csv").string());
  const auto b = Lines((dir_ / "exported/environment.csv").string());
  // 5 s at 10 Hz: 51 rows of the towfish (t = 0 included) and the header
  ASSERT_EQ(a.size(), 52u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i], b[i]) << "first difference at line " << i + 1;
  }
  EXPECT_NE(exp.out().find("Topic: /towsim/towfish/environment | Type: "
                           "towsim_msgs/msg/BodyEnvironment | Count: 51 | "),
            std::string::npos)
      << exp.out();
  EXPECT_NE(exp.err().find(", environment 51"), std::string::npos) << exp.err();
  // the values are the sea's, at t = 0 with the towfish at (0, 0, 203.5): eta = a cos(0) = 1 m
  // (phase 0 at the origin), altitude 250 - 203.5, depth z + eta, the profile's current
  // 0.6 + (0.1 - 0.6) 203.5 / 250 north and 0.1 (1 - 203.5 / 250) east (the 9 s wave's orbital
  // velocity at 203.5 m is a w e^{-k z} = 3e-5 m/s); within the 9 printed digits and that
  constexpr double kOrbitalTol = 1e-4;  // [m/s]
  std::vector<double> v;
  std::stringstream row(a[1]);
  for (std::string field; std::getline(row, field, ',');) {
    v.push_back(field == "towfish" ? 0.0 : std::stod(field));
  }
  ASSERT_EQ(v.size(), 8u) << a[1];
  EXPECT_EQ(v[0], 0.0);
  EXPECT_NEAR(v[2], 1.0, 1e-8);
  EXPECT_NEAR(v[3], 250.0 - 203.5, 1e-6);
  EXPECT_NEAR(v[4], 203.5 + 1.0, 1e-6);
  EXPECT_NEAR(v[5], 0.6 - 0.5 * 203.5 / 250.0, kOrbitalTol);
  EXPECT_NEAR(v[6], 0.1 * (1.0 - 203.5 / 250.0), kOrbitalTol);
  EXPECT_NEAR(v[7], 0.0, kOrbitalTol);
}

// a cable network (tests/integration/scenes/network_two_part_tow.yaml: main cable and tether,
// docs/scene_format.md "Networks"): each cable's rt/<ns>/<cable>/state comes back as the node's
// own <cable>.csv, byte for byte; bodies.csv, status.csv and forces.csv too: the bodies'
// totals (their cable_force topics), the depressor's per-attachment rows "depressor.main.end",
// "depressor.tether.start" (main/end_force, tether/start_force in depressor_frd) and the driven
// tow point's "main.start" (main/start_force in world_ned). DDS domain 216.
TEST_F(ExportRoundTrip, NetworkRecordedAndExportedGivesTheNodesCsvOfEveryCable) {
  RecordRun("tests/integration/scenes/network_two_part_tow.yaml", 216, 3.0);
  Process exp = Export(
      {(dir_ / "run.mcap").string(), "--csv", (dir_ / "exported").string(), "--info"}, "export");
  ASSERT_TRUE(exp.Wait(kTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  EXPECT_FALSE(fs::exists(dir_ / "node/cable.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "exported/cable.csv"));
  // 3 s at 10 Hz: 31 row sets (t = 0 included) of 21 and 11 nodes, and the header
  // forces.csv: per row set the depressor, its two attachments, the towfish, the tow point
  const std::map<std::string, std::size_t> rows = {
      {"main.csv", 1 + 31 * 21}, {"tether.csv", 1 + 31 * 11}, {"bodies.csv", 1 + 31 * 2},
      {"status.csv", 1 + 31},    {"forces.csv", 1 + 31 * 5}};
  for (const auto& [file, count] : rows) {
    SCOPED_TRACE(file);
    const auto a = Lines((dir_ / "node" / file).string());
    const auto b = Lines((dir_ / "exported" / file).string());
    EXPECT_EQ(a.size(), count);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i], b[i]) << "first difference at line " << i + 1;
    }
  }
  // the first row set of forces.csv, in the node's order
  std::vector<std::string> first;
  for (const std::string& line : Lines((dir_ / "exported/forces.csv").string())) {
    if (line.rfind("0,", 0) != 0) continue;
    first.push_back(line.substr(2, line.find(',', 2) - 2));
  }
  EXPECT_EQ(first, (std::vector<std::string>{"depressor", "depressor.main.end",
                                             "depressor.tether.start", "towfish", "main.start"}));
  const std::string info = exp.out();
  for (const char* topic :
       {"/towsim/main/start_force", "/towsim/main/end_force", "/towsim/tether/start_force"}) {
    EXPECT_NE(info.find(std::string("Topic: ") + topic +
                        " | Type: geometry_msgs/msg/WrenchStamped | Count: 31 | "),
              std::string::npos)
        << info;
  }
  EXPECT_EQ(info.find("/towsim/tether/end_force"), std::string::npos) << info;  // one attachment
  for (const char* topic : {"/towsim/main/state", "/towsim/tether/state"}) {
    EXPECT_NE(info.find(std::string("Topic: ") + topic +
                        " | Type: towsim_msgs/msg/CableState | Count: 31 | "),
              std::string::npos)
        << info;
  }
  EXPECT_EQ(info.find("/towsim/cable/state"), std::string::npos) << info;
}

// domain 134 (not 91: ctest -j2 runs it beside the steady tow test, and a second node in a
// domain and namespace is refused)
TEST_F(ExportRoundTrip, DamagedRecordingsAndBadFlagsExit2) {
  RecordRun("config/scenes/steady_tow.yaml", 134, 2.0);
  const std::string good = ReadFile((dir_ / "run.mcap").string());
  ASSERT_GT(good.size(), 1000u);
  struct Case {
    std::string name, bytes, expected;
  };
  std::string corrupt = good;
  corrupt[good.size() / 2] ^= 0x5A;  // a byte inside the chunk: its CRC fails
  const std::vector<Case> cases = {
      {"truncated", good.substr(0, good.size() - 100), "offset"},
      {"corrupt", corrupt, "CRC"},
      {"empty", "", "offset"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = (dir_ / (c.name + ".mcap")).string();
    std::ofstream(path, std::ios::binary) << c.bytes;
    Process exp = Export({path, "--csv", (dir_ / c.name).string()}, c.name);
    ASSERT_TRUE(exp.Wait(kTimeout));
    EXPECT_EQ(exp.exit_code(), 2) << exp.err();
    EXPECT_NE(exp.err().find("towsim_export: error: " + path), std::string::npos) << exp.err();
    EXPECT_NE(exp.err().find(c.expected), std::string::npos) << exp.err();
    EXPECT_NE(exp.err().find("byte offset"), std::string::npos) << exp.err();
  }
  // the truncated file read with --recover: what its complete chunks hold
  Process rec = Export({(dir_ / "truncated.mcap").string(), "--recover", "--info"}, "recover");
  ASSERT_TRUE(rec.Wait(kTimeout));
  EXPECT_EQ(rec.exit_code(), 0) << rec.err();
  EXPECT_NE(rec.out().find("Recovered:"), std::string::npos) << rec.out();

  for (const std::vector<std::string>& args :
       {std::vector<std::string>{(dir_ / "run.mcap").string()},
        std::vector<std::string>{(dir_ / "run.mcap").string(), "--bogus"},
        std::vector<std::string>{"--info"},
        std::vector<std::string>{(dir_ / "missing.mcap").string(), "--info"},
        std::vector<std::string>{(dir_ / "run.mcap").string(), "--info", "--namespace", "x"}}) {
    Process exp = Export(args, "flags");
    ASSERT_TRUE(exp.Wait(kTimeout));
    EXPECT_EQ(exp.exit_code(), 2) << args.back() << ": " << exp.err();
    EXPECT_NE(exp.err().find("towsim_export: error: "), std::string::npos) << exp.err();
  }
  // a namespace without towsim topics names the topics there are
  Process ns = Export(
      {(dir_ / "run.mcap").string(), "--csv", (dir_ / "ns").string(), "--namespace", "/other"},
      "ns");
  ASSERT_TRUE(ns.Wait(kTimeout));
  EXPECT_EQ(ns.exit_code(), 2);
  EXPECT_NE(ns.err().find("no towsim topics under the namespace '/other'"), std::string::npos)
      << ns.err();
  EXPECT_NE(ns.err().find("/towsim/cable/state"), std::string::npos) << ns.err();
}

}  // namespace
