// A cable network on the wire (docs/topics.md, docs/contract.md §3): the real sim_node in fast
// mode with a two-part tow (tests/integration/scenes/network_two_part_tow.yaml: a driven tow
// point, the main cable to a depressor, a tether from the depressor to a towfish), watched
// through the test fixture (towsim::testing::SimNode, the wire library's decoders). SceneInfo
// lists both cables with their node counts; each cable's state comes on rt/<ns>/<cable>/state
// with its own nodes; the cable ends held by a body are where that body's odometry of the same
// step puts them; the one-cable topic rt/<ns>/cable/state does not exist. DDS domain 215.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/csv_reader.h"
#include "testing/in_process_controller.h"
#include "testing/process.h"
#include "testing/sim_node.h"

namespace towsim::testing {
namespace {

// a cable end held at a sphere's centre (Eq. 24): the joint holds to the Newton tolerance,
// 1e-8 relative on a 360 m system, well inside 1e-6 m
constexpr double kJointTol = 1e-6;  // [m]

// the odometry sample of `body` stamped t (the same step), or nullopt
std::optional<OdometrySample> OdometryAt(const SimNode& node, const std::string& body, double t) {
  for (const OdometrySample& o : node.odometry_history(body)) {
    if (std::abs(o.t - t) < 1e-9) return o;
  }
  return std::nullopt;
}

TEST(NetworkOnTheWire, EveryCableHasItsStateTopicAndSceneInfoListsThem) {
  SimNodeOptions o;
  o.scene = std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/network_two_part_tow.yaml";
  o.mode = "fast";
  o.domain = 215;
  o.duration = 3.0;
  // every step on both topics, so that a cable state and an odometry share each stamp
  o.set = {"publish.odom=0", "publish.cable_state=0"};
  SimNode node(o);

  const SceneInfo& info = node.scene_info();
  EXPECT_EQ(info.scene, "network_two_part_tow");
  EXPECT_EQ(info.bodies, (std::vector<std::string>{"depressor", "towfish"}));
  EXPECT_EQ(info.cables, (std::vector<std::string>{"main", "tether"}));
  EXPECT_EQ(info.cable_node_counts, (std::vector<uint32_t>{21, 11}));  // elements + 1
  EXPECT_EQ(info.cable_nodes, 21u);  // the first cable's, as for one cable
  EXPECT_FALSE(info.has_winch);
  EXPECT_TRUE(info.winches.empty());

  const NodeResult end = node.Wait(60.0);
  ASSERT_EQ(end.exit_code, 0) << node.log();
  EXPECT_FALSE(node.cable_state("cable").has_value()) << "no one-cable topic in a network";

  const std::optional<CableSample> main = node.cable_state("main");
  const std::optional<CableSample> tether = node.cable_state("tether");
  ASSERT_TRUE(main.has_value());
  ASSERT_TRUE(tether.has_value());
  EXPECT_EQ(main->node_count, 21u);
  EXPECT_EQ(main->x.size(), 21u);
  EXPECT_EQ(main->tension.size(), 21u);
  EXPECT_EQ(tether->node_count, 11u);
  EXPECT_EQ(tether->x.size(), 11u);
  // without a winch: each cable's own length and the tension at its start
  EXPECT_EQ(main->paid_out_length, 300.0);
  EXPECT_EQ(tether->paid_out_length, 60.0);
  EXPECT_EQ(tether->drum_tension, tether->tension[0]);
  // the run's last state (3 s at 0.05 s: step 60) on both topics
  EXPECT_NEAR(main->t, 3.0, 1e-9);
  EXPECT_NEAR(tether->t, 3.0, 1e-9);
  EXPECT_EQ(main->step, 60u);
  EXPECT_EQ(tether->step, 60u);
  // a towed system: the main cable pulls harder than the tether (it also carries the
  // depressor's weight and drag), both in tension
  EXPECT_GT(tether->tension[0], 0.0);
  EXPECT_GT(main->tension[0], tether->tension[0]);
  EXPECT_EQ(node.max_tension_history("tether").size(), node.max_tension_history("main").size());

  // where the bodies hold the cables: at the spheres' centres, by their odometry of that step
  const std::optional<OdometrySample> depressor = OdometryAt(node, "depressor", tether->t);
  const std::optional<OdometrySample> towfish = OdometryAt(node, "towfish", tether->t);
  ASSERT_TRUE(depressor.has_value());
  ASSERT_TRUE(towfish.has_value());
  EXPECT_NEAR(tether->x[0], depressor->x, kJointTol);
  EXPECT_NEAR(tether->y[0], depressor->y, kJointTol);
  EXPECT_NEAR(tether->z[0], depressor->z, kJointTol);
  EXPECT_NEAR(main->x[20], depressor->x, kJointTol);
  EXPECT_NEAR(main->z[20], depressor->z, kJointTol);
  EXPECT_NEAR(tether->x[10], towfish->x, kJointTol);
  EXPECT_NEAR(tether->z[10], towfish->z, kJointTol);
  // the tow point, driven at 2.5 m/s from the origin
  EXPECT_NEAR(main->x[0], 2.5 * 3.0, kJointTol);
  EXPECT_NEAR(main->z[0], 0.0, kJointTol);
}

// the client on the towing vehicle of tests/integration/scenes/network_tow_vehicle.yaml reads
// the tether by name: at every step whose tether state it got, the tether's 6 nodes and its
// first node at the depressor's odometry of that step (ClientOptions::observe)
TEST(NetworkOnTheWire, TheClientReadsACableByName) {
  SimNodeOptions o;
  o.scene = std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/network_tow_vehicle.yaml";
  o.domain = 217;
  o.duration = 2.0;
  o.set = {"publish.cable_state=0"};
  SimNode node(o);
  EXPECT_EQ(node.scene_info().cables, (std::vector<std::string>{"main", "tether"}));

  controllers::ClientOptions wrong;
  wrong.body = "tow_vehicle";
  wrong.cable = true;  // the default name, "cable": not in this scene
  InProcessController refused(node, wrong, [](const controllers::BodyState&) {
    return controllers::Actuation();
  });
  EXPECT_EQ(refused.Join(), 2);
  EXPECT_NE(refused.error().find("has no cable cable (cables: main, tether)"), std::string::npos)
      << refused.error();

  controllers::ClientOptions opt;
  opt.body = "tow_vehicle";
  opt.cable = true;
  opt.cable_name = "tether";
  opt.observe = "depressor";
  int compared = 0, sized = 0;
  double worst = 0.0;  // |tether node 0 - depressor| [m]
  InProcessController controller(node, opt, [&](const controllers::BodyState& b) {
    if (b.observed.valid && std::abs(b.cable.t - b.t) < 1e-9) {
      sized += b.cable.node_count == 6 && b.cable.x.size() == 6;
      worst = std::max({worst, std::abs(b.cable.x[0] - b.observed.x),
                        std::abs(b.cable.y[0] - b.observed.y),
                        std::abs(b.cable.z[0] - b.observed.z)});
      ++compared;
    }
    return controllers::Actuation(2000.0, 0.0, 0.0);
  });
  EXPECT_EQ(controller.Join(), 0) << controller.error();
  EXPECT_EQ(node.Wait(60.0).exit_code, 0) << node.log();
  // 40 steps answered; most with the state of their own step (the node publishes it first)
  EXPECT_GE(compared, 20);
  EXPECT_EQ(sized, compared);
  EXPECT_LE(worst, kJointTol);
}

// the controllers' programs read a cable by name (--cable NAME, docs/controllers.md "Cables"),
// as separate processes against the real node on tests/integration/scenes/network_tow_vehicle.yaml:
// a name the scene has no cable of is refused naming its cables; --help lists the flag; the
// cable columns of the program's --log ("t_c top end" at its end) are the node's own <cable>.csv
// rows of that time. `program` commands the towing vehicle; `columns` its log line's own fields.
// The log prints "%.6f", the CSV "%.9g": they agree to half a unit of the log's last digit and
// 9 significant digits
constexpr double kLogTol = 5e-7;      // [N] absolute, "%.6f"
constexpr double kCsvDigits = 1e-8;   // relative, "%.9g"

std::map<std::string, std::pair<double, double>> CableCsvEnds(const std::string& path) {
  // t as written -> (tension at node 0, at the last node)
  std::map<std::string, std::pair<double, double>> ends;
  for (const auto& row : io::ReadCsvFile(path).rows) {
    auto it = ends.find(row[0]);
    const double tension = std::stod(row[5]);
    if (it == ends.end()) {
      ends[row[0]] = {tension, tension};
    } else {
      it->second.second = tension;
    }
  }
  return ends;
}

void ExpectLogReadsTheCable(int domain, const std::string& program,
                            std::vector<std::string> args, const std::string& cable,
                            size_t columns) {
  SimNodeOptions o;
  o.scene = std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/network_tow_vehicle.yaml";
  o.domain = domain;
  o.duration = 2.0;
  o.set = {"publish.cable_state=0"};  // every step: the log's newest sample is its own step's
  SimNode node(o);
  const std::string name = program.substr(program.rfind('/') + 1);
  const std::string dom = std::to_string(node.domain());

  args.insert(args.begin(), program);
  for (const std::string& a : {"--body", "tow_vehicle", "--domain", dom.c_str(), "--cable"}) {
    args.push_back(a);
  }
  // refused before any command: the scene's cables named (the node waits in lockstep)
  std::vector<std::string> wrong = args;
  wrong.push_back("ghost");
  Process ghost(wrong, LogPrefix(name + "_ghost"));
  ASSERT_TRUE(ghost.Wait(60.0));
  EXPECT_EQ(ghost.exit_code(), 1) << ghost.err();
  EXPECT_NE(ghost.err().find("scene network_tow_vehicle has no cable ghost (cables: main, "
                             "tether)"),
            std::string::npos)
      << ghost.err();

  const std::string log = LogPrefix(name + "_log");
  args.insert(args.end(), {cable, "--log", log});
  Process controller(args, LogPrefix(name));
  ASSERT_TRUE(controller.Wait(60.0)) << controller.command_line();
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  ASSERT_EQ(node.Wait(60.0).exit_code, 0) << node.log();

  const auto csv = CableCsvEnds(node.csv_dir() + "/" + cable + ".csv");
  ASSERT_EQ(csv.size(), 21u);  // 2 s at 10 Hz, t = 0 included
  std::istringstream lines(ReadFile(log));
  int steps = 0, compared = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::vector<double> f;
    for (double x; in >> x;) f.push_back(x);
    ASSERT_EQ(f.size(), columns + 3) << line;
    ++steps;
    const double t_c = f[columns], top = f[columns + 1], end = f[columns + 2];
    ASSERT_GE(t_c, 0.0) << line;  // every step's state came (publish.cable_state=0)
    // the rows of the CSV: the output times (10 Hz)
    char t_text[32];
    std::snprintf(t_text, sizeof t_text, "%.9g", std::round(t_c * 10.0) / 10.0);
    const auto row = csv.find(t_text);
    if (row == csv.end() || std::abs(t_c * 10.0 - std::round(t_c * 10.0)) > 1e-6) continue;
    EXPECT_NEAR(top, row->second.first, kLogTol + kCsvDigits * row->second.first) << line;
    EXPECT_NEAR(end, row->second.second, kLogTol + kCsvDigits * row->second.second) << line;
    ++compared;
  }
  // every step's state answered (40), and the final one at 2 s when the controller saw it
  // before the node's end of run
  EXPECT_GE(steps, 40);
  EXPECT_LE(steps, 41);
  // the output times 0 .. 2 s: the samples of their own step, but for the odd one a DDS reader
  // of the cable got later than the status (no order across writers)
  EXPECT_GE(compared, 19);
  EXPECT_LE(compared, 21);
}

TEST(NetworkOnTheWire, TowfishDepthReadsTheTetherByName) {
  // t z elevator target_depth
  ExpectLogReadsTheCable(218, TOWSIM_TOWFISH_DEPTH, {"--depth", "4"}, "tether", 4);
}

TEST(NetworkOnTheWire, AutopilotReadsTheMainCableByName) {
  // t x y yaw u speed_d heading_d thrust rudder elevator waypoint
  ExpectLogReadsTheCable(219, TOWSIM_AUTOPILOT, {"--speed", "1"}, "main", 11);
}

// --help lists --cable; maneuver_runner refuses a cable the scene does not have
TEST(NetworkOnTheWire, EveryProgramTakesACableFlag) {
  for (const char* program : {TOWSIM_TOWFISH_DEPTH, TOWSIM_AUTOPILOT, TOWSIM_MANEUVER_RUNNER}) {
    Process help({program, "--help"}, LogPrefix("help"));
    ASSERT_TRUE(help.Wait(30.0));
    EXPECT_EQ(help.exit_code(), 0) << program;
    EXPECT_NE(help.out().find("--cable NAME"), std::string::npos) << program << help.out();
  }
  SimNodeOptions o;
  o.scene = std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/network_tow_vehicle.yaml";
  o.domain = 193;
  o.duration = 0.5;
  SimNode node(o);
  Process ghost({TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--domain",
                 std::to_string(node.domain()), "--cable", "ghost"},
                LogPrefix("maneuver_runner_ghost"));
  ASSERT_TRUE(ghost.Wait(60.0));
  EXPECT_EQ(ghost.exit_code(), 1) << ghost.err();
  EXPECT_NE(ghost.err().find("has no cable ghost (cables: main, tether)"), std::string::npos)
      << ghost.err();
  // by name it runs the manoeuvre to the end of the node's run
  Process runner({TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--thrust", "1000", "--domain",
                  std::to_string(node.domain()), "--cable", "tether"},
                 LogPrefix("maneuver_runner"));
  ASSERT_TRUE(runner.Wait(60.0));
  EXPECT_EQ(runner.exit_code(), 0) << runner.err();
  // every step (10), and the final state when it came before the end of the run
  const std::string out = runner.out();
  const size_t at = out.find("maneuver_runner: case1, ");
  ASSERT_NE(at, std::string::npos) << out;
  const int answered = std::atoi(out.c_str() + at + 24);
  EXPECT_GE(answered, 10) << out;
  EXPECT_LE(answered, 11) << out;
  EXPECT_EQ(node.Wait(60.0).exit_code, 0) << node.log();
}

}  // namespace
}  // namespace towsim::testing
