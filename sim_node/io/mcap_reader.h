#pragma once
// MCAP reader (https://mcap.dev/spec), the counterpart of McapWriter; reads any
// spec-conforming file with uncompressed chunks (compression ""), and unchunked messages.
//
// Open(): the complete-file path. Checks both magics, the footer, the summary CRC, the data
// section CRC (DataEnd; accepted when computed from byte 0 or from byte 8, the two conventions
// in use), reads schemas, channels, statistics, chunk and metadata indexes from the summary.
// Chunk CRCs are checked when a chunk is read (ReadMessages / ForEachMessage).
// Recover(): the killed-recording and damaged-file path. Scans records linearly from the
// header and keeps every schema, channel, metadata and complete chunk whose CRC holds. A
// record that is cut off or malformed is skipped: the scan resumes at its end if a record
// starts there, else at the next offset where one does (a chunk whose CRC holds, a data end,
// or a schema / channel / metadata / message index record that parses and is followed by a
// record header), so every intact chunk after the damage is kept. skipped() lists the byte
// ranges not read, with the message count of a skipped chunk from the message indexes that
// follow it. Statistics and chunk indexes are rebuilt from what was read.
//
// Both paths walk the records with mcap::RecordIterator and the chunks with mcap::WalkChunk
// (io/mcap_records.h), and parse the schema, channel, metadata and message records in one place.
//
// Errors throw mcap::McapError, whose message names the byte offset ("chunk CRC mismatch:
// stored 0x..., computed 0x... (at byte offset 1234)"). The whole file is held in memory.

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "io/mcap_format.h"

namespace towsim::io {

struct McapSchema {
  std::uint16_t id = 0;
  std::string name;
  std::string encoding;
  std::string data;
};

struct McapChannel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;
  mcap::StringMap metadata;
};

struct McapStatistics {
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0;
  std::uint32_t attachment_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

struct McapChunkIndex {
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::uint64_t chunk_start_offset = 0;
  std::uint64_t chunk_length = 0;
  std::map<std::uint16_t, std::uint64_t> message_index_offsets;
  std::uint64_t message_index_length = 0;
  std::string compression;
  std::uint64_t compressed_size = 0;
  std::uint64_t uncompressed_size = 0;
};

struct McapMetadata {
  std::string name;
  mcap::StringMap metadata;
};

// a byte range Recover() could not read
struct McapSkipped {
  std::uint64_t begin = 0, end = 0;  // [begin, end) [bytes]
  std::string reason;                // the damage found at `begin` (McapError's message)
  std::uint64_t messages = 0;        // messages in it, if messages_known
  bool messages_known = false;       // message indexes after a skipped chunk counted them
};

// "bytes 9505-41377 (31872 bytes, 120 messages by its message indexes): chunk CRC mismatch..."
std::string DescribeSkipped(const McapSkipped& skipped);

class McapReader;
// Recover() that kept no message although it skipped damage (a file of the magic alone, one
// cut off inside its first chunk): "nothing to recover: ...", bad input for the tools; else ""
std::string NothingRecovered(const McapReader& reader);

struct McapMessage {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;
  std::uint64_t publish_time = 0;
  std::vector<std::uint8_t> data;
};

class McapReader {
 public:
  // reads and validates a complete file; throws mcap::McapError (or std::runtime_error if the
  // file cannot be opened)
  static McapReader Open(const std::string& path);
  // reads what a killed writer or damage left: every complete, CRC-valid chunk (see above)
  static McapReader Recover(const std::string& path);
  // the same from bytes in memory (tests)
  static McapReader OpenBytes(std::string bytes);
  static McapReader RecoverBytes(std::string bytes);

  const std::string& profile() const { return profile_; }
  const std::string& library() const { return library_; }
  const std::map<std::uint16_t, McapSchema>& schemas() const { return schemas_; }
  const std::map<std::uint16_t, McapChannel>& channels() const { return channels_; }
  const McapStatistics& statistics() const { return statistics_; }
  bool has_statistics() const { return has_statistics_; }
  const std::vector<McapChunkIndex>& chunk_indexes() const { return chunk_indexes_; }
  const std::vector<McapMetadata>& metadata() const { return metadata_; }
  // Recover(): true if the file lacked a data end record or had damage; the end of the last
  // record read intact, and a note on what was missing
  bool recovered() const { return recovered_; }
  std::uint64_t recovered_bytes() const { return recovered_bytes_; }
  const std::string& recovery_note() const { return recovery_note_; }
  // Recover(): the byte ranges skipped (damaged records, a cut-off end); empty: nothing lost
  const std::vector<McapSkipped>& skipped() const { return skipped_; }

  // calls `fn` for every message in log-time order (ties in file order); checks chunk CRCs
  void ForEachMessage(const std::function<void(const McapMessage&)>& fn) const;
  std::vector<McapMessage> ReadMessages() const;

 private:
  McapReader() = default;
  void ReadSummary();
  void ScanLinear();
  // the messages of the chunk `index` points to, CRC-checked
  std::vector<McapMessage> ChunkMessages(const McapChunkIndex& index) const;

  std::string bytes_;
  std::string profile_;
  std::string library_;
  std::map<std::uint16_t, McapSchema> schemas_;
  std::map<std::uint16_t, McapChannel> channels_;
  McapStatistics statistics_;
  bool has_statistics_ = false;
  std::vector<McapChunkIndex> chunk_indexes_;
  std::vector<McapMetadata> metadata_;
  std::vector<McapMessage> loose_messages_;  // messages outside chunks (found by Recover)
  bool recovered_ = false;
  std::uint64_t recovered_bytes_ = 0;
  std::string recovery_note_;
  std::vector<McapSkipped> skipped_;
};

}  // namespace towsim::io
