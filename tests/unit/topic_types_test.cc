// sim_node/app/common/topic_types: the topics of a node the recorder and the Foxglove bridge
// subscribe to, from the wire's topic table: per body, per cable (SceneInfo.cables; none
// listed: the one cable "cable") and of the node.

#include "app/common/topic_types.h"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "towsim_msgs.h"

namespace towsim::app {
namespace {

std::vector<std::string> Names(const std::vector<NodeTopic>& topics) {
  std::vector<std::string> out;
  for (const NodeTopic& t : topics) out.push_back(t.dds_name);
  return out;
}

bool Has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(NodeTopicsTest, TheOneCableKeepsItsName) {
  const wire::TopicNames names("/towsim");
  const std::vector<NodeTopic> one = NodeTopics(names, {"towfish"});
  const std::vector<std::string> n = Names(one);
  EXPECT_TRUE(Has(n, "rt/towsim/cable/state"));
  EXPECT_TRUE(Has(n, "rt/towsim/towfish/odom"));
  EXPECT_FALSE(Has(n, "rt/towsim/scene_info"));
  // named for every body: a recorder or bridge subscribes to it, the node writes the
  // commanded vehicles' (docs/topics.md "Actuator state")
  EXPECT_TRUE(Has(n, "rt/towsim/towfish/actuator_state"));
  // listing the one cable by name gives the same topics, in the same order
  EXPECT_EQ(Names(NodeTopics(names, {"towfish"}, false, {"cable"})), n);
  for (const NodeTopic& t : one) {
    if (t.dds_name == "rt/towsim/cable/state") {
      EXPECT_EQ(t.descriptor, &towsim_msgs_msg_dds__CableState__desc);
      EXPECT_FALSE(t.transient_local);
    }
  }
}

TEST(NodeTopicsTest, ANetworkHasTheStateOfEveryCable) {
  const wire::TopicNames names("/towsim");
  const std::vector<NodeTopic> topics =
      NodeTopics(names, {"depressor", "towfish"}, true, {"main", "tether"});
  const std::vector<std::string> n = Names(topics);
  EXPECT_EQ(n.front(), "rt/towsim/scene_info");
  EXPECT_TRUE(Has(n, "rt/towsim/main/state"));
  EXPECT_TRUE(Has(n, "rt/towsim/tether/state"));
  EXPECT_FALSE(Has(n, "rt/towsim/cable/state"));
  EXPECT_TRUE(Has(n, "rt/towsim/depressor/cable_force"));
  int cable_states = 0;
  for (const NodeTopic& t : topics) {
    cable_states += t.descriptor == &towsim_msgs_msg_dds__CableState__desc;
  }
  EXPECT_EQ(cable_states, 2);
  // each cable's end forces (docs/topics.md "Cable end forces"), named for every cable: a
  // recorder or bridge subscribes to them all, the node writes those of its held ends
  for (const char* c : {"main", "tether"}) {
    EXPECT_TRUE(Has(n, std::string("rt/towsim/") + c + "/start_force")) << c;
    EXPECT_TRUE(Has(n, std::string("rt/towsim/") + c + "/end_force")) << c;
  }
  // one more cable, three more topics: its state and its two end forces
  EXPECT_EQ(topics.size(), NodeTopics(names, {"depressor", "towfish"}, true, {"main"}).size() + 3);
}

// several winches (docs/winch_dds.md "Several winches on the wire"): one command topic each,
// named by the winch; without the list, the one winch's winch/command as before
TEST(NodeTopicsTest, EveryWinchHasItsCommandTopic) {
  const wire::TopicNames names("/towsim");
  const std::vector<std::string> one = Names(NodeTopics(names, {"fish"}, false, {"main"}));
  EXPECT_TRUE(Has(one, "rt/towsim/winch/command"));
  const std::vector<std::string> two = Names(NodeTopics(
      names, {"fish"}, false, {"port", "starboard"}, {"port_winch", "starboard_winch"}));
  EXPECT_TRUE(Has(two, "rt/towsim/port_winch/command"));
  EXPECT_TRUE(Has(two, "rt/towsim/starboard_winch/command"));
  EXPECT_FALSE(Has(two, "rt/towsim/winch/command"));
  // one more cable (its state and its two end forces) and one more winch command
  EXPECT_EQ(two.size(), one.size() + 4);
}

}  // namespace
}  // namespace towsim::app
