#include "io/mcap_writer.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "io/output_error.h"

namespace towsim::io {

using mcap::Encoder;
using mcap::Op;

McapWriter::~McapWriter() {
  try {
    Close();
  } catch (...) {
    // destructor: errors are ignored, Close() reports them to callers that call it
  }
}

void McapWriter::Open(const std::string& path, const std::string& profile) {
  if (opened_) throw std::runtime_error("McapWriter: a writer writes one file, already " + path_);
  // create (exclusive: only if it does not exist), lock, and only then truncate: a file
  // another writer holds is neither truncated nor written
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (options_.exclusive ? O_EXCL : 0);
  const int fd = ::open(path.c_str(), flags, 0644);
  if (fd < 0) {
    if (errno == EEXIST) throw std::runtime_error(path + " exists: a recording is not replaced");
    throw std::runtime_error("McapWriter: cannot open " + path + ": " + std::strerror(errno));
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK) {
      throw std::runtime_error(path + " is being written by another process (it holds the lock)");
    }
    throw std::runtime_error("McapWriter: cannot lock " + path + ": " + std::strerror(error));
  }
  if (::ftruncate(fd, 0) != 0 || (file_ = ::fdopen(fd, "wb")) == nullptr) {
    const int error = errno;
    ::close(fd);
    throw std::runtime_error("McapWriter: cannot open " + path + ": " + std::strerror(error));
  }
  path_ = path;
  opened_ = true;
  WriteBytes(mcap::kMagic, mcap::kMagicSize);
  Encoder header;
  header.Str(profile);
  header.Str(options_.library);
  WriteRecord(Op::kHeader, header.bytes());
  FlushFile();
}

std::uint16_t McapWriter::AddSchema(const std::string& name, const std::string& encoding,
                                    const std::string& data) {
  if (file_ == nullptr) throw std::runtime_error("McapWriter::AddSchema: not open");
  const std::uint16_t id = next_schema_id_++;
  Encoder content;
  content.U16(id);
  content.Str(name);
  content.Str(encoding);
  content.U32(static_cast<std::uint32_t>(data.size()));
  content.Raw(data.data(), data.size());
  // written at once, outside chunks, so a recovered file has it before any chunk using it
  WriteRecord(Op::kSchema, content.bytes());
  schema_records_.push_back(content.bytes());
  schema_names_[id] = name;
  return id;
}

std::uint16_t McapWriter::AddChannel(std::uint16_t schema_id, const std::string& topic,
                                     const std::string& message_encoding,
                                     const mcap::StringMap& metadata) {
  if (file_ == nullptr) throw std::runtime_error("McapWriter::AddChannel: not open");
  if (schema_id >= next_schema_id_) {
    throw std::invalid_argument("McapWriter::AddChannel: unknown schema id " +
                                std::to_string(schema_id) + " for topic " + topic);
  }
  const auto id = static_cast<std::uint16_t>(channel_records_.size());
  Encoder content;
  content.U16(id);
  content.U16(schema_id);
  content.Str(topic);
  content.Str(message_encoding);
  content.Map(metadata);
  WriteRecord(Op::kChannel, content.bytes());
  channel_records_[id] = content.bytes();
  channel_summaries_[id] = {topic, message_encoding,
                            schema_id == 0 ? std::string() : schema_names_[schema_id], metadata, 0};
  return id;
}

