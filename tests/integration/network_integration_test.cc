// A cable network on the wire (docs/topics.md, docs/contract.md §3): the real sim_node in fast
// mode with a two-part tow (tests/integration/scenes/network_two_part_tow.yaml: a driven tow
// point, the main cable to a depressor, a tether from the depressor to a towfish), watched
// through the test fixture (towsim::testing::SimNode, the wire library's decoders). SceneInfo
// lists both cables with their node counts; each cable's state comes on rt/<ns>/<cable>/state
// with its own nodes; the cable ends held by a body are where that body's odometry of the same
// step puts them; the one-cable topic rt/<ns>/cable/state does not exist. DDS domain 215.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/in_process_controller.h"
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

}  // namespace
}  // namespace towsim::testing
