// app/foxglove/foxglove_layout (docs/foxglove.md "A layout for any scene"): the layout of a
// scene names exactly the topics the node publishes for it (the node's list,
// app/common/topic_types.h NodeTopics, from the wire's table), every plotted array index is a
// node of the built system, its camera frames the initial system, and the shipped
// config/foxglove/towsim.json is the generator's output for Case 1.

#include "app/foxglove/foxglove_layout.h"

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/common/topic_types.h"
#include "core/simulation.h"
#include "dds/translators.h"
#include "hanging_sphere_scene.h"
#include "scene/scene_loader.h"

namespace towsim::app {
namespace {

using Json = nlohmann::json;

std::string Scene(const std::string& name) {
  return std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + name;
}

// the topics a layout names: the 3D panel's, the plots' (before the first '.') and Teleop's
std::set<std::string> LayoutTopics(const Json& layout) {
  std::set<std::string> topics;
  for (const auto& [id, panel] : layout.at("configById").items()) {
    if (id.rfind("3D!", 0) == 0) {
      for (const auto& [topic, shown] : panel.at("topics").items()) topics.insert(topic);
    } else if (id.rfind("Plot!", 0) == 0) {
      for (const Json& p : panel.at("paths")) {
        const std::string v = p.at("value");
        topics.insert(v.substr(0, v.find('.')));
      }
    } else if (id.rfind("Teleop!", 0) == 0) {
      topics.insert(panel.at("topic").get<std::string>());
    }
  }
  return topics;
}

// the checks of a scene's layout against the node's topics and the built system
void CheckLayout(const core::Model& model) {
  SCOPED_TRACE(model.name);
  const wire::TopicNames names("/towsim");
  const Json layout = Json::parse(FoxgloveLayoutJson(model, names));
  const core::Simulation sim(model);

  // the node's topics for this scene, as towsim_record and the bridge list them
  std::vector<std::string> bodies, cables, winches;
  for (int b = 0; b < sim.num_bodies(); ++b) bodies.push_back(sim.body_name(b));
  for (int c = 0; c < sim.num_cables(); ++c) cables.push_back(sim.cable_name(c));
  for (int w = 0; w < sim.num_winches(); ++w) winches.push_back(sim.winch_name(w));
  std::set<std::string> node, expected;
  for (const NodeTopic& t : NodeTopics(names, bodies, true, cables, winches)) {
    const std::string ros = wire::RosTopicName(t.dds_name);
    node.insert(ros);
    // what the layout shows: every body's odometry, every cable's state, markers and tf
    for (const std::string& b : bodies) {
      if (ros == "/towsim/" + b + "/odom") expected.insert(ros);
    }
    for (const std::string& c : cables) {
      if (ros == "/towsim/" + c + "/state") expected.insert(ros);
    }
    if (ros == "/towsim/markers" || ros == "/tf" || ros == "/tf_static") expected.insert(ros);
  }
  for (const core::Vehicle& v : model.vehicles) {  // Teleop: the first commanded vehicle
    if (!dds::IsCommandable(v.params)) continue;
    expected.insert("/towsim/" + v.name + "/command");
    break;
  }
  const std::set<std::string> shown = LayoutTopics(layout);
  EXPECT_EQ(shown, expected);
  for (const std::string& t : shown) EXPECT_EQ(node.count(t), 1u) << t << " not a node topic";

  // every array index of a plot path: a node of its cable in the built system; the bottom
  // node is the last one (a winched cable: [-1], the last whatever the drum paid out)
  const std::regex indexed(R"(^/towsim/(\w+)/state\.tensions\[(-?\d+)\]$)");
  int bottoms = 0;
  for (const Json& p : layout.at("configById").at("Plot!tension").at("paths")) {
    std::smatch m;
    const std::string v = p.at("value");
    ASSERT_TRUE(std::regex_match(v, m, indexed)) << v;
    int c = 0;
    while (c < sim.num_cables() && sim.cable_name(c) != m[1].str()) ++c;
    ASSERT_LT(c, sim.num_cables()) << v;
    const int index = std::stoi(m[2].str());
    if (index == -1) {
      EXPECT_TRUE(model.cables[c].winch.has_value()) << v;
    } else {
      EXPECT_GE(index, 0) << v;
      EXPECT_LT(index, sim.num_nodes(c)) << v;
    }
    if (p.at("label").get<std::string>().find("bottom") != std::string::npos) {
      ++bottoms;
      if (index != -1) {
        EXPECT_EQ(index, sim.num_nodes(c) - 1) << v;
      }
    }
  }
  EXPECT_EQ(bottoms, sim.num_cables());

  // the camera frames the system: every node and body of the initial state lies within the
  // sphere about the followed frame that the vertical field of view holds at the distance
  const Json& camera = layout.at("configById").at("3D!towsim").at("cameraState");
  EXPECT_EQ(camera.at("targetOffset"), Json::array({0, 0, 0}));
  const double radius = camera.at("distance").get<double>() *
                        std::sin(0.5 * camera.at("fovy").get<double>() * core::kPi / 180.0);
  const std::string follow = layout.at("configById").at("3D!towsim").at("followTf");
  int followed = -1;
  for (int b = 0; b < sim.num_bodies(); ++b) {
    if (sim.body_name(b) == follow) followed = b;
  }
  ASSERT_GE(followed, 0) << follow;
  const core::Vec3 origin = sim.body_position(followed);
  double farthest = 0.0;
  for (int c = 0; c < sim.num_cables(); ++c) {
    for (int i = 0; i < sim.num_nodes(c); ++i) {
      farthest = std::max(farthest, (sim.node_position(i, c) - origin).norm());
    }
  }
  for (int b = 0; b < sim.num_bodies(); ++b) {
    farthest = std::max(farthest, (sim.body_position(b) - origin).norm());
  }
  EXPECT_LE(farthest, radius);
  EXPECT_LT(camera.at("far").get<double>(), 1e5);
  EXPECT_GT(camera.at("far").get<double>(), camera.at("distance").get<double>() + radius);
}

TEST(FoxgloveLayout, TwoPartTowShowsEveryBodyAndCableTheNodePublishes) {
  const core::Model model = scene::LoadScene(Scene("two_part_tow.yaml"));
  ASSERT_EQ(model.cables.size(), 2u);
  CheckLayout(model);
}

TEST(FoxgloveLayout, OneBodySceneShowsItsBodyAndCable) {
  const core::Model model = test::LoadHangingSphere("");
  CheckLayout(model);
  const Json layout = Json::parse(FoxgloveLayoutJson(model, wire::TopicNames("/towsim")));
  // a sphere: no vehicle, so no speed plot and no Teleop; the 3D panel follows the sphere
  EXPECT_FALSE(layout.at("configById").contains("Plot!speed"));
  EXPECT_EQ(layout.at("configById").at("3D!towsim").at("followTf"), "ball");
  EXPECT_EQ(layout.at("configById").at("Plot!tension").at("paths").at(1).at("value"),
            "/towsim/cable/state.tensions[4]");
}

TEST(FoxgloveLayout, WinchSceneFollowsTheLastNode) {
  const core::Model model = scene::LoadScene(Scene("winch_tow.yaml"));
  ASSERT_TRUE(model.cables[0].winch.has_value());
  CheckLayout(model);
  const Json layout = Json::parse(FoxgloveLayoutJson(model, wire::TopicNames("/towsim")));
  EXPECT_EQ(layout.at("configById").at("Plot!tension").at("paths").at(1).at("value"),
            "/towsim/cable/state.tensions[-1]");
}

TEST(FoxgloveLayout, NamespaceNamesEveryTopic) {
  const core::Model model = scene::LoadScene(Scene("case1_forward.yaml"));
  const std::string text = FoxgloveLayoutJson(model, wire::TopicNames("/sys_a"));
  EXPECT_EQ(text.find("/towsim"), std::string::npos);
  EXPECT_NE(text.find("\"/sys_a/tow_vehicle/command\""), std::string::npos);
}

// the shipped layout is the generator's output for the scene it was made for, so the two
// cannot drift: regenerate it with
//   towsim_foxglove --layout config/scenes/case1_forward.yaml --output config/foxglove/towsim.json
TEST(FoxgloveLayout, ShippedLayoutIsTheGeneratorsOutputForCase1) {
  const core::Model model = scene::LoadScene(Scene("case1_forward.yaml"));
  CheckLayout(model);
  std::ifstream in(std::string(TOWSIM_SOURCE_DIR) + "/config/foxglove/towsim.json",
                   std::ios::binary);
  ASSERT_TRUE(in.good());
  std::stringstream shipped;
  shipped << in.rdbuf();
  EXPECT_EQ(shipped.str(), FoxgloveLayoutJson(model, wire::TopicNames("/towsim")));
}

}  // namespace
}  // namespace towsim::app
