// The controllers' trials over loopback DDS: sim_node in lockstep on the paper's
// Case 1 scene (start from rest, no script) with real controller processes: the manoeuvre
// runner's zig-zag and turning circle, the autopilot's heading step and lawn-mower survey, the
// C example of docs/controllers.md. Every number the controllers report is checked against
// the node's own bodies.csv. Domains 70-75, 79 (tests/integration/README.md).

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/process.h"

namespace towsim::testing {
namespace {

const std::string kSource = TOWSIM_SOURCE_DIR;
const std::string kCase1 = kSource + "/config/scenes/case1_forward.yaml";
constexpr double kProcessTimeout = 60.0;  // [s] of wall time: a run that takes longer hung
constexpr double kDeg = 180.0 / M_PI;

struct Row {
  double t = 0, x = 0, y = 0, z = 0, yaw = 0, u = 0;
};

// the rows of one body from a bodies.csv
std::vector<Row> BodyRows(const std::string& csv, const std::string& body) {
  std::vector<Row> rows;
  std::stringstream in(csv);
  std::string line;
  std::getline(in, line);  // t,body,x,y,z,roll,pitch,yaw,u,...
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string field;
    std::vector<std::string> f;
    while (std::getline(s, field, ',')) f.push_back(field);
    if (f.size() < 9 || f[1] != body) continue;
    rows.push_back({std::stod(f[0]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4]),
                    std::stod(f[7]), std::stod(f[8])});
  }
  return rows;
}

