#include "app/foxglove/foxglove_protocol.h"

#include <cstring>
#include <nlohmann/json.hpp>

namespace towsim::app::foxglove {
namespace {

using Json = nlohmann::json;

constexpr uint8_t kMessageData = 0x01;
constexpr uint8_t kTime = 0x02;
constexpr uint8_t kClientMessageData = 0x01;

void PutLe(uint64_t v, int bytes, std::string* out) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

uint32_t Id(const Json& j, const char* key) {
  const Json& v = j.at(key);
  if (!v.is_number_integer() || v.get<int64_t>() < 0 || v.get<int64_t>() > 0xffffffffLL) {
    throw std::invalid_argument(std::string(key) + " must be an integer in [0, 2^32)");
  }
  return static_cast<uint32_t>(v.get<int64_t>());
}

}  // namespace

std::string ChooseSubprotocol(const std::vector<std::string>& offered) {
  for (const std::string& p : offered) {
    if (p == kSubprotocolV1 || p == kSubprotocolSdk) return p;
  }
  return "";
}

std::string ServerInfoJson(const std::string& name, const std::string& session_id) {
  const Json j = {{"op", "serverInfo"},
                  {"name", name},
                  {"capabilities", {"clientPublish", "time"}},
                  {"supportedEncodings", {"cdr"}},
                  {"metadata", Json::object()},
                  {"sessionId", session_id}};
  return j.dump();
}

std::string AdvertiseJson(const std::vector<Channel>& channels) {
  Json list = Json::array();
  for (const Channel& c : channels) {
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", "cdr"},
                    {"schemaName", c.schema_name},
                    {"schema", c.schema},
                    {"schemaEncoding", "ros2msg"}});
  }
  return Json{{"op", "advertise"}, {"channels", list}}.dump();
}

std::string StatusJson(StatusLevel level, const std::string& message) {
  return Json{{"op", "status"}, {"level", static_cast<int>(level)}, {"message", message}}.dump();
}

void MessageDataFrame(uint32_t subscription, uint64_t log_time_ns, const uint8_t* data,
                      std::size_t size, std::string* out) {
  out->clear();
  out->reserve(13 + size);
  out->push_back(static_cast<char>(kMessageData));
  PutLe(subscription, 4, out);
  PutLe(log_time_ns, 8, out);
  out->append(reinterpret_cast<const char*>(data), size);
}

std::string TimeFrame(uint64_t time_ns) {
  std::string out(1, static_cast<char>(kTime));
  PutLe(time_ns, 8, &out);
  return out;
}

ClientRequest ParseClientText(const std::string& text) {
  ClientRequest r;
  try {
    const Json j = Json::parse(text);
    if (!j.is_object() || !j.contains("op") || !j["op"].is_string()) {
      r.error = "a JSON object with a string field \"op\" expected";
      return r;
    }
    r.op = j["op"].get<std::string>();
    if (r.op == "subscribe") {
      for (const Json& s : j.at("subscriptions"))
        r.subscribe.emplace_back(Id(s, "id"), Id(s, "channelId"));
      r.kind = ClientRequest::kSubscribe;
    } else if (r.op == "unsubscribe") {
      for (const Json& id : j.at("subscriptionIds")) {
        r.ids.push_back(Id(Json{{"id", id}}, "id"));
      }
      r.kind = ClientRequest::kUnsubscribe;
    } else if (r.op == "advertise") {
      for (const Json& c : j.at("channels")) {
        ClientChannel ch;
        ch.id = Id(c, "id");
        ch.topic = c.at("topic").get<std::string>();
        ch.encoding = c.at("encoding").get<std::string>();
        ch.schema_name = c.at("schemaName").get<std::string>();
        r.channels.push_back(ch);
      }
      r.kind = ClientRequest::kAdvertise;
    } else if (r.op == "unadvertise") {
      for (const Json& id : j.at("channelIds")) r.ids.push_back(Id(Json{{"id", id}}, "id"));
      r.kind = ClientRequest::kUnadvertise;
    } else {
      r.kind = ClientRequest::kOther;
    }
  } catch (const std::exception& e) {
    r.kind = ClientRequest::kInvalid;
    r.error = std::string("malformed request: ") + e.what();
  }
  return r;
}

bool ParseClientBinary(const uint8_t* data, std::size_t size, ClientData* out, std::string* error) {
  if (size < 5 || data[0] != kClientMessageData) {
    *error = size < 5 ? "binary message shorter than 5 bytes"
                      : "unsupported binary opcode " + std::to_string(data[0]);
    return false;
  }
  uint32_t id = 0;
  for (int i = 0; i < 4; ++i) id |= static_cast<uint32_t>(data[1 + i]) << (8 * i);
  out->channel = id;
  out->data = data + 5;
  out->size = size - 5;
  return true;
}

}  // namespace towsim::app::foxglove
