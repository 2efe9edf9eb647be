// The cable in a current, held to independent references (docs/environment.md):
//   - Galilean invariance: the steady-tow scene's cable held at a fixed point in a uniform
//     current -U gives the same motion, shape and tension, relative to its top, as the same
//     cable towed at U through still water. The two runs share nothing but the physics: one
//     has every node moving and the water at rest, the other the water moving past a fixed
//     top; drag on the relative velocity and generalized-alpha (exact for motion linear in
//     time) make them the same problem.
//   - a steady tow in a depth-varying current: the static towed shape (cable.initial = static,
//     solved in the frame moving with the tow point) against the independent steady-state
//     integration of towed_cable_steady.h with the same profile, and the dynamics started
//     from it staying there.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "scene/scene_loader.h"
#include "towed_cable_steady_core.h"

namespace towsim::core {
namespace {

const std::string kSteadyTow = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/steady_tow.yaml";

// both runs solve the same equations to the Newton tolerance 1e-8 x 200 m; positions relative
// to the top and tensions then agree to that tolerance amplified by the transient's
// sensitivity (a few hundred steps of a damped system): 1e-6 relative is two orders above the
// differences observed and far below any physical effect
constexpr double kGalileanRelTol = 1e-6;

TEST(CurrentCore, HeldInACurrentIsTowedThroughStillWater) {
  const Vec3 u(6.0, 0.0, 0.0);
  const Model towed = scene::LoadScene(kSteadyTow);
  ASSERT_TRUE(towed.cables[0].start.velocity.isApprox(u));
  const Model held = scene::LoadScene(
      kSteadyTow, {"environment.current=[-6, 0, 0]", "cable.start={fixed: [0, 0, 3.5]}",
                   "cable.initial_velocity=[0, 0, 0]", "bodies.towfish.velocity=[0, 0, 0]"});
  Simulation a(towed), b(held);
  double worst_shape = 0.0, worst_tension = 0.0, scale_tension = 0.0;
  for (int step = 1; step <= 1200; ++step) {  // 60 s of the swing-back transient
    ASSERT_TRUE(a.Step().ok());
    ASSERT_TRUE(b.Step().ok());
    if (step % 20) continue;
    const Vec3 top_a = towed.cables[0].start.position + a.time() * u;
    for (int i = 0; i < a.num_nodes(); ++i) {
      const Vec3 ra = a.node_position(i) - top_a,
                 rb = b.node_position(i) - held.cables[0].start.position;
      worst_shape = std::max(worst_shape, (ra - rb).norm());
      worst_tension = std::max(worst_tension, std::abs(a.NodeTension(i) - b.NodeTension(i)));
      scale_tension = std::max(scale_tension, a.NodeTension(i));
    }
  }
  std::printf("Galilean check over 60 s: shape %.2e m, tension %.2e N (of %.1f N)\n", worst_shape,
              worst_tension, scale_tension);
  EXPECT_LT(worst_shape, kGalileanRelTol * towed.cables[0].length);
  EXPECT_LT(worst_tension, kGalileanRelTol * scale_tension);
}

// a sheared current crossing the cable: 0.8 m/s ahead at the surface, turning to 0.4 m/s
// across the tow at 60 m and -0.3 m/s (astern) below 180 m; linear between the rows
const std::vector<std::string> kShearedTow = {
    "cable.initial=static",
    "environment.current={profile: [[0, [0.8, 0, 0]], [60, [0.2, 0.4, 0]], [180, [-0.3, 0, 0]]]}"};

TEST(CurrentCore, SteadyTowInADepthVaryingCurrent) {
  const Model model = scene::LoadScene(kSteadyTow, kShearedTow);
  ASSERT_FALSE(model.environment.current.IsUniform());
  const reference::TowedCableSolution ref =
      reference::SolveTowedCableSteady(reference::SteadyTowProblem(model));
  Simulation sim(model);
  const reference::SteadyTowSample s0 = reference::MeasureSteadyTow(sim);
  const Vec3 side = sim.body_position(0) - (model.cables[0].start.position);
  // 20 elements against the converged reference: discretization error only (as for the
  // uniform current in steady_tow_core_test), and the profile's kinks inside elements, which
  // 5-point Gauss quadrature integrates to O(l^2) of the slope jump: 1e-3
  constexpr double kShearedRelTol = 1e-3;
  std::printf(
      "sheared steady tow: layback %.4f (ref %.4f) m, depth %.4f (ref %.4f) m, tension "
      "%.2f (ref %.2f) N, sideways %.4f m\n",
      s0.layback, ref.layback, s0.depth, ref.depth, s0.tension, ref.top_tension, side.y());
  EXPECT_NEAR(s0.layback, ref.layback, kShearedRelTol * ref.layback);
  EXPECT_NEAR(s0.depth, ref.depth, kShearedRelTol * ref.depth);
  EXPECT_NEAR(s0.tension, ref.top_tension, kShearedRelTol * ref.top_tension);
  // the shape is three-dimensional: the cross-current pushes the sphere sideways (+y)
  EXPECT_GT(side.y(), 1.0);
  // 10 s later: the static state is a solution of the dynamics in the same current
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(sim.Step().ok());
  const reference::SteadyTowSample s1 = reference::MeasureSteadyTow(sim);
  constexpr double kStayRelTol = 1e-6;
  EXPECT_NEAR(s1.layback, s0.layback, kStayRelTol * s0.layback);
  EXPECT_NEAR(s1.depth, s0.depth, kStayRelTol * s0.depth);
  EXPECT_NEAR(s1.tension, s0.tension, kStayRelTol * s0.tension);
}

}  // namespace
}  // namespace towsim::core
