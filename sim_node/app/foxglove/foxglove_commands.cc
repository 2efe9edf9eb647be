#include "app/foxglove/foxglove_commands.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <utility>

#include "app/common/mcap_recording.h"
#include "dds/qos.h"

namespace towsim::app {

dds::ActuatorCommandMsg TwistToCommand(const geometry_msgs_msg_dds__Twist_& t, uint64_t step,
                                       double* thrust) {
  const bool stop = t.linear.x == 0.0 && t.linear.y == 0.0 && t.linear.z == 0.0 &&
                    t.angular.x == 0.0 && t.angular.y == 0.0 && t.angular.z == 0.0;
  if (t.linear.x != 0.0 || stop) *thrust = t.linear.x;
  dds::ActuatorCommandMsg cmd{};
  cmd.step = step;
  cmd.thrust = *thrust;
  cmd.rudder = -t.angular.z;
  cmd.elevator = t.linear.z;
  return cmd;
}

std::string NonFiniteTwistField(const geometry_msgs_msg_dds__Twist_& t) {
  const std::pair<const char*, double> fields[] = {
      {"linear.x", t.linear.x},   {"linear.y", t.linear.y},   {"linear.z", t.linear.z},
      {"angular.x", t.angular.x}, {"angular.y", t.angular.y}, {"angular.z", t.angular.z}};
  for (const auto& [name, value] : fields) {
    if (!std::isfinite(value)) {
      return std::string(name) + " is not finite (" + (std::isnan(value) ? "nan" : "inf") + ")";
    }
  }
  return "";
}

std::string TrailingBytes(std::size_t size, std::size_t sample_size) {
  const std::size_t padded = (sample_size + 3) / 4 * 4;
  if (size <= padded) return "";
  return std::to_string(size - sample_size) + " bytes after the " + std::to_string(sample_size) +
         "-byte sample (only padding to a multiple of 4 may follow)";
}

namespace {

// the size of `data` serialized again by Cyclone (the bytes are a valid sample of `type`)
std::size_t SampleSize(const dds::RawType& type, const uint8_t* data, std::size_t size) {
  // zeroed storage (every byte: padding too, where Cyclone may find a string's pointer)
  void* sample = dds_alloc(type.descriptor()->m_size);
  if (sample == nullptr) throw std::bad_alloc();
  std::memset(sample, 0, type.descriptor()->m_size);
  std::size_t n = size;
  if (type.Deserialize(data, size, sample)) n = dds::CdrSample::FromSample(type, sample).size();
  dds_sample_free(sample, type.descriptor(), DDS_FREE_ALL);
  return n;
}

// the PanelTopic of `topic`, or nullptr
const PanelTopic* FindPanelTopic(const std::string& topic) {
  for (const PanelTopic& p : kPanelTopics) {
    if (topic == p.topic) return &p;
  }
  return nullptr;
}

// "geometry_msgs/msg/PointStamped" -> "geometry_msgs/PointStamped" (the ROS 1 spelling, which
// clients may use too)
std::string ShortName(const std::string& schema) {
  return schema.substr(0, schema.find('/')) + schema.substr(schema.rfind('/'));
}

}  // namespace

FoxgloveCommands::FoxgloveCommands(const dds::Participant& participant,
                                   const wire::TopicNames& names,
                                   const std::vector<std::string>& bodies,
                                   const std::vector<std::string>& winches)
    : participant_(participant),
      command_type_(participant, &towsim_msgs_msg_dds__ActuatorCommand__desc),
      control_type_(participant, &towsim_msgs_msg_dds__SimControl__desc),
      twist_type_(participant, &geometry_msgs_msg_dds__Twist__desc),
      winch_type_(participant, &towsim_msgs_msg_dds__WinchCommand__desc) {
  for (const std::string& b : bodies) {
    Inbound& in = inbound_[wire::RosTopicName(names.Name(wire::Topic::kCommand, b))];
    in.schema_name = "towsim_msgs/msg/ActuatorCommand";
    in.descriptor = &towsim_msgs_msg_dds__ActuatorCommand__desc;
    in.type = &command_type_;
    in.teleop = true;
  }
  for (const std::string& w : winches) {  // each winch's own command (docs/winch_dds.md),
                                          // checked by the node like any
    Inbound& in = inbound_[wire::RosTopicName(names.Name(wire::Topic::kWinchCommand, w))];
    in.schema_name = "towsim_msgs/msg/WinchCommand";
    in.descriptor = &towsim_msgs_msg_dds__WinchCommand__desc;
    in.type = &winch_type_;
  }
  Inbound& control = inbound_[wire::RosTopicName(names.Name(wire::Topic::kSimControl))];
  control.schema_name = "towsim_msgs/msg/SimControl";
  control.descriptor = &towsim_msgs_msg_dds__SimControl__desc;
  control.type = &control_type_;
  control.control = true;
}

void FoxgloveCommands::Attach(FoxgloveServer* server) {
  server->OnClientAdvertise([this](const foxglove::ClientChannel& c) { return Advertise(c); });
  server->OnClientPublish([this](const foxglove::ClientChannel& c, const uint8_t* d,
                                 std::size_t n) { return Publish(c, d, n); });
}

std::string FoxgloveCommands::Advertise(const foxglove::ClientChannel& c) {
  // the 3D panel's publish tools: taken with their schema, whatever the encoding (the
  // messages are ignored, never decoded)
  if (const PanelTopic* p = FindPanelTopic(c.topic)) {
    if (c.schema_name != p->schema && c.schema_name != ShortName(p->schema)) {
      return "schema " + c.schema_name + ": must be " + p->schema +
             " (the 3D panel's topic, taken and ignored)";
    }
    return "";
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = inbound_.find(c.topic);
  if (it == inbound_.end()) {
    std::string list;
    for (const auto& [topic, in] : inbound_) list += (list.empty() ? "" : ", ") + topic;
    return "not a topic clients may publish on (" + list + ")";
  }
  Inbound& in = it->second;
  if (c.encoding != "cdr") return "encoding " + c.encoding + ": only cdr";
  const std::string short_name = ShortName(in.schema_name);
  const bool twist = in.teleop && (c.schema_name == "geometry_msgs/msg/Twist" ||
                                   c.schema_name == "geometry_msgs/Twist");
  if (c.schema_name != in.schema_name && c.schema_name != short_name && !twist) {
    return "schema " + c.schema_name + ": must be " + in.schema_name +
           (in.teleop ? " or geometry_msgs/msg/Twist" : "");
  }
  if (!in.writer.valid()) {
    const std::string dds_name = wire::DdsTopicName(c.topic);
    const dds_entity_t t =
        dds_create_topic(participant_.get(), in.descriptor, dds_name.c_str(), nullptr, nullptr);
    if (t < 0) return "creating topic " + dds_name + ": " + dds_strretcode(t);
    in.topic = dds::Entity(t);
    dds::Qos qos = in.control ? dds::ControlQos() : dds::CommandQos();
    const dds_entity_t w = dds_create_writer(participant_.get(), t, qos.get(), nullptr);
    if (w < 0) return "creating a writer for " + dds_name + ": " + dds_strretcode(w);
    in.writer = dds::Entity(w);
  }
  return "";
}

FoxgloveServer::Verdict FoxgloveCommands::Publish(const foxglove::ClientChannel& c,
                                                  const uint8_t* data, std::size_t size) {
  using Verdict = FoxgloveServer::Verdict;
  // advertised only if Advertise took it (the server checks): taken, not written anywhere
  if (FindPanelTopic(c.topic) != nullptr) {
    ++ignored_;
    return Verdict{};
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = inbound_.find(c.topic);
  if (it == inbound_.end() || !it->second.writer.valid()) {
    return Verdict{"not advertised: " + c.topic};
  }
  Inbound& in = it->second;
  auto reject = [&](const std::string& type, const std::string& why) {
    ++malformed_;
    return Verdict{"rejected: malformed " + type + " on " + c.topic + " (" + std::to_string(size) +
                       " bytes)" + (why.empty() ? "" : ": " + why),
                   true};
  };
  if (in.teleop && c.schema_name.rfind("geometry_msgs/", 0) == 0) {
    const char* kTwist = "geometry_msgs/msg/Twist";
    geometry_msgs_msg_dds__Twist_ t{};  // no pointers: nothing to free
    if (!twist_type_.Deserialize(data, size, &t)) return reject(kTwist, "");
    const std::string trailing = TrailingBytes(size, SampleSize(twist_type_, data, size));
    if (!trailing.empty()) return reject(kTwist, trailing);
    // rejected before it reaches the kept thrust
    if (const std::string bad = NonFiniteTwistField(t); !bad.empty()) return reject(kTwist, bad);
    dds::ActuatorCommandMsg cmd = TwistToCommand(t, status_step_.load(), &in.teleop_thrust);
    cmd.header.frame_id = const_cast<char*>("");
    const dds_return_t rc = dds_write(in.writer.get(), &cmd);
    if (rc < 0) return Verdict{"writing to " + c.topic + ": " + dds_strretcode(rc)};
    return Verdict{};
  }
  dds::CdrSample sample;
  try {
    sample = dds::CdrSample::FromBytes(*in.type, data, size);
  } catch (const std::invalid_argument& e) {
    return reject(in.schema_name, e.what());
  }
  const std::string trailing = TrailingBytes(size, SampleSize(*in.type, data, size));
  if (!trailing.empty()) return reject(in.schema_name, trailing);
  const dds_return_t rc = sample.Write(in.writer.get(), dds_time());
  if (rc < 0) return Verdict{"writing to " + c.topic + ": " + dds_strretcode(rc)};
  return Verdict{};
}

}  // namespace towsim::app
