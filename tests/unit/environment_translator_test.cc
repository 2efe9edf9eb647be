// sim_node/dds/environment_translator: the sea at a body (towsim_msgs/BodyEnvironment) against
// the closed form of one regular Airy wave over a plane seabed plus a uniform current, at
// t = 0 where the body's position is the scene's; no seabed gives a NaN altitude.

#include "dds/environment_translator.h"

#include <cmath>
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
// the closed forms evaluated here in another order than the core's sums: a few ulps of the
// largest term (1 m of elevation, 1 m/s of velocity, 40 m of depth)
constexpr double kRoundOffTol = 1e-12;

core::Model Load(const std::string& environment) { return test::LoadHangingSphere(environment); }

TEST(EnvironmentTranslator, RegularWaveCurrentAndPlaneSeabedAtTheBody) {
  // H 1.5 m, T 6 s travelling toward 30 deg, phase 40 deg; a plane bed 30 m under the origin
  // deepening 4 deg toward east; a current (0.5, -0.2, 0)
  const core::Simulation sim(Load(
      "environment:\n"
      "  current: [0.5, -0.2, 0]\n"
      "  waves: {regular: {height: 1.5, period: 6, direction_deg: 30, phase_deg: 40}}\n"
      "  seabed: {depth: 30, slope_deg: 4, slope_direction_deg: 90}\n"));
  BodyEnvironmentMessage env(kWorldFrame);
  ToBodyEnvironment(sim, 0, 17, &env.msg);

  // linear theory at (x, y, z) = (3, 4, 20), t = 0, over h = 30 m (the bed under the origin)
  const double a = 0.75, w = 2.0 * kPi / 6.0, h = 30.0, z = 20.0;
  const double b = 30.0 * kPi / 180.0;
  const double k = test::BisectWaveNumber(w, h, 9.81);
  const double th = k * (3.0 * std::cos(b) + 4.0 * std::sin(b)) + 40.0 * kPi / 180.0;
  const double eta = a * std::cos(th);
  const double u_h = a * w * std::cosh(k * (h - z)) / std::sinh(k * h) * std::cos(th);
  const double u_up = a * w * std::sinh(k * (h - z)) / std::sinh(k * h) * std::sin(th);
  EXPECT_NEAR(env.msg.wave_elevation, eta, kRoundOffTol);
  EXPECT_NEAR(env.msg.current.x, 0.5 + u_h * std::cos(b), kRoundOffTol);
  EXPECT_NEAR(env.msg.current.y, -0.2 + u_h * std::sin(b), kRoundOffTol);
  EXPECT_NEAR(env.msg.current.z, -u_up, kRoundOffTol);  // NED: down positive
  EXPECT_NEAR(env.msg.depth, z + eta, kRoundOffTol * 40.0);
  // the plane: d(x, y) = 30 + tan(4 deg) (x cos 90 + y sin 90)
  EXPECT_NEAR(env.msg.altitude, 30.0 + std::tan(4.0 * kPi / 180.0) * 4.0 - z,
              kRoundOffTol * 40.0);
  // the orbital velocity is in it: 0.2 m/s of it at 20 m under this wave
  EXPECT_GT(std::hypot(u_h, u_up), 0.05);

  EXPECT_EQ(env.msg.step, 17u);
  EXPECT_STREQ(env.msg.header.frame_id, "world_ned");
  EXPECT_EQ(env.msg.header.stamp.sec, 0);
  EXPECT_EQ(env.msg.header.stamp.nanosec, 0u);
}

TEST(EnvironmentTranslator, NoSeabedIsANanAltitudeAndStampsAreSimTime) {
  const core::Model model = Load("environment: {current: [0.3, 0, 0]}\n");
  core::Simulation sim(model);
  ASSERT_TRUE(sim.Step().ok());
  BodyEnvironmentMessage env(kWorldFrame);
  ToBodyEnvironment(sim, 0, 1, &env.msg);
  EXPECT_TRUE(std::isnan(env.msg.altitude));  // environment.csv: an empty field
  EXPECT_EQ(env.msg.wave_elevation, 0.0);     // calm surface
  EXPECT_EQ(env.msg.current.x, 0.3);
  EXPECT_EQ(env.msg.current.y, 0.0);
  EXPECT_EQ(env.msg.current.z, 0.0);
  EXPECT_EQ(env.msg.depth, sim.body_position(0).z());
  EXPECT_EQ(FromTimeMsg(env.msg.header.stamp), 0.05);
}

}  // namespace
}  // namespace towsim::dds
