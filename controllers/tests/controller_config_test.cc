// The controllers' configuration: manoeuvre and autopilot settings from flags and
// YAML files, with errors that name the key or flag, its value, file:line and the rule; the
// shipped files in config/maneuvers and config/autopilot load.

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "autopilot/autopilot_config.h"
#include "common/config_file.h"
#include "common/flags.h"
#include "common/laws.h"
#include "maneuver_runner/maneuver_config.h"

namespace towsim::controllers {
namespace {

const std::string kSource = TOWSIM_SOURCE_DIR;

std::string WriteTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/towsim_ctlcfg_" + name;
  std::ofstream(path) << text;
  return path;
}

Flags Parse(std::vector<std::string> args, const std::vector<std::string>& known,
            const std::vector<std::string>& switches) {
  static std::vector<std::string> storage;
  storage = args;
  storage.insert(storage.begin(), "prog");
  static std::vector<char*> argv;
  argv.clear();
  for (auto& s : storage) argv.push_back(s.data());
  return Flags(static_cast<int>(argv.size()), argv.data(), known, switches);
}

ManeuverConfig Maneuver(std::vector<std::string> args) {
  return ResolveManeuver(Parse(args, ManeuverFlagNames(), ManeuverSwitchNames()));
}

AutopilotConfig Autopilot(std::vector<std::string> args) {
  return ResolveAutopilot(Parse(args, AutopilotFlagNames(), AutopilotSwitchNames()));
}

template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(ManeuverConfig, DefaultsPerManeuverAndFlags) {
  ManeuverConfig c = Maneuver({});
  EXPECT_EQ(c.kind, ManeuverKind::kUTurn);
  EXPECT_EQ(c.rudder_deg, 20);
  c = Maneuver({"--maneuver", "zigzag"});
  EXPECT_EQ(c.rudder_deg, 10);
  EXPECT_EQ(c.heading_deg, 10);
  EXPECT_EQ(c.reversals, 4);
  c = Maneuver({"--maneuver=zigzag", "--rudder-deg", "20", "--heading-deg", "20", "--port-first",
                "--reversals", "6"});
  EXPECT_EQ(c.rudder_deg, 20);
  EXPECT_EQ(c.heading_deg, 20);
  EXPECT_TRUE(c.port_first);
  EXPECT_EQ(c.reversals, 6);
  EXPECT_EQ(Maneuver({"--maneuver", "case1"}).rudder_deg, 0);
}

TEST(ManeuverConfig, FileThenFlagsWin) {
  const std::string f = WriteTemp("zz.yaml",
                                  "maneuver: zigzag\nrudder_deg: 20\nheading_deg: 20\n"
                                  "thrust: 4000\nstart: 40\n");
  ManeuverConfig c = Maneuver({"--config", f});
  EXPECT_EQ(c.kind, ManeuverKind::kZigZag);
  EXPECT_EQ(c.rudder_deg, 20);
  EXPECT_EQ(c.thrust, 4000);
  EXPECT_EQ(c.start, 40);
  c = Maneuver({"--config", f, "--thrust", "4165", "--maneuver", "turning_circle"});
  EXPECT_EQ(c.kind, ManeuverKind::kTurningCircle);
  EXPECT_EQ(c.thrust, 4165);
  EXPECT_EQ(c.rudder_deg, 20);  // from the file, over the turning circle's default
}

TEST(ManeuverConfig, ErrorsNameTheKeyValueLineAndRule) {
  const std::string typo = WriteTemp("typo.yaml", "maneuver: zigzag\nrudder_dg: 10\n");
  EXPECT_EQ(ErrorOf([&] {
              Maneuver({"--config", typo});
            }),
            "rudder_dg = 10 (towsim_ctlcfg_typo.yaml:2): unknown key (allowed: maneuver, body, "
            "thrust, start, rudder_deg, heading_deg, until_yaw_deg, until_turn_deg, reversals, "
            "port_first, tow_speed, from_length, to_length, payout_rate, hold, towfish, "
            "sample_period)");
  const std::string bad = WriteTemp("bad.yaml", "maneuver: zigzag\nheading_deg: -5\n");
  EXPECT_EQ(ErrorOf([&] {
              Maneuver({"--config", bad});
            }),
            "heading_deg = -5 (towsim_ctlcfg_bad.yaml:2): must be in (0, 180) (the zig-zag's "
            "switch angle)");
  const std::string kind = WriteTemp("kind.yaml", "maneuver: spiral\n");
  EXPECT_NE(ErrorOf([&] {
              Maneuver({"--config", kind});
            }).find("maneuver = spiral (towsim_ctlcfg_kind.yaml:1): must be one of"),
            std::string::npos);
  EXPECT_EQ(ErrorOf([&] {
              Maneuver({"--maneuver", "zigzag", "--reversals", "2.5"});
            }),
            "--reversals 2.5: must be an integer from 1 to 100");
  EXPECT_EQ(ErrorOf([&] {
              Maneuver({"--maneuver", "spiral"});
            }),
            "--maneuver spiral: must be one of case1, uturn, zigzag, turning_circle, payout");
  EXPECT_NE(ErrorOf([&] {
              Maneuver({"--config", "/nonexistent.yaml"});
            }).find("cannot read"),
            std::string::npos);
}

TEST(ManeuverConfig, ShippedFilesLoad) {
  for (const char* name : {"zigzag_10_10", "zigzag_20_20", "turning_circle_20", "uturn"}) {
    const std::string path = kSource + "/config/maneuvers/" + name + ".yaml";
    EXPECT_EQ(ErrorOf([&] { Maneuver({"--config", path}); }), "") << path;
  }
  const ManeuverConfig c = Maneuver({"--config", kSource + "/config/maneuvers/zigzag_20_20.yaml"});
  EXPECT_EQ(c.kind, ManeuverKind::kZigZag);
  EXPECT_EQ(c.rudder_deg, 20);
  EXPECT_EQ(c.heading_deg, 20);
}

TEST(AutopilotConfig, FlagsSurveyAndSchedule) {
  AutopilotConfig c = Autopilot({"--speed", "5", "--heading-deg", "190"});
  EXPECT_EQ(c.initial.speed, 5);
  EXPECT_NEAR(c.initial.heading, Rad(-170), 1e-12);
  EXPECT_FALSE(c.follow_waypoints);
  EXPECT_FALSE(c.gains.depth_enabled);
  c = Autopilot({"--legs", "2", "--leg-length", "300", "--spacing", "100", "--survey-origin",
                 "50,0", "--turn", "port"});
  ASSERT_TRUE(c.follow_waypoints);
  ASSERT_EQ(c.waypoints.size(), 4u);
  EXPECT_NEAR(c.waypoints[1].x, 350, 1e-9);
  EXPECT_NEAR(c.waypoints[2].y, -100, 1e-9);  // port of north: west
  const std::string f = WriteTemp("ap.yaml",
                                  "speed: 6\nheading_deg: 0\nschedule:\n"
                                  "  - {at: 60, heading_deg: 30}\n  - {at: 90, speed: 5}\n");
  c = Autopilot({"--config", f});
  EXPECT_NEAR(SetpointAt(c, 59.9).heading, 0, 1e-12);
  EXPECT_NEAR(SetpointAt(c, 60).heading, Rad(30), 1e-12);
  EXPECT_EQ(SetpointAt(c, 60).speed, 6);
  EXPECT_EQ(SetpointAt(c, 100).speed, 5);
  EXPECT_NEAR(SetpointAt(c, 100).heading, Rad(30), 1e-12);
}

TEST(AutopilotConfig, ErrorsNameTheKeyValueLineAndRule) {
  const std::string f = WriteTemp("ap_bad.yaml", "speed: 6\nschedule:\n  - {at: 60, hdg: 30}\n");
  EXPECT_NE(ErrorOf([&] {
              Autopilot({"--config", f});
            }).find("schedule[0].hdg = 30 (towsim_ctlcfg_ap_bad.yaml:3): unknown key"),
            std::string::npos);
  const std::string g = WriteTemp("ap_turn.yaml", "survey_legs: 2\nsurvey_turn: left\n");
  EXPECT_EQ(ErrorOf([&] {
              Autopilot({"--config", g});
            }),
            "survey_turn = left (towsim_ctlcfg_ap_turn.yaml:2): must be starboard or port");
  EXPECT_EQ(ErrorOf([&] {
              Autopilot({"--legs", "0"});
            }),
            "--legs 0: must be an integer from 1 to 1000");
  EXPECT_EQ(ErrorOf([&] {
              Autopilot({"--legs", "2", "--survey-origin", "5"});
            }),
            "--survey-origin 5: must be X,Y [m] (world NED)");
  EXPECT_EQ(ErrorOf([&] { Autopilot({"--lookahead", "-1"}); }), "--lookahead -1: must be > 0 [m]");
}

TEST(AutopilotConfig, ShippedFilesLoad) {
  for (const char* name : {"heading_step", "survey"}) {
    const std::string path = kSource + "/config/autopilot/" + name + ".yaml";
    EXPECT_EQ(ErrorOf([&] { Autopilot({"--config", path}); }), "") << path;
  }
}

}  // namespace
}  // namespace towsim::controllers