// "key: value" lines of a flat YAML results file; lists stay text
std::map<std::string, std::string> ReadResults(const std::string& path) {
  std::map<std::string, std::string> m;
  std::stringstream in(ReadFile(path));
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(": ");
    if (colon != std::string::npos) m[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return m;
}

std::vector<double> ParseList(const std::string& text) {  // "[1, 2.5]"
  std::vector<double> v;
  std::string s = text;
  std::replace(s.begin(), s.end(), '[', ' ');
  std::replace(s.begin(), s.end(), ']', ' ');
  std::replace(s.begin(), s.end(), ',', ' ');
  std::stringstream in(s);
  double x;
  while (in >> x) v.push_back(x);
  return v;
}

struct TrialRun {
  std::vector<Row> tow;
  std::string controller_out;
};

// sim_node (lockstep, Case 1 without its script, from rest) with `controller` on the tow
// vehicle and towfish_depth --hold on the towfish (every commandable vehicle must answer)
TrialRun RunLockstep(int domain, std::vector<std::string> controller, double duration) {
  // ctest sets it (ENVIRONMENT); so does the test, for a run by hand: loopback DDS only
  setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
  const std::string csv = LogPrefix("csv");
  controller.insert(controller.end(), {"--domain", std::to_string(domain)});
  Process ctl(controller, LogPrefix("controller"));
  Process fish({TOWSIM_TOWFISH_DEPTH, "--hold", "--domain", std::to_string(domain)},
               LogPrefix("towfish_depth"));
  Process node({TOWSIM_SIM_NODE, "--scene", kCase1, "--mode", "lockstep", "--duration",
                std::to_string(duration), "--domain", std::to_string(domain), "--set", "script=[]",
                "--csv", csv},
               LogPrefix("node"));
  TrialRun run;
  EXPECT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_TRUE(ctl.Wait(10.0)) << ctl.command_line();
  EXPECT_EQ(ctl.exit_code(), 0) << ctl.err();
  EXPECT_TRUE(fish.Wait(10.0));
  // every step was answered in time: no failsafe, no lockstep timeout
  EXPECT_NE(node.out().find("failsafes 0,"), std::string::npos) << node.out();
  EXPECT_NE(node.out().find("lockstep timeouts 0,"), std::string::npos) << node.out();
  run.tow = BodyRows(ReadFile(csv + "/bodies.csv"), "tow_vehicle");
  run.controller_out = ctl.out();
  EXPECT_FALSE(run.tow.empty());
  if (!run.tow.empty()) {
    EXPECT_NEAR(run.tow.back().t, duration, 1e-6);
  }
  return run;
}

// domain 70: the 10/10 zig-zag runs to completion; its sheet matches the node's track
TEST(ControllerTrials, ZigZag10x10CompletesAndItsOvershootsMatchTheTrack) {
  const std::string results = LogPrefix("results.yaml");
  const TrialRun run =
      RunLockstep(70,
                  {TOWSIM_MANEUVER_RUNNER, "--config",
                   kSource + "/config/maneuvers/zigzag_10_10.yaml", "--results", results},
                  130.0);
  if (HasFailure()) return;
  std::printf("%s", run.controller_out.c_str());
  auto r = ReadResults(results);
  EXPECT_EQ(r["completed"], "true");
  const std::vector<double> overshoots = ParseList(r["overshoot_deg"]);
  const std::vector<double> periods = ParseList(r["period"]);
  ASSERT_EQ(overshoots.size(), 4u);
  ASSERT_EQ(periods.size(), 2u);
  // independent: the heading change's extremes in the node's bodies.csv (10 Hz), each past
  // +-10 deg by the overshoot; at an extreme the yaw rate is zero, so 0.1 s sampling costs
  // < 0.5 |psi''| dt^2 ~ 0.01 deg; the runner rounds to 4 digits
  constexpr double kPeakTol = 0.05;  // [deg]
  const double psi0 = std::find_if(run.tow.begin(), run.tow.end(), [](const Row& w) {
                        return w.t >= 55.0 - 1e-9;
                      })->yaw;
  std::vector<double> peaks;  // |heading change| at each local extreme after execute
  std::vector<double> change;
  for (const Row& w : run.tow) {
    if (w.t >= 55.0 - 1e-9) change.push_back(std::remainder(w.yaw - psi0, 2 * M_PI) * kDeg);
  }
  for (size_t i = 1; i + 1 < change.size(); ++i) {
    const bool max = change[i] > change[i - 1] && change[i] >= change[i + 1] && change[i] > 10;
    const bool min = change[i] < change[i - 1] && change[i] <= change[i + 1] && change[i] < -10;
    if (max || min) peaks.push_back(std::abs(change[i]));
  }
  ASSERT_GE(peaks.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(overshoots[k], peaks[k] - 10.0, kPeakTol) << "overshoot " << k + 1;
    // sensible for a vehicle that answers its rudder within ~2 s: a few degrees
    EXPECT_GT(overshoots[k], 1.0);
    EXPECT_LT(overshoots[k], 10.0);
  }
  for (double p : periods) {
    EXPECT_GT(p, 4.0);
    EXPECT_LT(p, 20.0);
  }
}

// the heading change of a track interpolated where it crosses `angle` [deg], returning y
double YAtHeadingChange(const std::vector<Row>& tow, double t0, double angle) {
  double psi0 = 0, last = 0, change = 0;
  bool started = false;
  const Row* prev = nullptr;
  double prev_change = 0;
  for (const Row& w : tow) {
    if (w.t < t0 - 1e-9) continue;
    if (!started) psi0 = last = w.yaw, started = true;
    change += std::remainder(w.yaw - last, 2 * M_PI) * kDeg;
    last = w.yaw;
    if (prev != nullptr && prev_change < angle && change >= angle) {
      const double a = (angle - prev_change) / (change - prev_change);
      return prev->y + a * (w.y - prev->y);
    }
    prev = &w;
    prev_change = change;
  }
  (void)psi0;
  return NAN;
}

// domain 71: turning circle, 20 deg of rudder; the sheet's tactical and steady diameters
// against the track in bodies.csv
TEST(ControllerTrials, TurningCircleDiametersMatchTheTrack) {
  const std::string results = LogPrefix("results.yaml");
  const TrialRun run =
      RunLockstep(71,
                  {TOWSIM_MANEUVER_RUNNER, "--config",
                   kSource + "/config/maneuvers/turning_circle_20.yaml", "--results", results},
                  150.0);
  if (HasFailure()) return;
  std::printf("%s", run.controller_out.c_str());
  auto r = ReadResults(results);
  ASSERT_TRUE(r.count("tactical_diameter") && r.count("steady_diameter")) << ReadFile(results);
  const double tactical = std::stod(r["tactical_diameter"]);
  const double steady = std::stod(r["steady_diameter"]);
  const double kinematic = std::stod(r["kinematic_diameter"]);
  // from the CSV (start heading 0 = north, so the transfer is y): y where the heading change
  // reaches 180 deg; chords of ~1.1 deg at 10 Hz: interpolation error < R (0.02)^2 / 8 + the
  // runner's 20 Hz samples: 0.05 m
  constexpr double kTrackTol = 0.05;  // [m]
  EXPECT_NEAR(tactical, YAtHeadingChange(run.tow, 55.0, 180.0), kTrackTol);
  // steady circle: the east-west extent of the track over its last 40 s (> 1 circle of
  // ~27 s), whose extremes at 10 Hz are within R (1 - cos(1.1 deg)) = 5 mm of the circle;
  // the circle drifts little once steady (the fit and the extent agree to 1 %)
  double ymin = 1e300, ymax = -1e300;
  for (const Row& w : run.tow) {
    if (w.t < 110.0) continue;
    ymin = std::min(ymin, w.y);
    ymax = std::max(ymax, w.y);
  }
  EXPECT_NEAR(steady, ymax - ymin, 0.01 * steady);
  EXPECT_NEAR(steady, kinematic, 0.01 * steady);  // 2 U / r: the same circle
  // the paper's Case 2 turning radius of the tow vehicle is 24.5 m (docs/verification.md) at
  // the same rudder
  EXPECT_NEAR(steady / 2, 24.5, 1.0);
}

// domain 72: the autopilot holds 6 m/s and, after a heading step 0 -> 30 deg at 60 s, the new
// heading: within 2 deg and 2 % after settling (from bodies.csv)
TEST(ControllerTrials, AutopilotHoldsHeadingWithin2DegAndSpeedWithin2Percent) {
  const TrialRun run = RunLockstep(
      72, {TOWSIM_AUTOPILOT, "--config", kSource + "/config/autopilot/heading_step.yaml"}, 120.0);
  if (HasFailure()) return;
  constexpr double kHeadingTol = 2.0;  // [deg]
  constexpr double kSpeedTol = 0.02;   // relative
  double worst_heading = 0, worst_speed = 0, worst_before = 0;
  for (const Row& w : run.tow) {
    if (w.t >= 40.0 && w.t < 60.0) {  // settled on the first setpoint (north)
      worst_before = std::max(worst_before, std::abs(w.yaw * kDeg));
      worst_speed = std::max(worst_speed, std::abs(w.u - 6.0) / 6.0);
    }
    if (w.t >= 80.0) {  // 20 s after the step
      worst_heading = std::max(worst_heading, std::abs(w.yaw * kDeg - 30.0));
      worst_speed = std::max(worst_speed, std::abs(w.u - 6.0) / 6.0);
    }
  }
  std::printf(
      "autopilot: heading error <= %.3f deg (t >= 80 s), %.3f deg (40-60 s); speed "
      "error <= %.3f %%\n",
      worst_heading, worst_before, 100 * worst_speed);
  EXPECT_LT(worst_heading, kHeadingTol);
  EXPECT_LT(worst_before, kHeadingTol);
  EXPECT_LT(worst_speed, kSpeedTol);
}

// domain 73: a lawn-mower of 2 legs of 250 m, 100 m apart: every waypoint reached, checked on
// the track, and the second leg followed
TEST(ControllerTrials, AutopilotLawnMowerReachesItsWaypoints) {
  const TrialRun run = RunLockstep(73,
                                   {TOWSIM_AUTOPILOT, "--speed", "6", "--legs", "2", "--leg-length",
                                    "250", "--spacing", "100", "--survey-origin", "50,0", "--turn",
                                    "starboard", "--acceptance-radius", "30", "--lookahead", "60"},
                                   150.0);
  if (HasFailure()) return;
  std::printf("%s", run.controller_out.c_str());
  const std::vector<std::pair<double, double>> waypoints = {
      {50, 0}, {300, 0}, {300, 100}, {50, 100}};
  for (size_t i = 0; i < waypoints.size(); ++i) {
    double closest = 1e300;
    for (const Row& w : run.tow) {
      closest = std::min(closest, std::hypot(w.x - waypoints[i].first, w.y - waypoints[i].second));
    }
    // taken within the 30 m acceptance circle (10 Hz rows: 0.6 m apart)
    EXPECT_LT(closest, 30.0 + 0.6) << "waypoint " << i + 1;
    EXPECT_NE(run.controller_out.find("waypoint " + std::to_string(i + 1) + " ("),
              std::string::npos);
  }
  EXPECT_EQ(run.controller_out.find("not reached"), std::string::npos) << run.controller_out;
  // the return leg (y = 100, southbound, x from 300 to 50) is followed: the turn onto it
  // (tactical diameter ~48 m for 100 m of spacing) overshoots the line by ~5 m, which LOS
  // then decays like exp(-s / lookahead); on the leg's second half (x < 175 m, >= 80 m after
  // the overshoot) the error is below 1 m (measured 0.66 m at its start)
  constexpr double kOvershootTol = 10.0;  // [m] anywhere on the leg
  constexpr double kCrossTrackTol = 1.0;  // [m] on its second half
  double worst_leg = 0, worst_half = 0;
  int n = 0;
  for (const Row& w : run.tow) {
    const bool southbound = std::abs(std::remainder(w.yaw - M_PI, 2 * M_PI)) < 0.5;
    if (!southbound || w.y < 50 || w.x > 290 || w.x < 50) continue;
    worst_leg = std::max(worst_leg, std::abs(w.y - 100));
    if (w.x < 175) worst_half = std::max(worst_half, std::abs(w.y - 100)), ++n;
  }
  std::printf(
      "lawn-mower return leg: cross-track error <= %.2f m, <= %.2f m on its second "
      "half\n",
      worst_leg, worst_half);
  EXPECT_GT(n, 150);  // 125 m at 6 m/s: 20 s of rows at 10 Hz
  EXPECT_LT(worst_leg, kOvershootTol);
  EXPECT_LT(worst_half, kCrossTrackTol);
}

// domain 74: the C example of docs/controllers.md drives the tow vehicle to the speed of the
// offline run at the same thrust
TEST(ControllerTrials, HelloControllerInCReachesTheOfflineSpeed) {
  const double duration = 60.0;
  const TrialRun run = RunLockstep(74, {TOWSIM_HELLO_CONTROLLER, "74", "4165", "0"}, duration);
  if (HasFailure()) return;
  // (RunLockstep appends --domain 74: the example reads only its first 3 arguments)
  const std::string dir = LogPrefix("offline_csv");
  Process offline({TOWSIM_SIM_NODE, "--scene", kCase1, "--mode", "offline", "--duration",
                   std::to_string(duration), "--csv", dir},
                  LogPrefix("offline"));
  ASSERT_TRUE(offline.Wait(kProcessTimeout));
  ASSERT_EQ(offline.exit_code(), 0) << offline.err();
  const std::vector<Row> reference = BodyRows(ReadFile(dir + "/bodies.csv"), "tow_vehicle");
  ASSERT_FALSE(reference.empty());
  constexpr double kSpeedTol = 0.03;  // relative
  EXPECT_NEAR(run.tow.back().u, reference.back().u, kSpeedTol * reference.back().u);
  EXPECT_GT(reference.back().u, 5.5);  // the offline run is at speed (6 m/s at 4165 N)
  EXPECT_LT(std::abs(run.tow.back().yaw * kDeg), 1.0);
}

// domain 75: the towfish's altitude mode. The tow vehicle runs Case 1 (4165 N, from rest);
// towfish_depth holds the towfish 10 m above a seabed at 38 m that shoals to 33 m between
// s = 500 and 900 m of run (piecewise linear). The reference is computed here from the
// towfish's own track in bodies.csv: s = its horizontal distance run, target depth =
// seabed(s) - altitude. Measured: the altitude within 0.05 m on the flat part, the towfish
// lagging the 1.25 % slope by ~0.2 m of depth.
TEST(ControllerTrials, TowfishAltitudeModeFollowsAShoalingSeabed) {
  constexpr int kDomain = 75;
  constexpr double kAltitude = 10.0;       // [m]
  constexpr double kSettled = 110.0;       // [s] the towfish has come up from its vertical start
  constexpr double kFlatTolerance = 0.3;   // [m] altitude error over the flat seabed
  constexpr double kSlopeTolerance = 0.8;  // [m] while the seabed shoals (tracking lag)
  setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
  const std::string csv = LogPrefix("csv");
  const std::string d = std::to_string(kDomain);
  Process runner({TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--thrust", "4165", "--domain", d},
                 LogPrefix("runner"));
  Process fish({TOWSIM_TOWFISH_DEPTH, "--altitude", "10", "--seabed-profile", "0:38,500:38,900:33",
                "--domain", d},
               LogPrefix("towfish_depth"));
  Process node({TOWSIM_SIM_NODE, "--scene", kCase1, "--mode", "lockstep", "--duration", "220",
                "--domain", d, "--set", "script=[]", "--csv", csv},
               LogPrefix("node"));
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_TRUE(runner.Wait(10.0));
  EXPECT_TRUE(fish.Wait(10.0));
  EXPECT_EQ(fish.exit_code(), 0) << fish.err();
  EXPECT_NE(node.out().find("failsafes 0,"), std::string::npos) << node.out();

  auto seabed = [](double s) {  // the profile above
    if (s <= 500.0) return 38.0;
    if (s >= 900.0) return 33.0;
    return 38.0 + (s - 500.0) / 400.0 * (33.0 - 38.0);
  };
  const std::vector<Row> fish_rows = BodyRows(ReadFile(csv + "/bodies.csv"), "towfish");
  ASSERT_GT(fish_rows.size(), 2000u);
  double s = 0.0, worst_flat = 0.0, worst_slope = 0.0, s_end = 0.0;
  for (size_t i = 0; i < fish_rows.size(); ++i) {
    if (i > 0) {
      s += std::hypot(fish_rows[i].x - fish_rows[i - 1].x, fish_rows[i].y - fish_rows[i - 1].y);
    }
    if (fish_rows[i].t < kSettled) continue;
    const double error = std::fabs(seabed(s) - fish_rows[i].z - kAltitude);
    double& worst = s <= 500.0 ? worst_flat : worst_slope;
    worst = std::max(worst, error);
    s_end = s;
  }
  std::printf(
      "[ trials ] altitude mode: worst altitude error %.3f m (flat), %.3f m (slope), "
      "run %.0f m\n",
      worst_flat, worst_slope, s_end);
  ASSERT_GT(s_end, 800.0) << "the run must reach the sloping part of the seabed";
  EXPECT_LT(worst_flat, kFlatTolerance);
  EXPECT_LT(worst_slope, kSlopeTolerance);
}

// domain 113: towfish_depth --altitude with no --seabed-* flag reads the node's own altimeter
// (<ns>/towfish/altitude, sensor_msgs/Range) over a plane seabed that shoals along the tow:
// Case 3's steady tow without its waves, the bed 40 m deep at the origin rising 0.5 deg toward
// north (d = 40 - tan(0.5 deg) x). The reference is the plane's closed form at the towfish's
// own track in bodies.csv, not the message the controller read.
TEST(ControllerTrials, TowfishAltitudeModeReadsTheSimsAltimeter) {
  constexpr int kDomain = 113;
  constexpr double kAltitude = 15.0;  // [m]
  constexpr double kSettled = 60.0;   // [s] the towfish has dived from its 25 m of altitude
  // [m] the depth loop lags a rising target (0.24 m on the 1.25 % slope of the test above; this
  // slope is 0.87 %); measured 0.073 m (0.068 m with the vertical altimeter before the beam
  // ran along the body's z axis). Holding the depth instead would miss by the 4+ m the bed
  // rises
  constexpr double kTolerance = 0.3;
  constexpr double kSlope = 0.00872687;  // tan(0.5 deg)
  setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
  const std::string csv = LogPrefix("csv");
  const std::string d = std::to_string(kDomain);
  Process runner({TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--thrust", "4165", "--domain", d},
                 LogPrefix("runner"));
  // gains for a 6 m/s tow: the defaults (set on Case 1's run from rest) limit-cycle +-1.3 m
  // here even at a constant --depth 21 (measured; the elevator's lift grows as U^2); these
  // hold --depth 21 within 0.01 m in this scene
  Process fish({TOWSIM_TOWFISH_DEPTH, "--altitude", "15", "--kp", "0.05", "--kd", "0.25",
                "--domain", d},
               LogPrefix("towfish_depth"));
  Process node(
      {TOWSIM_SIM_NODE, "--scene", kSource + "/config/scenes/case3_waves.yaml", "--mode",
       "lockstep", "--duration", "150", "--domain", d, "--set", "script=[]", "--set",
       "environment.waves=null", "--set",
       "environment.seabed={depth: 40, slope_deg: 0.5, slope_direction_deg: 180}", "--csv", csv},
      LogPrefix("node"));
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  ASSERT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_TRUE(runner.Wait(10.0));
  EXPECT_TRUE(fish.Wait(10.0));
  EXPECT_EQ(fish.exit_code(), 0) << fish.err();
  EXPECT_EQ(fish.err().find("warning"), std::string::npos) << fish.err();
  EXPECT_NE(node.out().find("failsafes 0,"), std::string::npos) << node.out();

  const std::vector<Row> rows = BodyRows(ReadFile(csv + "/bodies.csv"), "towfish");
  ASSERT_GT(rows.size(), 1000u);
  double worst = 0.0, deepest = 0.0;
  for (const Row& r : rows) {
    const double altitude = 40.0 - kSlope * r.x - r.z;  // the plane below the towfish
    if (r.t < kSettled) continue;
    worst = std::max(worst, std::fabs(altitude - kAltitude));
    deepest = std::max(deepest, r.z);
  }
  std::printf(
      "[ trials ] altimeter mode: worst altitude error %.3f m after %.0f s, bed rose "
      "%.1f m, towfish rose %.1f m\n",
      worst, kSettled, kSlope * (rows.back().x - rows.front().x), deepest - rows.back().z);
  EXPECT_LT(worst, kTolerance);
  // the target moved: the towfish followed the rising bed (not a depth held by chance)
  EXPECT_GT(kSlope * (rows.back().x - rows.front().x), 4.0);
  EXPECT_GT(deepest - rows.back().z, 3.0);
}

// domain 79 (no DDS traffic: they exit before creating a participant): bad configuration
TEST(ControllerTrials, BadConfigurationExits2NamingTheKey) {
  const std::string bad = LogPrefix("bad.yaml");
  {
    std::FILE* f = std::fopen(bad.c_str(), "w");
    std::fputs("maneuver: zigzag\nrudder_dg: 10\n", f);
    std::fclose(f);
  }
  struct Case {
    std::vector<std::string> argv;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{TOWSIM_MANEUVER_RUNNER, "--config", bad}, "rudder_dg = 10 ("},
      {{TOWSIM_MANEUVER_RUNNER, "--maneuver", "zigzag", "--heading-deg", "0"},
       "--heading-deg 0: must be in (0, 180)"},
      {{TOWSIM_AUTOPILOT, "--legs", "0"}, "--legs 0: must be an integer"},
      {{TOWSIM_AUTOPILOT, "--bogus", "1"}, "unknown option --bogus"},
      {{TOWSIM_TOWFISH_DEPTH, "--altitude", "30", "--seabed-depth", "20"},
       "--seabed-depth 20: must be > --altitude"},
      {{TOWSIM_TOWFISH_DEPTH, "--altitude", "30", "--seabed-depth", "40", "--seabed-profile",
        "0:40"},
       "--seabed-depth and --seabed-profile: give one of them"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> argv = c.argv;
    argv.insert(argv.end(), {"--domain", "79"});
    Process p(argv, LogPrefix("bad"));
    ASSERT_TRUE(p.Wait(10.0));
    EXPECT_EQ(p.exit_code(), 2) << p.command_line();
    EXPECT_NE(p.err().find(c.message), std::string::npos) << p.err();
  }
}

}  // namespace
}  // namespace towsim::testing
