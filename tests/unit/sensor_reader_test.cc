// bodies.<name>.sensors (scene/sensor_reader.h, docs/scene_format.md): what the keys become in
// core::BodySensors, their defaults, and every rule broken once, each with the key, the value
// and the rule in the message.

#include <string>

#include <gtest/gtest.h>

#include "core/sensor_model.h"
#include "scene/config_error.h"
#include "scene/scene_loader.h"

namespace towsim::scene {
namespace {

const std::string kConfig = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";

// two spheres on a cable; `ball` and `buoy` the extra keys of their entries
std::string Scene(const std::string& ball, const std::string& buoy = "") {
  return "name: s\n"
         "time: {step: 0.05, duration: 1, output_rate: 10}\n"
         "cable: {length: 20, elements: 4, diameter: 0.041, density: 1300, youngs_modulus: 7e8,\n"
         "        start: {body: buoy}, end: {body: ball}}\n"
         "bodies:\n"
         "  buoy: {type: sphere, mass: 10, volume: 0.5, position: [0, 0, 0]" +
         buoy +
         "}\n"
         "  ball: {type: sphere, mass: 50, volume: 0.01, position: [0, 0, 20]" +
         ball + "}\n";
}

core::Model Load(const std::string& yaml) { return LoadSceneFromString(yaml, "t.yaml", kConfig); }

std::string Error(const std::string& yaml) {
  try {
    Load(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(SensorReader, AbsentMeansNoSensorErrors) { EXPECT_TRUE(Load(Scene("")).sensors.empty()); }

TEST(SensorReader, KeysBecomeTheSensorErrors) {
  const core::Model m = Load(Scene(
      ", sensors: {altimeter: {noise: 0.1, bias: -0.2, rate: 5, latency_steps: 3, dropout: 0.05, "
      "seed: 9}, pressure: {noise: 50}, odometry: {noise: 0.5, bias: 1, velocity_noise: 0.02, "
      "velocity_bias: -0.01, rate: 2}}"));
  ASSERT_EQ(m.sensors.size(), 1u);
  const core::BodySensors& s = m.sensors[0];
  EXPECT_EQ(s.body, "ball");
  ASSERT_TRUE(s.altimeter && s.pressure && s.odometry);
  EXPECT_EQ(s.altimeter->noise, 0.1);
  EXPECT_EQ(s.altimeter->bias, -0.2);
  EXPECT_EQ(s.altimeter->rate, 5.0);
  EXPECT_EQ(s.altimeter->latency_steps, 3);
  EXPECT_EQ(s.altimeter->dropout, 0.05);
  EXPECT_EQ(s.altimeter->seed, 9u);
  // defaults
  EXPECT_EQ(s.pressure->noise, 50.0);
  EXPECT_EQ(s.pressure->bias, 0.0);
  EXPECT_EQ(s.pressure->rate, 0.0);
  EXPECT_EQ(s.pressure->latency_steps, 0);
  EXPECT_EQ(s.pressure->dropout, 0.0);
  EXPECT_EQ(s.pressure->seed, core::DefaultSensorSeed("ball", "pressure"));
  EXPECT_EQ(s.odometry->noise, 0.5);
  EXPECT_EQ(s.odometry->bias, 1.0);
  EXPECT_EQ(s.odometry->velocity_noise, 0.02);
  EXPECT_EQ(s.odometry->velocity_bias, -0.01);
  EXPECT_EQ(s.odometry->rate, 2.0);
}

TEST(SensorReader, DefaultSeedsDifferBetweenBodies) {
  const core::Model m =
      Load(Scene(", sensors: {altimeter: {noise: 1}}", ", sensors: {altimeter: {noise: 1}}"));
  ASSERT_EQ(m.sensors.size(), 2u);
  EXPECT_NE(m.sensors[0].altimeter->seed, m.sensors[1].altimeter->seed);
  EXPECT_FALSE(m.sensors[0].pressure.has_value());
}

TEST(SensorReader, EveryRuleNamesKeyValueAndRule) {
  struct Case {
    std::string keys, expected;
  };
  const Case cases[] = {
      {"altimeter: {noise: -0.1}", "bodies.ball.sensors.altimeter.noise = -0.1"},
      {"altimeter: {noise: -0.1}", "must be >= 0"},
      {"pressure: {dropout: 1}", "bodies.ball.sensors.pressure.dropout = 1"},
      {"pressure: {dropout: 1}", "must be < 1"},
      {"pressure: {dropout: -0.5}", "must be >= 0"},
      {"altimeter: {latency_steps: 1.5}", "bodies.ball.sensors.altimeter.latency_steps = 1.5"},
      {"altimeter: {latency_steps: -1}", "bodies.ball.sensors.altimeter.latency_steps = -1"},
      {"altimeter: {rate: 0}", "bodies.ball.sensors.altimeter.rate = 0"},
      {"altimeter: {rate: 0}", "must be > 0"},
      {"odometry: {rate: 25}", "must be <= the step rate 1 / time.step = 20 Hz"},
      {"altimeter: {seed: -3}", "bodies.ball.sensors.altimeter.seed = -3"},
      {"altimeter: {bias: .nan}", "bodies.ball.sensors.altimeter.bias"},
      {"altimeter: {noize: 1}", "did you mean noise?"},
      {"altimeter: {velocity_noise: 1}", "bodies.ball.sensors.altimeter.velocity_noise"},
      {"altimeter: {velocity_noise: 1}", "unknown key"},
      {"sonar: {noise: 1}", "bodies.ball.sensors.sonar"},
      {"sonar: {noise: 1}", "allowed: altimeter, pressure, odometry"},
  };
  for (const Case& c : cases) {
    const std::string error = Error(Scene(", sensors: {" + c.keys + "}"));
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.keys << "\n  got: " << error;
  }
}

}  // namespace
}  // namespace towsim::scene
