#include "io/mcap_reader.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <queue>
#include <stdexcept>
#include <tuple>

#include "io/mcap_records.h"

namespace towsim::io {

using mcap::ChunkView;
using mcap::Decoder;
using mcap::Hex;
using mcap::McapError;
using mcap::Op;
using mcap::RecordAt;
using mcap::RecordIterator;
using mcap::RecordView;

namespace {

McapSchema ParseSchema(const std::string& b, const RecordView& r) {
  Decoder d(b, r.content, r.end(), "schema record");
  McapSchema s;
  s.id = d.U16();
  s.name = d.Str();
  s.encoding = d.Str();
  s.data = d.Bytes(d.U32());
  return s;
}

McapChannel ParseChannel(const std::string& b, const RecordView& r) {
  Decoder d(b, r.content, r.end(), "channel record");
  McapChannel c;
  c.id = d.U16();
  c.schema_id = d.U16();
  c.topic = d.Str();
  c.message_encoding = d.Str();
  c.metadata = d.Map();
  return c;
}

McapMetadata ParseMetadata(const std::string& b, const RecordView& r) {
  Decoder d(b, r.content, r.end(), "metadata record");
  McapMetadata m;
  m.name = d.Str();
  m.metadata = d.Map();
  return m;
}

McapMessage ParseMessage(const std::string& b, const RecordView& r) {
  Decoder d(b, r.content, r.end(), "message record");
  McapMessage m;
  m.channel_id = d.U16();
  m.sequence = d.U32();
  m.log_time = d.U64();
  m.publish_time = d.U64();
  const std::uint64_t n = d.remaining();
  m.data.resize(n);
  if (n > 0) std::memcpy(m.data.data(), b.data() + d.pos(), n);
  return m;
}

// the records that carry what the reader keeps, and which of them a path reads: the summary
// its schemas and channels, the data section all four, a chunk schemas, channels and messages
enum ContentKind : unsigned { kSchemas = 1u, kChannels = 2u, kMetadata = 4u, kMessages = 8u };

// what content records parsed into, before the reader keeps it (so that a record or a chunk
// that turns out damaged contributes nothing)
struct Content {
  std::vector<McapSchema> schemas;
  std::vector<McapChannel> channels;
  std::vector<McapMetadata> metadata;
  std::vector<McapMessage> messages;
};

// the one dispatch of the content records: parses `r` into `out` if it is a schema, channel,
// metadata or message record of a kind in `kinds`; false (nothing read) for any other record
bool ParseContent(const std::string& b, const RecordView& r, unsigned kinds, Content& out) {
  const unsigned kind = r.op == Op::kSchema     ? kSchemas
                        : r.op == Op::kChannel  ? kChannels
                        : r.op == Op::kMetadata ? kMetadata
                        : r.op == Op::kMessage  ? kMessages
                                                : 0u;
  if ((kind & kinds) == 0u) return false;
  if (kind == kSchemas) out.schemas.push_back(ParseSchema(b, r));
  if (kind == kChannels) out.channels.push_back(ParseChannel(b, r));
  if (kind == kMetadata) out.metadata.push_back(ParseMetadata(b, r));
  if (kind == kMessages) out.messages.push_back(ParseMessage(b, r));
  return true;
}

// keeps what was parsed: a schema or channel replaces one of the same id, metadata add up
void Keep(Content& found, std::map<std::uint16_t, McapSchema>& schemas,
          std::map<std::uint16_t, McapChannel>& channels, std::vector<McapMetadata>& metadata) {
  for (McapSchema& s : found.schemas) schemas[s.id] = std::move(s);
  for (McapChannel& c : found.channels) channels[c.id] = std::move(c);
  for (McapMetadata& m : found.metadata) metadata.push_back(std::move(m));
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("McapReader: cannot open " + path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void CheckLeadingMagic(const std::string& b) {
  if (b.size() < mcap::kMagicSize || std::memcmp(b.data(), mcap::kMagic, mcap::kMagicSize) != 0) {
    throw McapError("not an MCAP file: bad leading magic", 0);
  }
}

}  // namespace

McapReader McapReader::Open(const std::string& path) { return OpenBytes(ReadFile(path)); }
McapReader McapReader::Recover(const std::string& path) { return RecoverBytes(ReadFile(path)); }

McapReader McapReader::OpenBytes(std::string bytes) {
  McapReader r;
  r.bytes_ = std::move(bytes);
  r.ReadSummary();
  return r;
}

McapReader McapReader::RecoverBytes(std::string bytes) {
  McapReader r;
  r.bytes_ = std::move(bytes);
  r.ScanLinear();
  return r;
}

void McapReader::ReadSummary() {
  const std::string& b = bytes_;
  CheckLeadingMagic(b);
  const std::uint64_t size = b.size();
  const std::uint64_t footer_record = mcap::kRecordPrefixSize + mcap::kFooterContentSize;
  if (size < 2 * mcap::kMagicSize + footer_record) {
    throw McapError("file of " + std::to_string(size) + " bytes is too short for an MCAP file",
                    size);
  }
  if (std::memcmp(b.data() + size - mcap::kMagicSize, mcap::kMagic, mcap::kMagicSize) != 0) {
    throw McapError("bad trailing magic: the file is truncated or not closed (try --recover)",
                    size - mcap::kMagicSize);
  }
  const std::uint64_t footer_start = size - mcap::kMagicSize - footer_record;

  // header
  const RecordView header = RecordAt(b, mcap::kMagicSize, footer_start);
  if (header.op != Op::kHeader) {
    throw McapError("first record is opcode " + Hex(static_cast<unsigned>(header.op)) +
                        ", expected the header (0x1)",
                    header.start);
  }
  Decoder hd(b, header.content, header.end(), "header record");
  profile_ = hd.Str();
  library_ = hd.Str();

  // footer
  Decoder fd(b, footer_start, size - mcap::kMagicSize, "footer");
  if (fd.U8() != static_cast<std::uint8_t>(Op::kFooter) || fd.U64() != mcap::kFooterContentSize) {
    throw McapError("no footer record before the trailing magic", footer_start);
  }
  const std::uint64_t summary_start = fd.U64();
  const std::uint64_t summary_offset_start = fd.U64();
  const std::uint32_t summary_crc = fd.U32();
  if (summary_start > footer_start || summary_offset_start > footer_start ||
      (summary_start != 0 && summary_offset_start != 0 && summary_offset_start < summary_start)) {
    throw McapError("footer offsets out of range: summary_start " + std::to_string(summary_start) +
                        ", summary_offset_start " + std::to_string(summary_offset_start),
                    footer_start);
  }
  const std::uint64_t crc_begin = summary_start != 0 ? summary_start : footer_start;
  if (summary_crc != 0) {
    const std::uint32_t computed =
        mcap::ComputeCrc32(b.data() + crc_begin, footer_start + 1 + 8 + 16 - crc_begin);
    if (computed != summary_crc) {
      throw McapError(
          "summary CRC mismatch: stored " + Hex(summary_crc) + ", computed " + Hex(computed),
          crc_begin);
    }
  }

  // data end: the last record of the data section
  const std::uint64_t data_limit = summary_start != 0          ? summary_start
                                   : summary_offset_start != 0 ? summary_offset_start
                                                               : footer_start;
  const std::uint64_t data_end_record = mcap::kRecordPrefixSize + 4;
  if (data_limit < header.end() + data_end_record) {
    throw McapError("no data end record before the summary", data_limit);
  }
  const RecordView data_end = RecordAt(b, data_limit - data_end_record, data_limit);
  if (data_end.op != Op::kDataEnd || data_end.length != 4) {
    throw McapError("no data end record before the summary", data_limit - data_end_record);
  }
  const std::uint32_t data_crc = Decoder(b, data_end.content, data_end.end(), "data end").U32();
  if (data_crc != 0) {
    // from the leading magic on (our writer, mcap C++/Go) or from after it (other writers)
    const std::uint32_t from0 = mcap::ComputeCrc32(b.data(), data_end.start);
    const std::uint32_t from8 =
        mcap::ComputeCrc32(b.data() + mcap::kMagicSize, data_end.start - mcap::kMagicSize);
    if (data_crc != from0 && data_crc != from8) {
      throw McapError(
          "data section CRC mismatch: stored " + Hex(data_crc) + ", computed " + Hex(from0),
          data_end.start);
    }
  }

  if (summary_start == 0) {  // no summary: index the data section by scanning it
    ScanLinear();
    if (recovered_) throw McapError(recovery_note_, recovered_bytes_);
    return;
  }

  const std::uint64_t summary_end = summary_offset_start != 0 ? summary_offset_start : footer_start;
  Content found;
  for (RecordIterator it(b, summary_start, summary_end); !it.done();) {
    const RecordView r = it.Next();
    if (ParseContent(b, r, kSchemas | kChannels, found)) continue;
    switch (r.op) {
      case Op::kStatistics: {
        Decoder d(b, r.content, r.end(), "statistics record");
        McapStatistics& s = statistics_;
        s.message_count = d.U64();
        s.schema_count = d.U16();
        s.channel_count = d.U32();
        s.attachment_count = d.U32();
        s.metadata_count = d.U32();
        s.chunk_count = d.U32();
        s.message_start_time = d.U64();
        s.message_end_time = d.U64();
        const std::uint32_t n = d.U32();
        Decoder counts(b, d.pos(), d.pos() + n, "statistics channel counts");
        if (n > d.remaining()) throw McapError("truncated statistics record", d.pos());
        while (!counts.done()) {
          const std::uint16_t id = counts.U16();
          s.channel_message_counts[id] = counts.U64();
        }
        has_statistics_ = true;
        break;
      }
      case Op::kChunkIndex: {
        Decoder d(b, r.content, r.end(), "chunk index record");
        McapChunkIndex c;
        c.message_start_time = d.U64();
        c.message_end_time = d.U64();
        c.chunk_start_offset = d.U64();
        c.chunk_length = d.U64();
        const std::uint32_t n = d.U32();
        if (n > d.remaining()) throw McapError("truncated chunk index record", d.pos());
        Decoder offsets(b, d.pos(), d.pos() + n, "chunk index offsets");
        while (!offsets.done()) {
          const std::uint16_t id = offsets.U16();
          c.message_index_offsets[id] = offsets.U64();
        }
        d.Bytes(n);
        c.message_index_length = d.U64();
        c.compression = d.Str();
        c.compressed_size = d.U64();
        c.uncompressed_size = d.U64();
        if (c.chunk_start_offset > data_limit ||
            c.chunk_length > data_limit - c.chunk_start_offset) {
          throw McapError("chunk index points past the data section", r.start);
        }
        chunk_indexes_.push_back(std::move(c));
        break;
      }
      case Op::kMetadataIndex: {
        Decoder d(b, r.content, r.end(), "metadata index record");
        const std::uint64_t offset = d.U64();
        const std::uint64_t length = d.U64();
        if (offset > data_limit || length > data_limit - offset) {
          throw McapError("metadata index points past the data section", r.start);
        }
        const RecordView m = RecordAt(b, offset, offset + length);
        if (m.op != Op::kMetadata)
          throw McapError("metadata index points to opcode " + Hex(static_cast<unsigned>(m.op)),
                          offset);
        ParseContent(b, m, kMetadata, found);
        break;
      }
      default:
        break;  // attachment indexes and unknown records: skipped
    }
  }
  Keep(found, schemas_, channels_, metadata_);
}

namespace {

// the entries of a message index record: (log_time, offset) pairs of 16 bytes after the
// channel id (2) and the array's byte length (4)
std::uint64_t MessageIndexEntries(const std::string& b, const RecordView& r) {
  Decoder d(b, r.content, r.end(), "message index record");
  d.U16();
  const std::uint32_t n = d.U32();
  if (n % 16 != 0 || n != d.remaining()) {
    throw McapError("message index of " + std::to_string(n) + " bytes is malformed", r.start);
  }
  return n / 16;
}

// a record whose header fits and whose content checks out at `p`: a chunk with a CRC that
// holds, a data end, or a schema / channel / metadata / message index record that parses and
// is followed by a record header that fits (or the end). Where recovery resumes after damage.
bool RecordStartsAt(const std::string& b, std::uint64_t p, std::uint64_t size) {
  if (p + 9 > size) return false;
  try {
    const RecordView r = RecordAt(b, p, size);
    auto followed = [&] {
      if (r.end() == size) return true;
      const unsigned next = static_cast<unsigned>(RecordAt(b, r.end(), size).op);
      return next >= static_cast<unsigned>(Op::kHeader) &&
             next <= static_cast<unsigned>(Op::kDataEnd);
    };
    Content parsed;
    if (ParseContent(b, r, kSchemas | kChannels | kMetadata, parsed)) return followed();
    switch (r.op) {
      case Op::kChunk:  // a CRC that holds over records that fit
        return mcap::WalkChunk(b, r, [](const RecordView&) {}).crc != 0;
      case Op::kDataEnd:
        return r.length == 4;
      case Op::kMessageIndex:
        MessageIndexEntries(b, r);
        return followed();
      default:
        return false;
    }
  } catch (const McapError&) {
    return false;
  }
}

// the first offset at or after `from` where a record starts (RecordStartsAt), else `size`
std::uint64_t Resynchronize(const std::string& b, std::uint64_t from, std::uint64_t size) {
  for (std::uint64_t p = from; p < size; ++p) {
    if (RecordStartsAt(b, p, size)) return p;
  }
  return size;
}

}  // namespace

std::string DescribeSkipped(const McapSkipped& s) {
  std::string text = "bytes " + std::to_string(s.begin) + "-" + std::to_string(s.end) + " (" +
                     std::to_string(s.end - s.begin) + " bytes, ";
  text += s.messages_known ? std::to_string(s.messages) + " messages by its message indexes"
                           : std::string("message count unknown");
  return text + "): " + s.reason;
}

std::string NothingRecovered(const McapReader& reader) {
  if (reader.skipped().empty() || reader.statistics().message_count != 0) return "";
  return "nothing to recover: no intact chunk (no message survives the " +
         std::to_string(reader.skipped().size()) + " byte ranges skipped)";
}

void McapReader::ScanLinear() {
  const std::string& b = bytes_;
  CheckLeadingMagic(b);
  const std::uint64_t size = b.size();
  statistics_ = McapStatistics{};
  skipped_.clear();
  recovered_ = true;
  recovery_note_ = "no data end record: the file ends after the last complete record";

  // a damaged record at `pos`: skip it, to its own end if that is where a record starts, else
  // to the next place one does; the message indexes after a skipped chunk count its messages
  bool counting_skipped = false;  // message indexes now belong to the last skipped range
  auto skip = [&](std::uint64_t pos, const std::string& reason) {
    std::uint64_t next = size;
    try {
      const RecordView r = RecordAt(b, pos, size);
      next = RecordStartsAt(b, r.end(), size) ? r.end() : Resynchronize(b, pos + 1, size);
    } catch (const McapError&) {
      next = Resynchronize(b, pos + 1, size);
    }
    skipped_.push_back({pos, next, reason, 0, false});
    counting_skipped = true;
    return next;
  };

  std::uint64_t pos = mcap::kMagicSize;
  try {
    const RecordView header = RecordAt(b, pos, size);
    if (header.op != Op::kHeader) throw McapError("first record is not the header", header.start);
    Decoder hd(b, header.content, header.end(), "header record");
    profile_ = hd.Str();
    library_ = hd.Str();
    // a damaged length would step into the next record: it must hold exactly the two strings
    if (hd.remaining() != 0) {
      throw McapError("header record of " + std::to_string(header.length) + " bytes holds " +
                          std::to_string(hd.remaining()) + " bytes after its profile and library",
                      header.start);
    }
    pos = header.end();
  } catch (const McapError& e) {
    pos = skip(pos, e.what());
  }

  bool any_message = false;
  auto count = [&](const McapMessage& m) {
    McapStatistics& s = statistics_;
    if (!any_message) s.message_start_time = s.message_end_time = m.log_time;
    any_message = true;
    s.message_start_time = std::min(s.message_start_time, m.log_time);
    s.message_end_time = std::max(s.message_end_time, m.log_time);
    ++s.message_count;
    ++s.channel_message_counts[m.channel_id];
  };

  recovered_bytes_ = pos;
  for (RecordIterator it(b, pos, size); !it.done();) {
    const std::uint64_t start = it.pos();
    try {
      const RecordView r = it.Next();
      Content found;
      bool stop = false;
      if (ParseContent(b, r, kSchemas | kChannels | kMetadata | kMessages, found)) {
        Keep(found, schemas_, channels_, metadata_);
        for (McapMessage& m : found.messages) {
          count(m);
          loose_messages_.push_back(std::move(m));
          counting_skipped = false;
        }
      } else {
        switch (r.op) {
          case Op::kChunk: {
            // parse everything first, so a damaged chunk contributes nothing
            const ChunkView c = mcap::WalkChunk(b, r, [&](const RecordView& inner) {
              ParseContent(b, inner, kSchemas | kChannels | kMessages, found);
            });
            Keep(found, schemas_, channels_, metadata_);
            McapChunkIndex index;
            index.message_start_time = c.start_time;
            index.message_end_time = c.end_time;
            index.chunk_start_offset = r.start;
            index.chunk_length = r.end() - r.start;
            index.compression = c.compression;
            index.compressed_size = index.uncompressed_size = c.uncompressed_size;
            chunk_indexes_.push_back(index);
            for (const McapMessage& m : found.messages) count(m);
            counting_skipped = false;
            break;
          }
          case Op::kMessageIndex:
            if (counting_skipped) {
              skipped_.back().messages += MessageIndexEntries(b, r);
              skipped_.back().messages_known = true;
            }
            break;
          case Op::kDataEnd:
            if (skipped_.empty()) {
              recovered_ = false;
              recovery_note_.clear();
            }
            stop = true;
            break;
          case Op::kFooter:
            stop = true;
            break;
          default:
            break;  // attachments, unknown records
        }
      }
      recovered_bytes_ = it.pos();
      if (stop) break;
    } catch (const McapError& e) {
      it.Seek(skip(start, e.what()));
    }
  }
  if (!skipped_.empty()) {
    recovered_ = true;
    recovery_note_ = std::to_string(skipped_.size()) + " damaged or cut-off byte range" +
                     (skipped_.size() > 1 ? "s" : "") +
                     " skipped; the first: " + DescribeSkipped(skipped_.front());
  }
  statistics_.schema_count = static_cast<std::uint16_t>(schemas_.size());
  statistics_.channel_count = static_cast<std::uint32_t>(channels_.size());
  statistics_.metadata_count = static_cast<std::uint32_t>(metadata_.size());
  statistics_.chunk_count = static_cast<std::uint32_t>(chunk_indexes_.size());
  has_statistics_ = true;
}

std::vector<McapMessage> McapReader::ChunkMessages(const McapChunkIndex& index) const {
  const RecordView r = RecordAt(bytes_, index.chunk_start_offset, bytes_.size());
  if (r.op != Op::kChunk) {
    throw McapError("chunk index points to opcode " + Hex(static_cast<unsigned>(r.op)),
                    index.chunk_start_offset);
  }
  Content found;
  mcap::WalkChunk(bytes_, r,
                  [&](const RecordView& inner) { ParseContent(bytes_, inner, kMessages, found); });
  return std::move(found.messages);
}

void McapReader::ForEachMessage(const std::function<void(const McapMessage&)>& fn) const {
  // merge: before emitting time t, load every chunk that starts at or before t
  std::vector<const McapChunkIndex*> chunks;
  for (const McapChunkIndex& c : chunk_indexes_) chunks.push_back(&c);
  std::stable_sort(chunks.begin(), chunks.end(), [](const auto* a, const auto* b) {
    return a->message_start_time < b->message_start_time;
  });
  std::vector<McapMessage> store;
  using Key = std::tuple<std::uint64_t, std::uint64_t>;  // (log_time, load order = store index)
  std::priority_queue<Key, std::vector<Key>, std::greater<Key>> heap;
  auto push = [&](McapMessage m) {
    heap.emplace(m.log_time, store.size());
    store.push_back(std::move(m));
  };
  for (const McapMessage& m : loose_messages_) push(m);
  std::size_t next = 0;
  while (true) {
    while (next < chunks.size() &&
           (heap.empty() || chunks[next]->message_start_time <= std::get<0>(heap.top()))) {
      for (McapMessage& m : ChunkMessages(*chunks[next])) push(std::move(m));
      ++next;
    }
    if (heap.empty()) break;
    const std::uint64_t i = std::get<1>(heap.top());
    heap.pop();
    fn(store[i]);
    store[i].data = {};  // release the payload
  }
}

std::vector<McapMessage> McapReader::ReadMessages() const {
  std::vector<McapMessage> out;
  ForEachMessage([&](const McapMessage& m) { out.push_back(m); });
  return out;
}

}  // namespace towsim::io
