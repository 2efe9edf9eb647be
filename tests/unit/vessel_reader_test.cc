// bodies.<name> of type vessel (docs/vessels.md "Scene keys"): what a scene's keys become in
// core::Vessel, the course entries of the script, and every rule broken once, each with the
// key, the value and the rule in the message.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "scene/config_error.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace towsim::scene {
namespace {

constexpr double kDeg = core::kPi / 180.0;

const std::string kConfig = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";

// a ship towing a sphere; `ship` its body entry's keys after the type, `script` the script
std::string Scene(const std::string& ship, const std::string& script = "",
                  const std::string& environment = "") {
  return "name: v\n"
         "time: {step: 0.05, duration: 100, output_rate: 10}\n" +
         environment +
         "cable: {length: 130, elements: 5, diameter: 0.03, density: 1300, youngs_modulus: 1e9,\n"
         "        initial: straight, start: {body: ship, at: [-28, 0, 1]}, end: {body: fish}}\n"
         "bodies:\n"
         "  ship: {type: vessel, " + ship + "}\n"
         "  fish: {type: sphere, mass: 400, volume: 0.2, position: [-120, 0, 40]}\n" +
         (script.empty() ? "" : "script:\n" + script);
}

std::string Error(const std::string& yaml, const std::string& dir = kConfig) {
  try {
    LoadSceneFromString(yaml, "t.yaml", dir);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(VesselReader, KeysBecomeTheVessel) {
  const core::Model m = LoadSceneFromString(
      Scene("position: [0, 0, 0], euler_deg: [0, 1, 30], speed: 4, max_acceleration: 0.02, "
            "max_yaw_acceleration_deg: 0.3, harmonic: [{dof: heave, amplitude: 1, period: 8}, "
            "{dof: roll, amplitude: 3, period: 10, phase_deg: 90}]",
            "  - {at: 10, body: ship, speed: 5}\n"
            "  - {at: 50, body: ship, heading_deg: 90, turn_rate_deg: 1}\n"
            "  - {at: 200, body: ship, turn_rate_deg: -0.5}\n"),
      "t.yaml", kConfig);
  ASSERT_EQ(m.vessels.size(), 1u);
  const core::Vessel& v = m.vessels[0];
  EXPECT_EQ(v.name, "ship");
  EXPECT_NEAR(v.euler.z(), 30 * kDeg, 1e-15);
  EXPECT_EQ(v.speed, 4.0);
  EXPECT_EQ(v.max_acceleration, 0.02);
  EXPECT_NEAR(v.max_yaw_acceleration, 0.3 * kDeg, 1e-15);
  ASSERT_EQ(v.harmonics.size(), 2u);
  EXPECT_EQ(v.harmonics[1].dof, core::VesselDof::kRoll);
  EXPECT_NEAR(v.harmonics[1].amplitude, 3 * kDeg, 1e-15);
  EXPECT_NEAR(v.harmonics[1].phase, 90 * kDeg, 1e-15);
  ASSERT_EQ(v.course.size(), 3u);
  EXPECT_TRUE(v.course[0].set_speed && !v.course[0].set_heading);
  EXPECT_TRUE(v.course[1].set_heading && v.course[1].set_turn_rate);
  EXPECT_NEAR(v.course[1].heading, 90 * kDeg, 1e-15);
  EXPECT_NEAR(v.course[2].turn_rate, -0.5 * kDeg, 1e-15);
  EXPECT_TRUE(m.script.empty());  // course entries are not commands
  // the cable holds the vessel, and starts with the vessel's velocity
  EXPECT_EQ(m.cables[0].start.kind, core::EndKind::kVessel);
  EXPECT_TRUE(m.cables[0].initial_velocity.isApprox(
      4.0 * Eigen::Vector3d(std::cos(30 * kDeg), std::sin(30 * kDeg), 0.0)));
  EXPECT_TRUE(SceneWarnings(m).empty());
}

TEST(VesselReader, ModelFileGivesTheRaosRelativeToItsFolder) {
  const core::Model m = LoadSceneFromString(
      Scene("model: ../vessels/survey_ship.yaml, position: [0, 0, 0], speed: 6"), "t.yaml",
      kConfig);
  const core::Vessel& v = m.vessels[0];
  ASSERT_TRUE(v.raos.has_value());
  EXPECT_TRUE(v.raos->periodic_directions);
  EXPECT_EQ(v.max_acceleration, 0.05);  // the file's
}

TEST(VesselReader, TimeHistoryGivesTheInitialPose) {
  test::TempDir dir;
  std::ofstream(dir.path() / "track.csv") << "t,x,y,z,roll,pitch,yaw\n0,5,6,0,0,0,0.5\n"
                                             "100,305,6,0,0,0,0.5\n";
  const core::Model m =
      LoadSceneFromString(Scene("time_history: track.csv"), "t.yaml", dir.path().string());
  const core::Vessel& v = m.vessels[0];
  ASSERT_TRUE(v.time_history.has_value());
  EXPECT_TRUE(v.position.isApprox(Eigen::Vector3d(5, 6, 0)));
  EXPECT_EQ(v.euler.z(), 0.5);
}

struct Broken {
  const char* name;
  std::string yaml;
  std::string expected;  // a part of the message: key, value and rule
};

class VesselReaderBroken : public ::testing::TestWithParam<Broken> {};

TEST_P(VesselReaderBroken, NamesKeyValueAndRule) {
  test::TempDir dir;
  std::ofstream(dir.path() / "track.csv") << "t,x,y,z,roll,pitch,yaw\n0,0,0,0,0,0,0\n"
                                             "50,100,0,0,0,0,0\n";
  std::ofstream(dir.path() / "narrow.csv") << "period,direction_deg,dof,amplitude,phase_deg\n"
                                              "6,180,heave,0.5,0\n10,180,heave,0.9,0\n";
  const std::string what = Error(GetParam().yaml, dir.path().string());
  EXPECT_NE(what.find(GetParam().expected), std::string::npos) << what;
}

const std::string kSea =
    "environment: {waves: {jonswap: {hs: 2, tp: 8, direction_deg: 180, components: 50}}}\n";

INSTANTIATE_TEST_SUITE_P(
    Table, VesselReaderBroken,
    ::testing::Values(
        Broken{"history_and_course", Scene("time_history: track.csv, speed: 3"),
               "bodies.ship.speed = 3 (t.yaml:6): a vessel with a time_history takes its whole "
               "motion from it"},
        Broken{"history_short", Scene("time_history: track.csv"),
               "bodies.ship.time_history = track.csv"},
        Broken{"external_with_raos", Scene("position: [0, 0, 0], external: true, raos: x.csv"),
               "bodies.ship.raos = x.csv (t.yaml:6): an external vessel's motion comes from "
               "another program"},
        Broken{"bad_dof", Scene("position: [0, 0, 0], harmonic: [{dof: bob, amplitude: 1, "
                                "period: 8}]"),
               "bodies.ship.harmonic[0].dof = bob"},
        Broken{"bad_period", Scene("position: [0, 0, 0], harmonic: [{dof: heave, amplitude: 1, "
                                   "period: 0}]"),
               "bodies.ship.harmonic[0].period = 0 (t.yaml:6): must be > 0"},
        Broken{"vehicle_key", Scene("position: [0, 0, 0], length: 3"),
               "bodies.ship.length = 3 (t.yaml:6): applies only to type: vehicle (this body is "
               "a vessel)"},
        Broken{"heading_without_rate",
               Scene("position: [0, 0, 0]", "  - {at: 5, body: ship, heading_deg: 90}\n"),
               "script[0].heading_deg = 90 (t.yaml:9): needs turn_rate_deg"},
        Broken{"thrust_on_vessel",
               Scene("position: [0, 0, 0]", "  - {at: 5, body: ship, thrust: 100}\n"),
               "script[0].thrust = 100 (t.yaml:9): does not apply to a vessel (ship)"},
        Broken{"when_on_vessel",
               Scene("position: [0, 0, 0]",
                     "  - {at: 5, when: \"ship.x >= 3\", body: ship, speed: 2}\n"),
               "script[0].when"},
        Broken{"course_of_history",
               Scene("time_history: track.csv", "  - {at: 5, body: ship, speed: 2}\n"),
               "ship takes its motion from its time_history"},
        Broken{"speed_on_sphere",
               Scene("position: [0, 0, 0]", "  - {at: 5, body: fish, speed: 2}\n"),
               "script[0].speed = 2 (t.yaml:9): applies only to a vessel's entry"},
        Broken{"raos_do_not_cover_the_sea",
               Scene("position: [0, 0, 0], speed: 3, raos: narrow.csv", "", kSea),
               "bodies.ship.raos = narrow.csv"},
        Broken{"extrapolation_without_raos",
               Scene("position: [0, 0, 0], rao_extrapolation: hold"),
               "bodies.ship.rao_extrapolation = hold (t.yaml:6): applies only with raos"}),
    [](const ::testing::TestParamInfo<Broken>& info) { return std::string(info.param.name); });

TEST(VesselReader, RaoExtrapolationHoldAdmitsTheSea) {
  test::TempDir dir;
  std::ofstream(dir.path() / "narrow.csv") << "period,direction_deg,dof,amplitude,phase_deg\n"
                                              "6,180,heave,0.5,0\n10,180,heave,0.9,0\n";
  const core::Model m = LoadSceneFromString(
      Scene("position: [0, 0, 0], speed: 3, raos: narrow.csv, rao_extrapolation: hold", "",
            kSea),
      "t.yaml", dir.path().string());
  EXPECT_TRUE(m.vessels[0].raos->extrapolate);
}

}  // namespace
}  // namespace towsim::scene
