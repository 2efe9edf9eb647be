// The cable in a current, held to independent references (docs/environment.md):
//   - Galilean invariance: the steady-tow scene's cable held at a fixed point in a uniform
//     current -U gives the same motion, shape and tension, relative to its top, as the same
//     cable towed at U through still water. The two runs share nothing but the physics: one
//     has every node moving and the water at rest, the other the water moving past a fixed
//     top; drag on the relative velocity and generalized-alpha (exact for motion linear in
//     time) make them the same problem.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "scene/scene_loader.h"

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
  ASSERT_TRUE(towed.cable.start.velocity.isApprox(u));
  const Model held = scene::LoadScene(
      kSteadyTow, {"environment.current=[-6, 0, 0]", "cable.start={fixed: [0, 0, 3.5]}",
                   "cable.initial_velocity=[0, 0, 0]", "bodies.towfish.velocity=[0, 0, 0]"});
  Simulation a(towed), b(held);
  double worst_shape = 0.0, worst_tension = 0.0, scale_tension = 0.0;
  for (int step = 1; step <= 1200; ++step) {  // 60 s of the swing-back transient
    ASSERT_TRUE(a.Step().ok());
    ASSERT_TRUE(b.Step().ok());
    if (step % 20) continue;
    const Vec3 top_a = towed.cable.start.position + a.time() * u;
    for (int i = 0; i < a.num_nodes(); ++i) {
      const Vec3 ra = a.node_position(i) - top_a, rb = b.node_position(i) - held.cable.start.position;
      worst_shape = std::max(worst_shape, (ra - rb).norm());
      worst_tension = std::max(worst_tension, std::abs(a.node_tension(i) - b.node_tension(i)));
      scale_tension = std::max(scale_tension, a.node_tension(i));
    }
  }
  std::printf("Galilean check over 60 s: shape %.2e m, tension %.2e N (of %.1f N)\n", worst_shape,
              worst_tension, scale_tension);
  EXPECT_LT(worst_shape, kGalileanRelTol * towed.cable.length);
  EXPECT_LT(worst_tension, kGalileanRelTol * scale_tension);
}

}  // namespace
}  // namespace towsim::core
