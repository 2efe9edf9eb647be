#pragma once
// The Foxglove WebSocket protocol, v1 (foxglove/ws-protocol docs/spec.md; subprotocols
// "foxglove.websocket.v1" and "foxglove.sdk.v1", which share these messages): the messages
// towsim's server sends and the client requests it understands, as pure functions (no
// sockets), unit-tested in tests/unit/foxglove_protocol_test.cc. docs/foxglove.md.
//
// Server -> client: serverInfo (capabilities "clientPublish" and "time", supported encoding
// "cdr"), advertise (channels: encoding "cdr", schemaEncoding "ros2msg", the schema the MCAP
// recording holds, io/ros2_schemas.h), status; binary Message Data (0x01, subscription id,
// log time [ns], payload) and Time (0x02, time [ns]). Integers little endian.
// Client -> server: subscribe, unsubscribe, advertise (client channels), unadvertise; binary
// Client Message Data (0x01, client channel id, payload).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace towsim::app::foxglove {

inline constexpr const char* kSubprotocolV1 = "foxglove.websocket.v1";
inline constexpr const char* kSubprotocolSdk = "foxglove.sdk.v1";

// the subprotocol to answer a client that offers `offered` (in its order of preference); ""
// if none of ours
std::string ChooseSubprotocol(const std::vector<std::string>& offered);

struct Channel {
  uint32_t id = 0;
  std::string topic;        // ROS name, "/towsim/towfish/odom"
  std::string schema_name;  // "nav_msgs/msg/Odometry"
  std::string schema;       // ros2msg text
};

enum class StatusLevel { kInfo = 0, kWarning = 1, kError = 2 };

std::string ServerInfoJson(const std::string& name, const std::string& session_id);
std::string AdvertiseJson(const std::vector<Channel>& channels);
std::string StatusJson(StatusLevel level, const std::string& message);

// binary Message Data: 0x01, subscription id (uint32), log time (uint64), payload
void MessageDataFrame(uint32_t subscription, uint64_t log_time_ns, const uint8_t* data,
                      std::size_t size, std::string* out);
// binary Time: 0x02, time (uint64) [ns]
std::string TimeFrame(uint64_t time_ns);

// a client channel (Client Advertise)
struct ClientChannel {
  uint32_t id = 0;
  std::string topic, encoding, schema_name;
};

// one text message of a client
struct ClientRequest {
  enum Kind { kSubscribe, kUnsubscribe, kAdvertise, kUnadvertise, kOther, kInvalid };
  Kind kind = kInvalid;
  std::string op;                                        // as sent
  std::vector<std::pair<uint32_t, uint32_t>> subscribe;  // (subscription id, channel id)
  std::vector<uint32_t> ids;                             // unsubscribe / unadvertise
  std::vector<ClientChannel> channels;                   // advertise
  std::string error;                                     // kInvalid: why
};

ClientRequest ParseClientText(const std::string& text);

// binary Client Message Data; false (and `error`) if it is not one
struct ClientData {
  uint32_t channel = 0;
  const uint8_t* data = nullptr;
  std::size_t size = 0;
};
bool ParseClientBinary(const uint8_t* data, std::size_t size, ClientData* out, std::string* error);

}  // namespace towsim::app::foxglove
