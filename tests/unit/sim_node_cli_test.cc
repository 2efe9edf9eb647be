// The sim_node command line as scripts and users meet it (docs/contract.md §5): the real binary runs as
// a process; exit codes, messages and the CSV files are checked.
//   0 ok, 2 bad input (the message names the key), 3 solver failure, 128 + signal when stopped.

#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "run_sim_node.h"
#include "temp_dir.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = TOWSIM_SOURCE_DIR;
const std::string kSimNode = TOWSIM_SIM_NODE;

using towsim::test::ReadFile;
using towsim::test::RunSimNode;
using towsim::test::ShellQuote;
using towsim::test::SimNodeResult;
using towsim::test::TempDir;

void WriteFile(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

size_t CountFields(const std::string& line) {
  return static_cast<size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

// the first field (t) of every data row
std::vector<std::string> Times(const std::vector<std::string>& lines) {
  std::vector<std::string> times;
  for (size_t i = 1; i < lines.size(); ++i) times.push_back(lines[i].substr(0, lines[i].find(',')));
  return times;
}

// a small valid scene: 20 m of cable from a fixed point down to a sphere
constexpr char kGoodScene[] = R"(name: cli_test
time: {step: 0.05, duration: 1, output_rate: 10}
cable:
  length: 20
  elements: 4
  diameter: 0.041
  density: 1300
  youngs_modulus: 7.0e8
  start: {fixed: [0, 0, 0]}
  end: {body: ball, at: [0, 0, 0]}
bodies:
  ball: {type: sphere, mass: 50, volume: 0.01, position: [0, 0, 20]}
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(SimNodeCliTest, GoodSceneRuns) {
  // the base of the broken scenes below is itself valid
  TempDir tmp;
  WriteFile(tmp.path() / "good.yaml", kGoodScene);
  const SimNodeResult r =
      RunSimNode({"--scene", (tmp.path() / "good.yaml").string(), "--mode", "offline"}, tmp.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("sim_node: cli_test: 20 steps, 1 s simulated"), std::string::npos) << r.out;
  // no vehicles, no coupling iterations in the summary
  EXPECT_EQ(r.out.find("coupling"), std::string::npos) << r.out;
}

// --- bad input: exit 2 and a message naming what is wrong ----------------------------------

struct BadScene {
  const char* name;
  std::string yaml;  // the scene file's text
  std::vector<std::string> extra_args;
  std::vector<std::string> expected;  // substrings of stderr
};

// test names for ctest, instead of a byte dump
void PrintTo(const BadScene& c, std::ostream* os) { *os << c.name; }

std::vector<BadScene> BadScenes() {
  const std::string good = kGoodScene;
  return {
      {"MissingKey", Replace(good, "  length: 20\n", ""), {}, {"cable.length", "is required"}},
      {"WrongType",
       Replace(good, "elements: 4", "elements: four"),
       {},
       {"cable.elements = four", "must be an integer"}},
      {"NegativeLength",
       Replace(good, "length: 20", "length: -20"),
       {},
       {"cable.length = -20", "must be > 0"}},
      {"UnknownKey",
       Replace(good, "length: 20", "lenght: 20"),
       {},
       {"cable.lenght", "unknown key", "did you mean length"}},
      {"UnknownBody",
       Replace(good, "body: ball", "body: fish"),
       {},
       {"cable.end.body = fish", "no such body"}},
      {"NotYaml", "name: [unclosed\ncable: {length: 3\n", {}, {"scene.yaml", "not valid YAML"}},
      {"UnknownKeyBySet", good, {"--set", "cable.lenght=3"}, {"cable.lenght", "--set"}},
      {"WrongTypeBySet",
       good,
       {"--set", "cable.elements=abc"},
       {"cable.elements = abc", "--set", "must be an integer"}},
  };
}

class BadSceneTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, ExitsTwoNamingTheKey) {
  const BadScene& c = GetParam();
  TempDir tmp;
  const fs::path scene = tmp.path() / "scene.yaml";
  WriteFile(scene, c.yaml);
  std::vector<std::string> args = {"--scene", scene.string(), "--mode",
                                   "offline", "--csv",        (tmp.path() / "csv").string()};
  args.insert(args.end(), c.extra_args.begin(), c.extra_args.end());
  const SimNodeResult r = RunSimNode(args, tmp.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("sim_node: error: ", 0), 0u) << r.err;
  for (const std::string& text : c.expected) {
    EXPECT_NE(r.err.find(text), std::string::npos) << "expected '" << text << "' in: " << r.err;
  }
  EXPECT_FALSE(fs::exists(tmp.path() / "csv")) << "no output for a scene that does not load";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BadSceneTest, ::testing::ValuesIn(BadScenes()),
                         [](const auto& info) { return std::string(info.param.name); });

struct BadArgs {
  const char* name;
  std::vector<std::string> args;
  std::vector<std::string> expected;  // substrings of stderr
};

void PrintTo(const BadArgs& c, std::ostream* os) { *os << c.name; }

class BadArgsTest : public ::testing::TestWithParam<BadArgs> {};

TEST_P(BadArgsTest, ExitsTwoWithMessage) {
  const BadArgs& c = GetParam();
  TempDir tmp;
  const SimNodeResult r = RunSimNode(c.args, tmp.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const std::string& text : c.expected) {
    EXPECT_NE(r.err.find(text), std::string::npos) << "expected '" << text << "' in: " << r.err;
  }
}

const std::string kCatenary = (kSourceDir / "config/scenes/catenary.yaml").string();

INSTANTIATE_TEST_SUITE_P(
    CommandLine, BadArgsTest,
    ::testing::Values(
        BadArgs{"MissingScene", {"--mode", "offline"}, {"missing --scene", "usage:"}},
        BadArgs{"UnknownFlag", {"--scene", kCatenary, "--bogus"}, {"'--bogus'", "usage:"}},
        BadArgs{"MissingValue", {"--scene"}, {"--scene needs a value", "usage:"}},
        BadArgs{"BadMode", {"--scene", kCatenary, "--mode", "turbo"}, {"--mode turbo"}},
        BadArgs{"NegativeDuration", {"--scene", kCatenary, "--duration", "-1"}, {"--duration"}},
        BadArgs{
            "MalformedSet", {"--scene", kCatenary, "--set", "cable.elements"}, {"key.path=value"}},
        BadArgs{"NonexistentSceneFile",
                {"--scene", "/nonexistent/towsim/scene.yaml", "--mode", "offline"},
                {"/nonexistent/towsim/scene.yaml", "cannot read"}},
        BadArgs{"NegativeDomain",
                {"--scene", kCatenary, "--mode", "fast", "--domain", "-1"},
                {"--domain -1", "integer >= 0"}},
        BadArgs{"NamespaceWithoutSlash",
                {"--scene", kCatenary, "--mode", "fast", "--namespace", "towsim"},
                {"--namespace towsim", "must start with '/'"}},
        BadArgs{"FoxglovePortOutOfRange",
                {"--scene", kCatenary, "--mode", "fast", "--foxglove", "70000"},
                {"--foxglove 70000", "port number from 0 to 65535"}},
        BadArgs{"FoxgloveOffline",
                {"--scene", kCatenary, "--mode", "offline", "--foxglove", "8765"},
                {"--foxglove", "needs a DDS mode"}},
        BadArgs{"PausedOffline",
                {"--scene", kCatenary, "--mode", "offline", "--paused"},
                {"--paused", "needs a DDS mode"}},
        BadArgs{"RecordOffline",
                {"--scene", kCatenary, "--mode", "offline", "--record", "x.mcap"},
                {"--record x.mcap", "needs a DDS mode"}},
        BadArgs{"RecordWallTimeWithoutRecord",
                {"--scene", kCatenary, "--mode", "fast", "--record-wall-time"},
                {"--record-wall-time: needs --record FILE.mcap"}},
        BadArgs{"BadWinchSource",
                {"--scene", kCatenary, "--mode", "fast", "--winch", "manual"},
                {"--winch manual", "must be dds or script"}},
        BadArgs{"WinchDdsOffline",
                {"--scene", kCatenary, "--mode", "offline", "--winch", "dds"},
                {"--winch dds", "needs a DDS mode"}},
        BadArgs{"WinchWithoutAWinch",
                {"--scene", kCatenary, "--mode", "offline", "--winch", "script"},
                {"--winch script", "has no winch (cable.winch)"}},
        BadArgs{"NegativeLockstepTimeout",
                {"--scene", kCatenary, "--mode", "lockstep", "--lockstep-timeout", "-1"},
                {"--lockstep-timeout -1: must be a number of seconds >= 0 (0: wait forever)",
                 "usage:"}},
        BadArgs{"NanLockstepTimeout",
                {"--scene", kCatenary, "--mode", "lockstep", "--lockstep-timeout", "nan"},
                {"--lockstep-timeout nan: must be a number of seconds >= 0"}},
        BadArgs{"InfiniteLockstepTimeout",
                {"--scene", kCatenary, "--mode", "lockstep", "--lockstep-timeout=inf"},
                {"--lockstep-timeout inf: must be a number of seconds >= 0"}},
        BadArgs{"NonNumberLockstepTimeout",
                {"--scene", kCatenary, "--mode", "lockstep", "--lockstep-timeout", "2s"},
                {"--lockstep-timeout 2s: must be a number of seconds >= 0"}},
        BadArgs{"MissingLockstepTimeout",
                {"--scene", kCatenary, "--mode", "lockstep", "--lockstep-timeout"},
                {"option --lockstep-timeout needs a value"}},
        BadArgs{"LockstepTimeoutOutsideLockstep",
                {"--scene", kCatenary, "--mode", "fast", "--lockstep-timeout", "2"},
                {"--lockstep-timeout: needs --mode lockstep (the mode is fast)"}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SimNodeCliTest, HelpAndVersionExitZero) {
  TempDir tmp;
  SimNodeResult r = RunSimNode({"--help"}, tmp.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("usage: sim_node --scene FILE"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--lockstep-timeout S"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--fail-on-failsafe"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--record-wall-time"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("5 failsafe or lockstep timeout"), std::string::npos) << r.out;
  r = RunSimNode({"--version"}, tmp.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("sim_node (towsim) "), std::string::npos) << r.out;
}

// --- a good run -----------------------------------------------------------------------------

TEST(SimNodeCliTest, OfflineCatenaryWritesTheFourCsvFiles) {
  TempDir tmp;
  const fs::path csv = tmp.path() / "csv";
  const SimNodeResult r = RunSimNode(
      {"--scene", kCatenary, "--mode", "offline", "--duration", "1", "--csv", csv.string(),
       // pinned here, so that the row counts below hold whatever catenary.yaml says
       "--set", "time.step=0.05", "--set", "time.output_rate=10", "--set", "cable.elements=20"},
      tmp.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // h = 0.05 s, so 1 s is 20 steps
  EXPECT_NE(r.out.find("sim_node: catenary: 20 steps, 1 s simulated in "), std::string::npos)
      << r.out;
  EXPECT_TRUE(std::regex_search(
      r.out,
      std::regex(R"(\(RTF [0-9.]+\), Newton iterations mean [0-9.]+ max \d+, substeps \d+)")))
      << r.out;

  struct Expected {
    const char* file;
    const char* header;
    size_t rows_per_time;  // catenary: no bodies, 21 nodes, two fixed ends
  };
  for (const Expected& e :
       {Expected{"bodies.csv", "t,body,x,y,z,roll,pitch,yaw,u,v,w,p,q,r", 0},
        Expected{"cable.csv", "t,node,x,y,z,tension", 21},
        Expected{"forces.csv", "t,body,fx,fy,fz,mx,my,mz", 2},
        Expected{"status.csv", "t,step,newton_iterations,residual,wall_us,cable_length", 1}}) {
    SCOPED_TRACE(e.file);
    const std::vector<std::string> lines = Lines(ReadFile(csv / e.file));
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0], e.header);
    // output_rate 10 Hz: t = 0, 0.1, ..., 1 -> 11 row sets
    EXPECT_EQ(lines.size(), 1 + 11 * e.rows_per_time);
    for (const std::string& line : lines) EXPECT_EQ(CountFields(line), CountFields(e.header));
    if (e.rows_per_time == 0) continue;
    const std::vector<std::string> times = Times(lines);
    EXPECT_EQ(times.front(), "0");
    EXPECT_EQ(times.back(), "1");
  }
  const std::vector<std::string> forces = Lines(ReadFile(csv / "forces.csv"));
  EXPECT_EQ(forces[1].rfind("0,cable.start,", 0), 0u) << forces[1];
  EXPECT_EQ(forces[2].rfind("0,cable.end,", 0), 0u) << forces[2];
  const std::vector<std::string> status = Lines(ReadFile(csv / "status.csv"));
  EXPECT_EQ(status[1].rfind("0,0,0,", 0), 0u) << status[1];
  EXPECT_EQ(status.back().rfind("1,20,", 0), 0u) << status.back();
  // a calm scene: no environment.csv (the four files, as before)
  EXPECT_FALSE(fs::exists(csv / "environment.csv"));
}

// --- vehicles and the script ----------------------------------------------------------------

const std::string kCase1 = (kSourceDir / "config/scenes/case1_forward.yaml").string();

// the field `column` of the rows of `lines` at time `t` for `body`
double Value(const std::vector<std::string>& lines, const std::string& t, const std::string& body,
             int column) {
  for (const std::string& line : lines) {
    if (line.rfind(t + "," + body + ",", 0) != 0) continue;
    std::stringstream in(line);
    std::string field;
    for (int c = 0; c <= column; ++c) std::getline(in, field, ',');
    return std::stod(field);
  }
  ADD_FAILURE() << "no row for " << body << " at t = " << t;
  return 0.0;
}

// the sea at the sphere of kGoodScene, written by the node: environment.csv is the bodies'
// positions seen through the seabed and the surface (columns checked against bodies.csv and the
// plane's closed form, not against the accessors that wrote them)
TEST(SimNodeCliTest, SeaSceneWritesEnvironmentCsv) {
  TempDir tmp;
  constexpr double kBed = 40.0, kSlopeDeg = 3.0, kSlopeDirDeg = 30.0;
  const fs::path scene = tmp.path() / "sea.yaml";
  WriteFile(scene, std::string(kGoodScene) +
                       "environment:\n"
                       "  current: [0.4, 0.1, 0]\n"
                       "  waves: {regular: {height: 2, period: 7, direction_deg: 20}}\n"
                       "  seabed: {depth: 40, slope_deg: 3, slope_direction_deg: 30}\n");
  const fs::path csv = tmp.path() / "csv";
  const SimNodeResult r = RunSimNode(
      {"--scene", scene.string(), "--mode", "offline", "--csv", csv.string()}, tmp.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> env = Lines(ReadFile(csv / "environment.csv"));
  const std::vector<std::string> bodies = Lines(ReadFile(csv / "bodies.csv"));
  ASSERT_FALSE(env.empty());
  EXPECT_EQ(env[0], "t,body,wave_elevation,altitude,depth,current_u,current_v,current_w");
  ASSERT_EQ(env.size(), 1u + 11u) << "one row per body at t = 0, 0.1, ..., 1";
  ASSERT_EQ(Times(env), Times(bodies));
  // "%.9g": a value read back is within 1e-8 relative of the printed double
  constexpr double kPrintRelTol = 1e-8;
  const double pi = std::acos(-1.0);
  double max_eta = 0.0;
  for (const std::string& t : Times(env)) {
    SCOPED_TRACE("t = " + t);
    const double x = Value(bodies, t, "ball", 2), y = Value(bodies, t, "ball", 3);
    const double z = Value(bodies, t, "ball", 4);
    const double eta = Value(env, t, "ball", 2), altitude = Value(env, t, "ball", 3);
    const double depth = Value(env, t, "ball", 4);
    const double c = kSlopeDirDeg * pi / 180.0;
    const double bed =
        kBed + std::tan(kSlopeDeg * pi / 180.0) * (x * std::cos(c) + y * std::sin(c));
    EXPECT_NEAR(altitude, bed - z, kPrintRelTol * bed) << "altitude = d(x, y) - z";
    EXPECT_NEAR(depth, z + eta, kPrintRelTol * (std::abs(z) + 1.0)) << "depth = z + eta";
    EXPECT_LE(std::abs(eta), 1.0 + 1e-9) << "a 2 m wave: |eta| <= a";
    max_eta = std::max(max_eta, std::abs(eta));
    // 20 m below a 7 s wave (k = 0.082 /m): orbital velocity a w e^{-kz} = 0.17 m/s at most
    const double u = Value(env, t, "ball", 5), v = Value(env, t, "ball", 6);
    EXPECT_NEAR(u, 0.4, 0.2);
    EXPECT_NEAR(v, 0.1, 0.2);
  }
  EXPECT_GT(max_eta, 0.1) << "the wave is in the file";
}

TEST(SimNodeCliTest, VehicleSceneRunsTheScript) {
  TempDir tmp;
  // the paper's Case 1 for 2 s: the thrust of the script accelerates the towing vehicle
  for (const bool thrust : {true, false}) {
    SCOPED_TRACE(thrust ? "with thrust" : "without script");
    const fs::path csv = tmp.path() / (thrust ? "thrust" : "none");
    std::vector<std::string> args = {"--scene",    kCase1, "--mode", "offline",
                                     "--duration", "2",    "--csv",  csv.string()};
    if (!thrust) args.insert(args.end(), {"--set", "script=[]"});
    const SimNodeResult r = RunSimNode(args, tmp.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(
        std::regex_search(r.out, std::regex(R"(substeps \d+, coupling iterations mean [0-9.]+\n)")))
        << r.out;

    // one row per body and time, spheres (none) then vehicles in scene order; the cable ends
    // are on the vehicles, so forces.csv has no support rows
    const std::vector<std::string> bodies = Lines(ReadFile(csv / "bodies.csv"));
    const std::vector<std::string> forces = Lines(ReadFile(csv / "forces.csv"));
    ASSERT_EQ(bodies.size(), 1 + 2 * 21u);  // t = 0, 0.1, ..., 2
    ASSERT_EQ(forces.size(), 1 + 2 * 21u);
    EXPECT_EQ(bodies[1].rfind("0,tow_vehicle,0,0,3.5,", 0), 0u) << bodies[1];
    EXPECT_EQ(bodies[2].rfind("0,towfish,", 0), 0u) << bodies[2];
    EXPECT_EQ(forces[1].rfind("0,tow_vehicle,", 0), 0u) << forces[1];
    EXPECT_EQ(forces[2].rfind("0,towfish,", 0), 0u) << forces[2];
    for (const std::string& line : bodies) EXPECT_EQ(CountFields(line), 14u);
    for (const std::string& line : forces) EXPECT_EQ(CountFields(line), 8u);

    // surge u (column 8) of the towing vehicle after 2 s: the thrust makes the difference
    const double u = Value(bodies, "2", "tow_vehicle", 8);
    if (thrust) {
      EXPECT_GT(u, 0.3);
    } else {
      EXPECT_LT(std::abs(u), 0.1);
    }
    // the cable pulls the towfish up (z down): a negative heave force in its frame
    EXPECT_LT(Value(forces, "2", "towfish", 4), 0.0);
  }
}

// actuators.csv of an offline run: Case 1 with a 20 deg rudder step at 0.5 s. The command
// column is the script's command in force during the step that ended at t: it steps at the
// first row after 0.5 s. The actual rudder (VehicleState::actuator[kRudder]) starts at 0.5 s,
// ramps at the vehicle file's rate limit (config/vehicles/tow_vehicle.yaml: rudder.max_rate_deg
// 20) while the servo lag's demand (u - x) / T exceeds it (until 1 deg short, T = 0.05 s), and
// reaches the command; failsafe is 0 offline. The towfish, never commanded, stays at 0.
TEST(SimNodeCliTest, OfflineRudderStepIsInActuatorsCsv) {
  TempDir tmp;
  const fs::path csv = tmp.path() / "csv";
  const SimNodeResult r = RunSimNode(
      {"--scene", kCase1, "--mode", "offline", "--duration", "2", "--csv", csv.string(), "--set",
       "script=[{at: 0, body: tow_vehicle, thrust: 4165}, "
       "{at: 0.5, body: tow_vehicle, rudder_deg: 20}]"},
      tmp.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> act = Lines(ReadFile(csv / "actuators.csv"));
  ASSERT_FALSE(act.empty());
  EXPECT_EQ(act[0],
            "t,body,thrust_command,rudder_command,elevator_command,thrust,rudder,elevator,failsafe");
  ASSERT_EQ(act.size(), 1 + 2 * 21u) << "one row per vehicle at t = 0, 0.1, ..., 2";
  EXPECT_EQ(Times(act), Times(Lines(ReadFile(csv / "bodies.csv"))));
  EXPECT_EQ(act[1], "0,tow_vehicle,0,0,0,0,0,0,0") << "t = 0: the initial command and state";

  const double pi = std::acos(-1.0);
  const double kStep = 20.0 * pi / 180.0;  // the scripted rudder [rad]
  const double kRate = 20.0 * pi / 180.0;  // tow_vehicle.yaml rudder.max_rate_deg [rad/s]
  constexpr double kDt = 0.1;              // the output interval (case1: output_rate 10)
  constexpr double kStepAt = 0.5;          // [s]
  // "%.9g" of values <= 0.35 rad, and RK4 of a constant rate: exact to the printed digits
  constexpr double kPrintTol = 1e-8;
  double previous = 0.0;
  for (int k = 0; k <= 20; ++k) {
    const double t = k * kDt;
    std::ostringstream name;
    name << t;
    SCOPED_TRACE("t = " + name.str());
    const double command = Value(act, name.str(), "tow_vehicle", 3);
    const double rudder = Value(act, name.str(), "tow_vehicle", 6);
    // the command steps at the first row after the scripted time
    EXPECT_NEAR(command, t <= kStepAt + 1e-9 ? 0.0 : kStep, kPrintTol);
    EXPECT_EQ(Value(act, name.str(), "tow_vehicle", 2), k == 0 ? 0.0 : 4165.0) << "thrust command";
    EXPECT_EQ(Value(act, name.str(), "tow_vehicle", 9), 0.0) << "failsafe offline";
    EXPECT_EQ(Value(act, name.str(), "towfish", 6), 0.0) << "the towfish's rudder";
    // never faster than the rate limit
    EXPECT_LE(rudder - previous, kRate * kDt + kPrintTol);
    const double ramp = kRate * std::max(0.0, t - kStepAt);
    if (ramp <= kStep - kRate * 0.05) {
      // on the ramp: slope = the rate limit exactly
      EXPECT_NEAR(rudder, ramp, kPrintTol);
    } else {
      // the last degree: the servo lag closes it (1 deg e^{-(t - 1.45 s) / 0.05 s})
      EXPECT_LE(rudder, kStep + kPrintTol);
      EXPECT_GE(rudder, kStep - kRate * 0.05);
    }
    previous = rudder;
  }
  // reached: the last degree decays by RK4's 0.375 per 0.05 s step (lambda h = -1) over the
  // 0.55 s after the ramp: 0.375^11 of a degree, 4e-7 rad
  EXPECT_NEAR(Value(act, "2", "tow_vehicle", 6), kStep, 1e-6);
}

TEST(SimNodeCliTest, BadScriptConditionExitsTwo) {
  TempDir tmp;
  const SimNodeResult r = RunSimNode(
      {"--scene", kCase1, "--mode", "offline", "--set",
       "script=[{at: 1, when: \"tow_vehicle.yaw >= 10\", body: tow_vehicle, rudder: 0}]"},
      tmp.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("sim_node: error: script[0].when = \"tow_vehicle.yaw >= 10\" (--set): "
                       "unknown quantity yaw; did you mean yaw_deg?"),
            std::string::npos)
      << r.err;
}

// --- solver failure -------------------------------------------------------------------------

// One Newton iteration, no sub-stepping and a 1e-14 tolerance cannot converge on the first
// step of the steady tow (the towing point starts moving at 6 m/s: drag makes the step
// strongly nonlinear, the first Newton update leaves a residual of ~1e3 N), so step 1 fails,
// deterministically.
TEST(SimNodeCliTest, SolverFailureExitsThree) {
  TempDir tmp;
  const fs::path csv = tmp.path() / "csv";
  const SimNodeResult r = RunSimNode(
      {"--scene", (kSourceDir / "config/scenes/steady_tow.yaml").string(), "--mode", "offline",
       "--duration", "1", "--csv", csv.string(), "--set", "integrator.max_iterations=1", "--set",
       "integrator.max_substep_level=0", "--set", "integrator.tolerance=1e-14"},
      tmp.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("sim_node: solver failure at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(step 1)"), std::string::npos) << r.err;
  // the CSV holds what was written before the failure: the state at t = 0
  const std::vector<std::string> status = Lines(ReadFile(csv / "status.csv"));
  ASSERT_EQ(status.size(), 2u);
  EXPECT_EQ(status[1].rfind("0,0,", 0), 0u);
}

// offline has no failsafe: --fail-on-failsafe is accepted (towsim_sweep passes it) and the run
// is the same, exit 0
TEST(SimNodeCliTest, FailOnFailsafeOfflineIsHarmless) {
  TempDir tmp;
  const SimNodeResult r = RunSimNode(
      {"--scene", kCatenary, "--mode", "offline", "--duration", "0.2", "--fail-on-failsafe"},
      tmp.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

// --- stopped by a signal --------------------------------------------------------------------

// SIGTERM stops the loop at a step boundary: exit 143, summary printed, CSV complete.
TEST(SimNodeCliTest, SigtermStopsCleanly) {
  TempDir tmp;
  const fs::path csv = tmp.path() / "csv";
  const fs::path out = tmp.path() / "stdout.txt";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // a run far longer than the test: 1e6 s of steady tow
    std::freopen(out.c_str(), "w", stdout);
    std::freopen((tmp.path() / "stderr.txt").c_str(), "w", stderr);
    const std::string scene = (kSourceDir / "config/scenes/steady_tow.yaml").string();
    const std::string dir = csv.string();
    ::execl(kSimNode.c_str(), "sim_node", "--scene", scene.c_str(), "--mode", "offline",
            "--duration", "1e6", "--csv", dir.c_str(), static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  // wait until it is stepping (a few rows in status.csv), at most 30 s
  constexpr auto kStartTimeout = std::chrono::seconds(30);
  const auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
  while (Lines(ReadFile(csv / "status.csv")).size() < 3 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_NE(ReadFile(out).find("sim_node: steady_tow: "), std::string::npos) << ReadFile(out);
  // every file ends with a complete row
  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv", "status.csv"}) {
    const std::string text = ReadFile(csv / file);
    ASSERT_FALSE(text.empty()) << file;
    EXPECT_EQ(text.back(), '\n') << file;
  }
}

// --- the offline node and its DDS program (app/node/node_main.h; docs/benchmarks.md "Start-up") --

// an offline run loads no DDS, iceoryx or OpenSSL library: the dynamic loader's own list of the
// libraries it loads (LD_DEBUG=libs, written to LD_DEBUG_OUTPUT.<pid> for the shell and for
// sim_node) names the C library and none of them
TEST(SimNodeCliTest, OfflineLoadsNoDdsLibrary) {
  TempDir tmp;
  WriteFile(tmp.path() / "good.yaml", kGoodScene);
  const fs::path logs = tmp.path() / "ld";
  fs::create_directories(logs);
  ::setenv("LD_DEBUG", "libs", 1);
  ::setenv("LD_DEBUG_OUTPUT", (logs / "libs").c_str(), 1);
  const SimNodeResult r =
      RunSimNode({"--scene", (tmp.path() / "good.yaml").string(), "--mode", "offline"}, tmp.path());
  ::unsetenv("LD_DEBUG");
  ::unsetenv("LD_DEBUG_OUTPUT");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string libs;  // the loader's log of the sim_node process
  for (const fs::directory_entry& log : fs::directory_iterator(logs)) {
    const std::string text = ReadFile(log.path());
    if (text.find("initialize program: " + kSimNode) != std::string::npos) libs = text;
  }
  ASSERT_NE(libs.find("libc.so.6"), std::string::npos) << "no LD_DEBUG=libs log of sim_node";
  for (const char* library : {"libddsc", "libiceoryx", "libssl", "libcrypto"}) {
    EXPECT_EQ(libs.find(library), std::string::npos) << library << " loaded:\n" << libs;
  }
}

// sim_node and its DDS program laid out as installed (P/bin/sim_node,
// P/libexec/towsim/sim_node_dds): a DDS mode runs in the DDS program, found from sim_node's own
// place; without it, exit 1 naming the places looked at. Domain 197 (tests/integration/README.md)
TEST(SimNodeCliTest, DdsModesRunInTheDdsProgram) {
  TempDir tmp;
  WriteFile(tmp.path() / "good.yaml", kGoodScene);
  const fs::path bin = tmp.path() / "bin";
  const fs::path libexec = tmp.path() / "libexec" / "towsim";
  fs::create_directories(bin);
  fs::copy_file(kSimNode, bin / "sim_node");
  const std::string command = ShellQuote((bin / "sim_node").string()) + " --scene " +
                              ShellQuote((tmp.path() / "good.yaml").string()) +
                              " --mode fast --duration 0.5 --domain 197 </dev/null >" +
                              ShellQuote((tmp.path() / "out.txt").string()) + " 2>" +
                              ShellQuote((tmp.path() / "err.txt").string());
  ::setenv("CYCLONEDDS_URI", "file://" TOWSIM_SOURCE_DIR "/config/cyclonedds.xml", 1);
  int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = ReadFile(tmp.path() / "err.txt");
  EXPECT_NE(
      err.find("sim_node: error: --mode fast: the DDS modes run in sim_node_dds, which is "
               "not installed (looked for " +
               (bin / "sim_node_dds").string() + ", " + (libexec / "sim_node_dds").string() + ")"),
      std::string::npos)
      << err;

  fs::create_directories(libexec);
  fs::copy_file(fs::path(kSimNode).parent_path() / "sim_node_dds", libexec / "sim_node_dds");
  status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << ReadFile(tmp.path() / "err.txt");
  EXPECT_NE(ReadFile(tmp.path() / "out.txt").find("sim_node: cli_test: fast, 10 steps"),
            std::string::npos)
      << ReadFile(tmp.path() / "out.txt");
}

}  // namespace