void McapWriter::Write(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time_ns,
                       std::uint64_t publish_time_ns, const void* data, std::size_t size) {
  if (file_ == nullptr) throw std::runtime_error("McapWriter::Write: not open");
  if (channel_records_.count(channel_id) == 0) {
    throw std::invalid_argument("McapWriter::Write: unknown channel id " +
                                std::to_string(channel_id));
  }
  // close the chunk once it spans a second of log time (either direction)
  if (!chunk_.empty()) {
    const std::uint64_t lo = std::min(chunk_start_time_, log_time_ns);
    const std::uint64_t hi = std::max(chunk_end_time_, log_time_ns);
    if (hi - lo >= options_.chunk_duration_ns) CloseChunk();
  }
  if (chunk_.empty()) {
    chunk_start_time_ = log_time_ns;
    chunk_end_time_ = log_time_ns;
  }
  chunk_start_time_ = std::min(chunk_start_time_, log_time_ns);
  chunk_end_time_ = std::max(chunk_end_time_, log_time_ns);

  Encoder message;
  message.U16(channel_id);
  message.U32(sequence);
  message.U64(log_time_ns);
  message.U64(publish_time_ns);
  message.Raw(data, size);
  chunk_index_[channel_id].emplace_back(log_time_ns, chunk_.size());
  mcap::AppendRecord(chunk_, Op::kMessage, message.bytes());

  if (message_count_ == 0) {
    message_start_time_ = log_time_ns;
    message_end_time_ = log_time_ns;
  }
  message_start_time_ = std::min(message_start_time_, log_time_ns);
  message_end_time_ = std::max(message_end_time_, log_time_ns);
  ++message_count_;
  ++channel_message_counts_[channel_id];

  if (chunk_.size() >= options_.chunk_size) CloseChunk();
}

std::map<std::uint16_t, McapWriter::ChannelSummary> McapWriter::channel_summaries() const {
  std::map<std::uint16_t, ChannelSummary> out = channel_summaries_;
  for (auto& [id, summary] : out) {
    const auto it = channel_message_counts_.find(id);
    summary.message_count = it == channel_message_counts_.end() ? 0 : it->second;
  }
  return out;
}

void McapWriter::AddMetadata(const std::string& name, const mcap::StringMap& metadata) {
  if (file_ == nullptr) throw std::runtime_error("McapWriter::AddMetadata: not open");
  Encoder content;
  content.Str(name);
  content.Map(metadata);
  const std::uint64_t offset = pos_;
  WriteRecord(Op::kMetadata, content.bytes());
  Encoder index;
  index.U64(offset);
  index.U64(pos_ - offset);
  index.Str(name);
  metadata_indexes_.push_back(index.bytes());
}

void McapWriter::Flush() {
  if (file_ == nullptr) return;
  CloseChunk();
  FlushFile();
}

void McapWriter::Close() {
  if (file_ == nullptr) return;
  CloseChunk();

  // data end: CRC of every byte so far
  Encoder data_end;
  data_end.U32(data_crc_.value());
  WriteRecord(Op::kDataEnd, data_end.bytes());
  in_data_section_ = false;

  // summary: one group per record type, remembering (opcode, start, length)
  const std::uint64_t summary_start = pos_;
  std::vector<std::pair<Op, std::pair<std::uint64_t, std::uint64_t>>> groups;
  auto write_group = [&](Op op, const auto& contents) {
    if (contents.empty()) return;
    const std::uint64_t start = pos_;
    for (const std::string& c : contents) WriteRecord(op, c);
    groups.push_back({op, {start, pos_ - start}});
  };
  write_group(Op::kSchema, schema_records_);
  std::vector<std::string> channels;
  for (const auto& [id, c] : channel_records_) channels.push_back(c);
  write_group(Op::kChannel, channels);

  Encoder stats;
  stats.U64(message_count_);
  stats.U16(static_cast<std::uint16_t>(schema_records_.size()));
  stats.U32(static_cast<std::uint32_t>(channel_records_.size()));
  stats.U32(0);  // attachments
  stats.U32(static_cast<std::uint32_t>(metadata_indexes_.size()));
  stats.U32(static_cast<std::uint32_t>(chunk_indexes_.size()));
  stats.U64(message_start_time_);
  stats.U64(message_end_time_);
  Encoder counts;
  for (const auto& [id, n] : channel_message_counts_) {
    counts.U16(id);
    counts.U64(n);
  }
  stats.U32(static_cast<std::uint32_t>(counts.size()));
  stats.Raw(counts.bytes().data(), counts.size());
  write_group(Op::kStatistics, std::vector<std::string>{stats.bytes()});
  write_group(Op::kMetadataIndex, metadata_indexes_);
  write_group(Op::kChunkIndex, chunk_indexes_);

  const std::uint64_t summary_offset_start = pos_;
  for (const auto& [op, range] : groups) {
    Encoder offset;
    offset.U8(static_cast<std::uint8_t>(op));
    offset.U64(range.first);
    offset.U64(range.second);
    WriteRecord(Op::kSummaryOffset, offset.bytes());
  }

  // footer: the summary CRC covers the footer up to and including summary_offset_start
  Encoder footer;
  footer.U8(static_cast<std::uint8_t>(Op::kFooter));
  footer.U64(mcap::kFooterContentSize);
  footer.U64(summary_start);
  footer.U64(summary_offset_start);
  WriteBytes(footer.bytes().data(), footer.size());
  Encoder tail;
  tail.U32(summary_crc_.value());
  tail.Raw(mcap::kMagic, mcap::kMagicSize);
  WriteBytes(tail.bytes().data(), tail.size());

  FlushFile();
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) {
    throw OutputError("McapWriter: closing " + path_ + " failed: " + std::strerror(errno));
  }
}

