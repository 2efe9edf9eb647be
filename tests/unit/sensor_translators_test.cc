// sim_node/dds/sensor_translators: a body's altimeter (sensor_msgs/Range) and pressure sensor
// (sensor_msgs/FluidPressure) at t = 0, where the body's position is the scene's and the
// surface elevation is the regular wave's closed form a cos(phase) at x = y = t = 0.

#include "dds/sensor_translators.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/simulation.h"
#include "dds/translators.h"
#include "hanging_sphere_scene.h"
#include "scene/scene_loader.h"
#include "wave_number_bisection.h"

namespace towsim::dds {
namespace {

using core::kPi;
// the range is a float32: round-off 2^-24 relative (2^-23 allowed)
constexpr double kFloatRelTol = 1.0 / (1 << 23);
// the pressure: a few ulps of 3e5 Pa
constexpr double kPressureTol = 1e-8;

core::Model Load(const std::string& environment) { return test::LoadHangingSphere(environment); }

TEST(SensorTranslators, AltitudeAbovePlaneSeabedAndPressureBelowTheWave) {
  const core::Model model = Load(
      "environment:\n"
      "  water_density: 1025\n"
      "  gravity: 9.81\n"
      "  waves: {regular: {height: 1.5, period: 8, direction_deg: 0, phase_deg: 60}}\n"
      "  seabed: {depth: 40, slope_deg: 5, slope_direction_deg: 90}\n");
  const core::Simulation sim(model);
  RangeMessage range("ball");
  ToAltitude(sim, 0, &range.msg);
  // a sphere's beam points straight down (its frame stays aligned with the world): the plane
  // d(x, y) = 40 + tan(5 deg) (x cos 90 + y sin 90) at (3, 4); the ball at z = 20
  const double bed = 40.0 + std::tan(5.0 * kPi / 180.0) * 4.0;
  EXPECT_NEAR(range.msg.range, bed - 20.0, kFloatRelTol * (bed - 20.0));
  EXPECT_EQ(range.msg.radiation_type, sensor_msgs_msg_dds__Range_Constants_ULTRASOUND);
  EXPECT_FLOAT_EQ(range.msg.field_of_view, 0.1f);
  EXPECT_EQ(range.msg.min_range, 0.0f);
  EXPECT_EQ(range.msg.max_range, 200.0f);
  EXPECT_STREQ(range.msg.header.frame_id, "ball");
  EXPECT_EQ(range.msg.header.stamp.sec, 0);
  EXPECT_EQ(range.msg.header.stamp.nanosec, 0u);

  FluidPressureMessage pressure("ball");
  ToPressure(sim, 0, &pressure.msg);
  // eta at (3, 4), t = 0: a cos(k x + phase) (waves toward north); k from the deep-water
  // w^2 / g, which at kh = 2.5 (h = 40 m) is 1.4 % below the exact dispersion relation's k the
  // core uses: 0.003 rad of phase at x = 3 m, within 1 % of a
  const double eta = sim.SurfaceElevationAt(0);
  const double k_deep = std::pow(2.0 * kPi / 8.0, 2) / 9.81;
  EXPECT_NEAR(eta, 0.75 * std::cos(k_deep * 3.0 + kPi / 3.0), 0.75 * 0.01);
  // linear theory's total pressure at z = 20 m under the one regular wave, in closed form:
  // p_atm + rho g z + rho g a cosh(k (h - z)) / cosh(k h) cos(k x + phase), h = 40 m (the
  // plane's depth under the origin), k by bisection of w^2 = g k tanh(k h) (not the core's
  // Newton iteration)
  const double k = test::BisectWaveNumber(2.0 * kPi / 8.0, 40.0, 9.81);
  const double p_dynamic = 1025.0 * 9.81 * 0.75 * std::cosh(k * (40.0 - 20.0)) /
                           std::cosh(k * 40.0) * std::cos(k * 3.0 + kPi / 3.0);
  EXPECT_NEAR(pressure.msg.fluid_pressure, 101325.0 + 1025.0 * 9.81 * 20.0 + p_dynamic,
              kPressureTol * 3e5);
  // the dynamic pressure is 30 % of the hydrostatic head of eta at this depth: the sensor does
  // not read the instantaneous depth z + eta (that would be 2 kPa more here)
  EXPECT_GT(std::abs(1025.0 * 9.81 * eta - p_dynamic), 1000.0);
  EXPECT_EQ(pressure.msg.variance, 0.0);
  EXPECT_EQ(range.msg.variance, 0.0f);
  EXPECT_STREQ(pressure.msg.header.frame_id, "ball");

  // stamps are simulation time
  core::Simulation later(model);
  ASSERT_TRUE(later.Step().ok());
  ToAltitude(later, 0, &range.msg);
  ToPressure(later, 0, &pressure.msg);
  EXPECT_EQ(FromTimeMsg(range.msg.header.stamp), 0.05);
  EXPECT_EQ(FromTimeMsg(pressure.msg.header.stamp), 0.05);
}

TEST(SensorTranslators, NoEchoIsPlusInfinity) {
  RangeMessage range("ball");
  // no seabed: REP 117's +inf (nothing detected)
  const core::Simulation bottomless(Load(""));
  ToAltitude(bottomless, 0, &range.msg);
  EXPECT_EQ(range.msg.range, std::numeric_limits<float>::infinity());
  // a bed 480 m below the ball, beyond max_range 200 m: +inf too
  const core::Simulation deep(Load("environment: {seabed: {depth: 500}}\n"));
  ToAltitude(deep, 0, &range.msg);
  EXPECT_EQ(range.msg.range, std::numeric_limits<float>::infinity());
  // calm water without a seabed: the pressure is atmospheric + rho g z
  FluidPressureMessage pressure("ball");
  ToPressure(bottomless, 0, &pressure.msg);
  EXPECT_NEAR(pressure.msg.fluid_pressure, 101325.0 + 1025.0 * 9.81 * 20.0, kPressureTol * 3e5);
}

TEST(SensorTranslators, PressureAboveTheSurfaceIsAtmosphericAndInACrestHydrostatic) {
  // a sphere 0.5 m above the mean surface: under a 4 m crest (phase 0 at x = 3 m shifted to
  // the crest) it is wet, at a trough dry
  auto at = [](double phase_deg) {
    std::string scene = std::string(test::kHangingSphereScene) +
                        "environment:\n  waves: {regular: {height: 4, period: 8, phase_deg: " +
                        std::to_string(phase_deg) + "}}\n";
    scene.replace(scene.find("position: [3, 4, 20]"), 20, "position: [3, 4, -0.5]");
    scene.replace(scene.find("fixed: [3, 4, 0]"), 16, "fixed: [3, 4, -20.5]");
    return scene::LoadSceneFromString(scene, "sensor_translators.yaml",
                                      std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
  };
  const double k_deep = std::pow(2.0 * kPi / 8.0, 2) / 9.81;  // no seabed: deep water
  const double crest_phase_deg = -k_deep * 3.0 * 180.0 / kPi;  // k x + phase = 0 at x = 3
  FluidPressureMessage pressure("ball");
  const core::Simulation crest(at(crest_phase_deg));
  ToPressure(crest, 0, &pressure.msg);
  // in the crest (vertical stretching: the kinematics at z = 0, p_d = rho g eta): the head
  // below the instantaneous surface, rho g (z + eta) = rho g (2 - 0.5)
  EXPECT_NEAR(pressure.msg.fluid_pressure, 101325.0 + 1025.0 * 9.81 * 1.5, kPressureTol * 3e5);
  const core::Simulation trough(at(crest_phase_deg + 180.0));
  ToPressure(trough, 0, &pressure.msg);
  EXPECT_EQ(pressure.msg.fluid_pressure, 101325.0);  // dry: the atmosphere
}

}  // namespace
}  // namespace towsim::dds
