#include "app/common/mcap_recording.h"

#include <stdexcept>
#include <string>

#include "io/ros2_schemas.h"
#include "wire/topic_names.h"

namespace towsim::app {

std::string OfferedQosYaml(bool transient_local, int depth) {
  // rmw enums: history 1 = keep last; reliability 1 = reliable; durability 1 = transient
  // local, 2 = volatile; liveliness 1 = automatic; "infinite" durations as rosbag2 writes them
  const char* kInfinite = "\n    sec: 2147483647\n    nsec: 4294967295";
  std::string y = "- history: 1\n  depth: " + std::to_string(depth) +
                  "\n  reliability: 1\n  durability: " + (transient_local ? "1" : "2") +
                  "\n  deadline:" + kInfinite + "\n  lifespan:" + kInfinite +
                  "\n  liveliness: 1\n  liveliness_lease_duration:" + kInfinite +
                  "\n  avoid_ros_namespace_conventions: false";
  return y;
}

namespace {

io::McapWriter::Options WriterOptions(bool overwrite) {
  io::McapWriter::Options options;
  options.exclusive = !overwrite;
  return options;
}

}  // namespace

McapRecording::McapRecording(const std::string& path, bool overwrite)
    : path_(path), writer_(WriterOptions(overwrite)) {
  try {
    writer_.Open(path, "ros2");
  } catch (const std::runtime_error& e) {
    if (!overwrite && std::string(e.what()).find(" exists") != std::string::npos) {
      throw std::runtime_error(std::string(e.what()) + " (--overwrite replaces it)");
    }
    throw;
  }
  last_flush_ = Clock::now();
}

McapRecording::~McapRecording() {
  try {
    Close();
  } catch (...) {
  }
}

std::uint16_t McapRecording::AddTopic(const std::string& dds_topic,
                                      const std::string& dds_type_name, bool transient_local,
                                      int depth) {
  const std::string type = io::Ros2TypeName(dds_type_name);
  auto it = schemas_.find(type);
  if (it == schemas_.end()) {
    it = schemas_.emplace(type, writer_.AddSchema(type, "ros2msg", io::Ros2MsgSchema(type))).first;
  }
  const std::uint16_t channel =
      writer_.AddChannel(it->second, wire::RosTopicName(dds_topic), "cdr",
                         {{"offered_qos_profiles", OfferedQosYaml(transient_local, depth)}});
  sequences_[channel] = 0;
  return channel;
}

void McapRecording::Write(std::uint16_t channel, std::uint64_t log_time_ns,
                          std::uint64_t publish_time_ns, const std::uint8_t* data,
                          std::size_t size) {
  try {
    writer_.Write(channel, ++sequences_[channel], log_time_ns, publish_time_ns, data, size);
  } catch (...) {
    failed_ = true;
    throw;
  }
  bytes_ += size;
  FlushIfDue();
}

void McapRecording::FlushIfDue() {
  const Clock::time_point now = Clock::now();
  if (std::chrono::duration<double>(now - last_flush_).count() < kFlushPeriod) return;
  last_flush_ = now;
  try {
    writer_.Flush();
  } catch (...) {
    failed_ = true;
    throw;
  }
}

void McapRecording::Close() {
  if (closed_ || !writer_.is_open()) return;
  closed_ = true;
  io::AddRosbag2Metadata(writer_);
  writer_.Close();
}

}  // namespace towsim::app