void McapWriter::WriteBytes(const void* data, std::size_t size) {
  if (size == 0) return;
  if (std::fwrite(data, 1, size, file_) != size) {
    throw OutputError("McapWriter: writing " + path_ + " failed at byte " + std::to_string(pos_) +
                      ": " + std::strerror(errno));
  }
  pos_ += size;
  (in_data_section_ ? data_crc_ : summary_crc_).Update(data, size);
}

void McapWriter::WriteRecord(Op op, const std::string& content) {
  Encoder prefix;
  prefix.U8(static_cast<std::uint8_t>(op));
  prefix.U64(content.size());
  WriteBytes(prefix.bytes().data(), prefix.size());
  WriteBytes(content.data(), content.size());
}

void McapWriter::CloseChunk() {
  if (chunk_.empty()) return;
  Encoder chunk;
  chunk.U64(chunk_start_time_);
  chunk.U64(chunk_end_time_);
  chunk.U64(chunk_.size());
  chunk.U32(mcap::ComputeCrc32(chunk_.data(), chunk_.size()));
  chunk.Str("");  // compression: none
  chunk.U64(chunk_.size());
  // header of the chunk record, then its records straight from the buffer (no copy)
  Encoder prefix;
  prefix.U8(static_cast<std::uint8_t>(Op::kChunk));
  prefix.U64(chunk.size() + chunk_.size());
  const std::uint64_t chunk_start = pos_;
  WriteBytes(prefix.bytes().data(), prefix.size());
  WriteBytes(chunk.bytes().data(), chunk.size());
  WriteBytes(chunk_.data(), chunk_.size());
  const std::uint64_t chunk_length = pos_ - chunk_start;

  Encoder offsets;  // Map<channel id u16, file offset u64>
  const std::uint64_t index_start = pos_;
  for (const auto& [channel_id, entries] : chunk_index_) {
    offsets.U16(channel_id);
    offsets.U64(pos_);
    Encoder index;
    index.U16(channel_id);
    index.U32(static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [log_time, offset] : entries) {
      index.U64(log_time);
      index.U64(offset);
    }
    WriteRecord(Op::kMessageIndex, index.bytes());
  }

  Encoder ci;
  ci.U64(chunk_start_time_);
  ci.U64(chunk_end_time_);
  ci.U64(chunk_start);
  ci.U64(chunk_length);
  ci.U32(static_cast<std::uint32_t>(offsets.size()));
  ci.Raw(offsets.bytes().data(), offsets.size());
  ci.U64(pos_ - index_start);
  ci.Str("");
  ci.U64(chunk_.size());  // compressed size = uncompressed size
  ci.U64(chunk_.size());
  chunk_indexes_.push_back(ci.bytes());

  chunk_.clear();
  chunk_index_.clear();
  FlushFile();
}

void McapWriter::FlushFile() {
  if (std::fflush(file_) != 0) {
    throw OutputError("McapWriter: flushing " + path_ + " failed: " + std::strerror(errno));
  }
  if (options_.fsync) ::fsync(fileno(file_));
}

}  // namespace towsim::io
