#pragma once
// An MCAP recording of DDS topics as rosbag2 writes one (docs/contract.md §6), shared by
// `sim_node --record` and `towsim_record`: profile "ros2", one channel per topic named in ROS
// form ("/towsim/towfish/odom" for the DDS topic "rt/towsim/towfish/odom"), message encoding
// "cdr" (the serialized payload with its 4-byte encapsulation header, as published), one
// schema per type ("nav_msgs/msg/Odometry", encoding "ros2msg", io/ros2_schemas), channel
// metadata "offered_qos_profiles" (the QoS YAML of rosbag2), and the rosbag2 metadata record
// written at Close().
//
// Durability: besides the writer's own rule (a chunk closes once it spans 1 s of log time),
// the open chunk is flushed to the operating system when kFlushPeriod of wall time has passed
// since the last flush, checked at every Write() and FlushIfDue(): a killed recorder loses at
// most the messages of the last kFlushPeriod plus the gap to the next call.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "io/mcap_writer.h"

namespace towsim::app {

// rosbag2's offered_qos_profiles YAML of a reliable keep-last writer, volatile or transient
// local (the towsim topics, docs/contract.md §3)
std::string OfferedQosYaml(bool transient_local, int depth);

class McapRecording {
 public:
  static constexpr double kFlushPeriod = 0.5;  // wall time between flushes [s]

  // creates `path` and locks it while it is written (io::McapWriter::Options::exclusive): an
  // existing file is refused unless `overwrite`, a file another writer holds always; throws
  // std::runtime_error naming it
  explicit McapRecording(const std::string& path, bool overwrite = false);
  ~McapRecording();  // Close(), errors ignored

  // a channel for a DDS topic ("rt/...") of a DDS type ("nav_msgs::msg::dds_::Odometry_");
  // the type's schema is added on first use. Throws std::invalid_argument for a type without
  // a ROS 2 definition.
  std::uint16_t AddTopic(const std::string& dds_topic, const std::string& dds_type_name,
                         bool transient_local = false, int depth = 1);

  // one message: log time [ns] (the simulation time, sim t = 0 at 0; or, on the wall clock,
  // the receive or publish time since the Unix epoch: docs/recording.md) and publish time
  // [ns since the Unix epoch]
  void Write(std::uint16_t channel, std::uint64_t log_time_ns, std::uint64_t publish_time_ns,
             const std::uint8_t* data, std::size_t size);
  // flushes the open chunk if kFlushPeriod has passed since the last flush
  void FlushIfDue();
  // writes the rosbag2 metadata record, the summary and the footer; no-op when closed
  void Close();

  const std::string& path() const { return path_; }
  std::uint64_t message_count() const { return writer_.message_count(); }
  std::size_t topic_count() const { return sequences_.size(); }
  std::uint64_t bytes() const { return bytes_; }
  // a write or flush threw (io::OutputError): the file holds what reached it before
  bool failed() const { return failed_; }

 private:
  using Clock = std::chrono::steady_clock;
  std::string path_;
  io::McapWriter writer_;
  std::map<std::string, std::uint16_t> schemas_;      // ROS 2 type name -> schema id
  std::map<std::uint16_t, std::uint32_t> sequences_;  // channel -> messages so far
  std::uint64_t bytes_ = 0;                           // payload bytes written
  Clock::time_point last_flush_;
  bool closed_ = false;
  bool failed_ = false;
};

}  // namespace towsim::app
