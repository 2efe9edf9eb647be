// app/foxglove/foxglove_commands: the rules a client's message must meet before it is written on
// DDS (docs/foxglove.md): every Teleop Twist field finite, nothing after the sample but padding,
// and the throttle of the notes on stderr; the 3D panel's standard topics taken and ignored,
// any other topic still refused (one participant on DDS domain 199, tests/integration/README.md).

#include "app/foxglove/foxglove_commands.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

TEST(FoxgloveCommands, NonFiniteTwistFieldNamesTheFirstOne) {
  geometry_msgs_msg_dds__Twist_ t{};
  EXPECT_EQ(NonFiniteTwistField(t), "");
  t.linear.x = 4165.0;
  t.angular.z = -0.2;
  EXPECT_EQ(NonFiniteTwistField(t), "");
  t.angular.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(NonFiniteTwistField(t), "angular.y is not finite (inf)");
  t.linear.x = std::nan("");
  EXPECT_EQ(NonFiniteTwistField(t), "linear.x is not finite (nan)");
}

TEST(FoxgloveCommands, OnlyPaddingToAMultipleOfFourMayFollowTheSample) {
  EXPECT_EQ(TrailingBytes(52, 52), "");  // a Twist: 4 + 6 x 8 bytes
  EXPECT_EQ(TrailingBytes(40, 40), "");
  EXPECT_EQ(TrailingBytes(33, 34), "");  // shorter: Cyclone's own rule
  EXPECT_EQ(TrailingBytes(37, 37), "");
  EXPECT_EQ(TrailingBytes(40, 37), "");  // 3 bytes of padding to 40
  EXPECT_EQ(TrailingBytes(41, 37), "4 bytes after the 37-byte sample (only padding to a "
                                   "multiple of 4 may follow)");
  EXPECT_EQ(TrailingBytes(60, 52), "8 bytes after the 52-byte sample (only padding to a "
                                   "multiple of 4 may follow)");
}

constexpr uint32_t kDomain = 199;

foxglove::ClientChannel Channel(uint32_t id, const std::string& topic, const std::string& schema,
                                const std::string& encoding = "cdr") {
  foxglove::ClientChannel c;
  c.id = id;
  c.topic = topic;
  c.schema_name = schema;
  c.encoding = encoding;
  return c;
}

TEST(FoxgloveCommands, PanelTopicsAreTakenAndIgnoredOthersStillRefused) {
  setenv("CYCLONEDDS_URI", "file://" TOWSIM_SOURCE_DIR "/config/cyclonedds.xml", 1);
  const dds::Participant participant(kDomain, "");
  FoxgloveCommands commands(participant, wire::TopicNames("/towsim"), {"tow_vehicle"}, {});
  // what Foxglove's 3D panel advertises when it opens, in both spellings of the schema and
  // whatever the encoding: taken
  EXPECT_EQ(commands.Advertise(Channel(1, "/move_base_simple/goal", "geometry_msgs/msg/PoseStamped")),
            "");
  EXPECT_EQ(commands.Advertise(Channel(2, "/clicked_point", "geometry_msgs/msg/PointStamped")), "");
  EXPECT_EQ(commands.Advertise(Channel(3, "/initialpose",
                                       "geometry_msgs/msg/PoseWithCovarianceStamped")),
            "");
  EXPECT_EQ(commands.Advertise(Channel(4, "/clicked_point", "geometry_msgs/PointStamped", "json")),
            "");
  // their messages: accepted, written nowhere, counted; the payload is not read
  const uint8_t bytes[] = {0, 1, 0, 0, 1, 2, 3, 4};
  const char* panel[] = {"/move_base_simple/goal", "/clicked_point", "/initialpose"};
  for (const char* topic : panel) {
    const FoxgloveServer::Verdict v =
        commands.Publish(Channel(9, topic, "geometry_msgs/msg/PoseStamped"), bytes, sizeof bytes);
    EXPECT_EQ(v.error, "") << topic;
    EXPECT_FALSE(v.malformed) << topic;
  }
  EXPECT_EQ(commands.ignored(), 3u);
  EXPECT_EQ(commands.malformed(), 0u);

  // a panel topic with another schema: refused, naming the rule
  EXPECT_EQ(commands.Advertise(Channel(5, "/clicked_point", "geometry_msgs/msg/PoseStamped")),
            "schema geometry_msgs/msg/PoseStamped: must be geometry_msgs/msg/PointStamped (the 3D "
            "panel's topic, taken and ignored)");
  // topics nobody may command: still refused at advertise, each on its own
  for (const char* topic : {"/cmd_vel", "/towsim/towfish/command", "/towsim/status",
                            "/goal_pose", "/towsim/clicked_point"}) {
    const std::string e = commands.Advertise(Channel(6, topic, "geometry_msgs/msg/Twist"));
    EXPECT_EQ(e.rfind("not a topic clients may publish on (", 0), 0u) << topic << ": " << e;
  }
  // and a message on one of them is not written either
  EXPECT_EQ(commands.Publish(Channel(6, "/cmd_vel", "geometry_msgs/msg/Twist"), bytes, sizeof bytes)
                .error,
            "not advertised: /cmd_vel");
  EXPECT_EQ(commands.ignored(), 3u);
  // the vehicle's own command topic is taken as before
  EXPECT_EQ(commands.Advertise(
                Channel(7, "/towsim/tow_vehicle/command", "towsim_msgs/msg/ActuatorCommand")),
            "");
}

}  // namespace
}  // namespace towsim::app
