// sim_node/app/foxglove/foxglove_protocol: the messages of the Foxglove WebSocket protocol v1
// (foxglove/ws-protocol docs/spec.md) against the byte layouts and JSON fields the spec gives.

#include "app/foxglove/foxglove_protocol.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include <gtest/gtest.h>

namespace towsim::app::foxglove {
namespace {

using Json = nlohmann::json;

TEST(FoxgloveProtocolTest, SubprotocolIsOneTheClientOffers) {
  EXPECT_EQ(ChooseSubprotocol({"foxglove.websocket.v1"}), "foxglove.websocket.v1");
  EXPECT_EQ(ChooseSubprotocol({"foxglove.sdk.v1", "foxglove.websocket.v1"}), "foxglove.sdk.v1");
  EXPECT_EQ(ChooseSubprotocol({"chat", "foxglove.websocket.v1"}), "foxglove.websocket.v1");
  EXPECT_EQ(ChooseSubprotocol({"chat"}), "");
  EXPECT_EQ(ChooseSubprotocol({}), "");
}

TEST(FoxgloveProtocolTest, ServerInfoAndAdvertiseCarryTheSpecsFields) {
  const Json info = Json::parse(ServerInfoJson("towsim", "42"));
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["name"], "towsim");
  EXPECT_EQ(info["capabilities"], Json({"clientPublish", "time"}));
  EXPECT_EQ(info["supportedEncodings"], Json({"cdr"}));
  EXPECT_EQ(info["sessionId"], "42");
  const Json ad = Json::parse(AdvertiseJson({{7, "/clock", "rosgraph_msgs/msg/Clock", "x\ny"}}));
  EXPECT_EQ(ad["op"], "advertise");
  ASSERT_EQ(ad["channels"].size(), 1u);
  const Json& c = ad["channels"][0];
  EXPECT_EQ(c["id"], 7);
  EXPECT_EQ(c["topic"], "/clock");
  EXPECT_EQ(c["encoding"], "cdr");
  EXPECT_EQ(c["schemaName"], "rosgraph_msgs/msg/Clock");
  EXPECT_EQ(c["schema"], "x\ny");
  EXPECT_EQ(c["schemaEncoding"], "ros2msg");
  const Json st = Json::parse(StatusJson(StatusLevel::kError, "bad"));
  EXPECT_EQ(st["op"], "status");
  EXPECT_EQ(st["level"], 2);
  EXPECT_EQ(st["message"], "bad");
}

TEST(FoxgloveProtocolTest, BinaryFramesAreLittleEndian) {
  const uint8_t payload[] = {0xaa, 0xbb};
  std::string f;
  MessageDataFrame(0x04030201u, 0x0c0b0a0908070605ull, payload, 2, &f);
  const std::string expected = {'\x01', '\x01', '\x02', '\x03', '\x04', '\x05', '\x06', '\x07',
                                '\x08', '\x09', '\x0a', '\x0b', '\x0c', '\xaa', '\xbb'};
  EXPECT_EQ(f, expected);
  const std::string t = TimeFrame(1000000001ull);  // 0x3b9aca01
  EXPECT_EQ(t, std::string("\x02\x01\xca\x9a\x3b\x00\x00\x00\x00", 9));
}

TEST(FoxgloveProtocolTest, ParsesTheClientRequests) {
  ClientRequest r = ParseClientText(
      R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":1,"channelId":5}]})");
  ASSERT_EQ(r.kind, ClientRequest::kSubscribe);
  ASSERT_EQ(r.subscribe.size(), 2u);
  EXPECT_EQ(r.subscribe[1], std::make_pair(1u, 5u));
  r = ParseClientText(R"({"op":"unsubscribe","subscriptionIds":[0,1]})");
  ASSERT_EQ(r.kind, ClientRequest::kUnsubscribe);
  EXPECT_EQ(r.ids, (std::vector<uint32_t>{0, 1}));
  r = ParseClientText(R"({"op":"advertise","channels":[{"id":2,"topic":"/towsim/towfish/command",)"
                      R"("encoding":"cdr","schemaName":"towsim_msgs/msg/ActuatorCommand"}]})");
  ASSERT_EQ(r.kind, ClientRequest::kAdvertise);
  ASSERT_EQ(r.channels.size(), 1u);
  EXPECT_EQ(r.channels[0].id, 2u);
  EXPECT_EQ(r.channels[0].topic, "/towsim/towfish/command");
  EXPECT_EQ(r.channels[0].encoding, "cdr");
  r = ParseClientText(R"({"op":"unadvertise","channelIds":[2]})");
  ASSERT_EQ(r.kind, ClientRequest::kUnadvertise);
  EXPECT_EQ(r.ids, std::vector<uint32_t>{2});
  EXPECT_EQ(ParseClientText(R"({"op":"getParameters","parameterNames":[]})").kind,
            ClientRequest::kOther);
  // malformed: the reason, never an exception
  for (const char* bad : {"{", "[1]", R"({"op":1})", R"({"op":"subscribe"})",
                          R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":3}]})"}) {
    const ClientRequest b = ParseClientText(bad);
    EXPECT_EQ(b.kind, ClientRequest::kInvalid) << bad;
    EXPECT_FALSE(b.error.empty()) << bad;
  }
}

TEST(FoxgloveProtocolTest, ParsesClientMessageData) {
  const uint8_t msg[] = {0x01, 0x02, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00};
  ClientData d;
  std::string error;
  ASSERT_TRUE(ParseClientBinary(msg, sizeof msg, &d, &error));
  EXPECT_EQ(d.channel, 2u);
  EXPECT_EQ(d.size, 4u);
  EXPECT_EQ(d.data, msg + 5);
  EXPECT_FALSE(ParseClientBinary(msg, 4, &d, &error));
  EXPECT_NE(error.find("shorter"), std::string::npos);
  const uint8_t other[] = {0x02, 0, 0, 0, 0};
  EXPECT_FALSE(ParseClientBinary(other, sizeof other, &d, &error));
  EXPECT_NE(error.find("opcode 2"), std::string::npos);
}

}  // namespace
}  // namespace towsim::app::foxglove
