#pragma once
// MCAP recording writer (docs/contract.md §6), written from the public specification
// (https://mcap.dev/spec); no external MCAP library.
//
// Layout of a file written by Close():
//   magic, Header(profile, library "towsim"),
//   data section: Schema / Channel / Metadata records (outside chunks, written as soon as they
//     are added), and Chunks (compression "" = none, uncompressed_crc set), each followed by
//     one Message Index record per channel in the chunk (sorted by channel id),
//   DataEnd(data_section_crc = CRC-32 of every byte of the file before the DataEnd record,
//     leading magic included),
//   summary: Schemas, Channels, Statistics, Metadata Indexes, Chunk Indexes (one group each),
//   summary offsets (one Summary Offset record per non-empty group),
//   Footer(summary_start, summary_offset_start, summary_crc = CRC-32 from summary_start through
//     the footer's summary_offset_start field), magic.
//
// Durability: a chunk is closed, written and flushed to the operating system (fflush, plus
// fsync if Options::fsync) when the next message's log time is >= 1 s (chunk_duration_ns)
// after the chunk's first message, or when the chunk's records exceed ~1 MiB (chunk_size),
// or on Flush(). A killed writer therefore loses at most the open chunk, i.e. the last second
// of log time; McapReader::Recover reads every complete chunk of such a file. A caller whose
// messages may stop arriving (a recorder) should call Flush() on a wall-clock timer.
//
// The `rosbag2` metadata record (key serialized_metadata: the bag-info YAML) is written by
// io/ros2_schemas AddRosbag2Metadata(writer) before Close(); rosbag2's MCAP storage plugin
// completes it from the summary (Statistics, Channels with metadata "offered_qos_profiles",
// Schemas named "pkg/msg/Type"), all of which are written.
//
// Not thread safe: the caller serializes calls.

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/mcap_format.h"

namespace towsim::io {

class McapWriter {
 public:
  struct Options {
    std::uint64_t chunk_size = 1u << 20;              // close a chunk above this [bytes]
    std::uint64_t chunk_duration_ns = 1'000'000'000;  // close a chunk spanning this [ns]
    bool fsync = false;                               // fsync after each chunk
    // refuse a file that exists (else it is truncated); either way the file is locked
    // (flock, exclusive) from Open() to Close(), and a file another writer holds is refused
    bool exclusive = false;
    std::string library = "towsim";
  };

  McapWriter() = default;
  explicit McapWriter(Options options) : options_(std::move(options)) {}
  ~McapWriter();  // Close(), ignoring errors
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // creates / truncates `path` (Options::exclusive: creates it only), locks it and writes the
  // magic and Header. One file per writer: throws std::runtime_error if the writer was opened
  // before, or naming the path if it cannot be opened, exists (exclusive) or is locked.
  void Open(const std::string& path, const std::string& profile = "ros2");

  // registers a schema (e.g. name "towsim_msgs/msg/BodyState", encoding "ros2msg", data the
  // .msg text with its dependencies) and returns its id (1, 2, ...; 0 means "no schema")
  std::uint16_t AddSchema(const std::string& name, const std::string& encoding,
                          const std::string& data);

  // registers a channel (topic) on a schema added before (or 0) and returns its id (0, 1, ...)
  std::uint16_t AddChannel(std::uint16_t schema_id, const std::string& topic,
                           const std::string& message_encoding = "cdr",
                           const mcap::StringMap& metadata = {});

  // appends one message (the serialized payload as received, e.g. CDR with its 4-byte
  // encapsulation header). Throws std::invalid_argument for an unknown channel and
  // std::runtime_error if writing fails.
  void Write(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time_ns,
             std::uint64_t publish_time_ns, const void* data, std::size_t size);
  void Write(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time_ns,
             std::uint64_t publish_time_ns, const std::vector<std::uint8_t>& data) {
    Write(channel_id, sequence, log_time_ns, publish_time_ns, data.data(), data.size());
  }

  // writes a Metadata record (indexed in the summary)
  void AddMetadata(const std::string& name, const mcap::StringMap& metadata);

  // closes the open chunk (if any) and flushes the file to the operating system
  void Flush();

  // closes the open chunk and writes DataEnd, the summary, the footer and the magic; the file
  // is then complete. No-op if not open. Throws std::runtime_error if writing fails.
  void Close();

  bool is_open() const { return file_ != nullptr; }
  const std::string& path() const { return path_; }
  std::uint64_t message_count() const { return message_count_; }
  std::uint32_t chunk_count() const { return static_cast<std::uint32_t>(chunk_indexes_.size()); }

  // what the summary will say so far, for records that describe the file (the rosbag2
  // metadata record of io/ros2_schemas): per channel id its topic, schema and message count
  struct ChannelSummary {
    std::string topic;
    std::string message_encoding;
    std::string schema_name;  // "" for schema id 0
    mcap::StringMap metadata;
    std::uint64_t message_count = 0;
  };
  std::map<std::uint16_t, ChannelSummary> channel_summaries() const;
  std::uint64_t message_start_time() const { return message_start_time_; }  // [ns], 0 if none
  std::uint64_t message_end_time() const { return message_end_time_; }      // [ns], 0 if none

 private:
  void WriteBytes(const void* data, std::size_t size);
  void WriteRecord(mcap::Op op, const std::string& content);
  void CloseChunk();
  void FlushFile();

  Options options_;
  std::string path_;
  std::FILE* file_ = nullptr;
  bool opened_ = false;          // Open() was called (a writer writes one file)
  std::uint64_t pos_ = 0;        // bytes written so far
  bool in_data_section_ = true;  // bytes go into the data CRC, else into the summary CRC
  mcap::Crc32 data_crc_;
  mcap::Crc32 summary_crc_;

  // summary content, kept as serialized record contents
  std::vector<std::string> schema_records_;
  std::map<std::uint16_t, std::string> channel_records_;  // by channel id
  std::vector<std::string> chunk_indexes_;
  std::vector<std::string> metadata_indexes_;
  std::uint16_t next_schema_id_ = 1;
  std::map<std::uint16_t, std::string> schema_names_;          // by schema id
  std::map<std::uint16_t, ChannelSummary> channel_summaries_;  // counts filled on demand

  // statistics
  std::uint64_t message_count_ = 0;
  std::uint64_t message_start_time_ = 0;
  std::uint64_t message_end_time_ = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts_;

  // the open chunk: its records, time range and per-channel (log_time, offset) index
  std::string chunk_;
  std::uint64_t chunk_start_time_ = 0;
  std::uint64_t chunk_end_time_ = 0;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
};

}  // namespace towsim::io
