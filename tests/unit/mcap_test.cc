// McapWriter / McapReader: round trips, CRCs, statistics, recovery of a cut-off recording and
// the byte layout of the records against the MCAP specification (https://mcap.dev/spec).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/mcap_format.h"
#include "io/mcap_reader.h"
#include "io/mcap_writer.h"

namespace towsim::io {
namespace {

using mcap::McapError;

constexpr std::uint64_t kMs = 1'000'000;                     // [ns]
constexpr std::uint64_t kT0 = 1'700'000'000'000'000'000ull;  // an epoch-like start [ns]

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "towsim_mcap_" + name + ".mcap";
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void Spit(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::uint64_t Le(const std::string& b, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= std::uint64_t(static_cast<unsigned char>(b[at + i])) << 8 * i;
  return v;
}

// a deterministic payload: CDR little-endian encapsulation header, then channel and index
std::vector<std::uint8_t> Payload(std::uint16_t channel, std::uint32_t i) {
  std::vector<std::uint8_t> p = {0x00, 0x01, 0x00, 0x00};
  for (int k = 0; k < 4; ++k) p.push_back(static_cast<std::uint8_t>(i >> 8 * k));
  p.push_back(static_cast<std::uint8_t>(channel));
  p.resize(p.size() + (i % 37), static_cast<std::uint8_t>(i * 7 + channel));  // varying size
  return p;
}

struct Sent {
  std::uint16_t channel;
  std::uint32_t sequence;
  std::uint64_t log_time;
};

// writes `n` messages round-robin on three channels, 1 ms apart (so a chunk spans <= 1 s)
std::vector<Sent> WriteRecording(const std::string& path, int n, McapWriter::Options options = {}) {
  McapWriter w(options);
  w.Open(path, "ros2");
  const std::uint16_t s1 = w.AddSchema("towsim_msgs/msg/BodyState", "ros2msg",
                                       "float64 x\n================================================"
                                       "================================\nMSG: a/B\nint32 y\n");
  const std::uint16_t s2 =
      w.AddSchema("rosgraph_msgs/msg/Clock", "ros2msg", "builtin_interfaces/Time clock\n");
  const std::vector<std::uint16_t> ch = {
      w.AddChannel(s1, "/towsim/body_state", "cdr", {{"offered_qos_profiles", ""}}),
      w.AddChannel(s2, "/clock", "cdr", {}),
      w.AddChannel(s1, "/towsim/cable_state", "cdr", {{"k", "v"}}),
  };
  w.AddMetadata("towsim", {{"scene", "case1.yaml"}});
  std::vector<Sent> sent;
  std::map<std::uint16_t, std::uint32_t> seq;
  for (int i = 0; i < n; ++i) {
    const std::uint16_t c = ch[i % 3];
    const std::uint64_t t = kT0 + static_cast<std::uint64_t>(i) * kMs;
    const std::uint32_t s = seq[c]++;
    w.Write(c, s, t, t - 5, Payload(c, static_cast<std::uint32_t>(i)));
    sent.push_back({c, s, t});
  }
  w.Close();
  return sent;
}

TEST(McapTest, RoundTripSeveralChannelsAndChunks) {
  const std::string path = TempPath("roundtrip");
  constexpr int kMessages = 10'000;  // 10 s of log time: >= 10 chunks by the 1 s rule
  const std::vector<Sent> sent = WriteRecording(path, kMessages);

  const McapReader r = McapReader::Open(path);
  EXPECT_EQ(r.profile(), "ros2");
  EXPECT_EQ(r.library(), "towsim");
  ASSERT_EQ(r.schemas().size(), 2u);
  EXPECT_EQ(r.schemas().at(1).name, "towsim_msgs/msg/BodyState");
  EXPECT_EQ(r.schemas().at(1).encoding, "ros2msg");
  EXPECT_NE(r.schemas().at(1).data.find("\nMSG: a/B\n"), std::string::npos);
  ASSERT_EQ(r.channels().size(), 3u);
  EXPECT_EQ(r.channels().at(0).topic, "/towsim/body_state");
  EXPECT_EQ(r.channels().at(0).message_encoding, "cdr");
  EXPECT_EQ(r.channels().at(0).metadata.at("offered_qos_profiles"), "");
  EXPECT_EQ(r.channels().at(2).metadata.at("k"), "v");
  EXPECT_EQ(r.channels().at(1).schema_id, 2);
  ASSERT_EQ(r.metadata().size(), 1u);
  EXPECT_EQ(r.metadata()[0].name, "towsim");
  EXPECT_EQ(r.metadata()[0].metadata.at("scene"), "case1.yaml");
  EXPECT_GE(r.chunk_indexes().size(), 10u);
  for (const McapChunkIndex& c : r.chunk_indexes()) {
    EXPECT_LT(c.message_end_time - c.message_start_time, 1000 * kMs);
    EXPECT_EQ(c.compression, "");
    EXPECT_EQ(c.message_index_offsets.size(), 3u);
  }

  const std::vector<McapMessage> got = r.ReadMessages();
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].channel_id, sent[i].channel) << i;
    ASSERT_EQ(got[i].sequence, sent[i].sequence) << i;
    ASSERT_EQ(got[i].log_time, sent[i].log_time) << i;
    ASSERT_EQ(got[i].publish_time, sent[i].log_time - 5) << i;
    ASSERT_EQ(got[i].data, Payload(sent[i].channel, static_cast<std::uint32_t>(i))) << i;
  }
}

TEST(McapTest, SizeLimitClosesChunks) {
  const std::string path = TempPath("size");
  McapWriter::Options options;
  options.chunk_size = 4096;
  WriteRecording(path, 3000, options);
  const McapReader r = McapReader::Open(path);
  // ~3000 messages of 9..45 + 31 bytes each: well over 20 chunks of 4 KiB
  EXPECT_GT(r.chunk_indexes().size(), 20u);
  for (const McapChunkIndex& c : r.chunk_indexes()) {
    EXPECT_LT(c.uncompressed_size, 4096u + 200u);  // one message past the limit at most
  }
  EXPECT_EQ(r.ReadMessages().size(), 3000u);
}

TEST(McapTest, MessagesComeOutInLogTimeOrder) {
  const std::string path = TempPath("order");
  McapWriter::Options options;
  options.chunk_size = 64;  // about one message per chunk: order must come from the merge
  {
    McapWriter w(options);
    w.Open(path);
    const auto c = w.AddChannel(0, "/a");
    const std::uint64_t times[] = {50, 10, 30, 20, 40, 10};
    std::uint32_t s = 0;
    for (std::uint64_t t : times) w.Write(c, s++, t, t, std::vector<std::uint8_t>(40, 1));
    w.Close();
  }
  const std::vector<McapMessage> got = McapReader::Open(path).ReadMessages();
  ASSERT_EQ(got.size(), 6u);
  const std::uint64_t want[] = {10, 10, 20, 30, 40, 50};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(got[i].log_time, want[i]) << i;
  EXPECT_EQ(got[0].sequence, 1u);  // ties in file order
  EXPECT_EQ(got[1].sequence, 5u);
}

TEST(McapTest, StatisticsCounts) {
  const std::string path = TempPath("stats");
  WriteRecording(path, 1000);
  const McapReader r = McapReader::Open(path);
  ASSERT_TRUE(r.has_statistics());
  const McapStatistics& s = r.statistics();
  EXPECT_EQ(s.message_count, 1000u);
  EXPECT_EQ(s.schema_count, 2u);
  EXPECT_EQ(s.channel_count, 3u);
  EXPECT_EQ(s.attachment_count, 0u);
  EXPECT_EQ(s.metadata_count, 1u);
  EXPECT_EQ(s.chunk_count, r.chunk_indexes().size());
  EXPECT_EQ(s.chunk_count, 1u);  // 1000 ms of log time: one chunk (span 999 ms)
  EXPECT_EQ(s.message_start_time, kT0);
  EXPECT_EQ(s.message_end_time, kT0 + 999 * kMs);
  ASSERT_EQ(s.channel_message_counts.size(), 3u);
  EXPECT_EQ(s.channel_message_counts.at(0), 334u);
  EXPECT_EQ(s.channel_message_counts.at(1), 333u);
  EXPECT_EQ(s.channel_message_counts.at(2), 333u);
}

TEST(McapTest, EmptyFileIsValid) {
  const std::string path = TempPath("empty");
  {
    McapWriter w;
    w.Open(path);
  }  // the destructor closes
  const McapReader r = McapReader::Open(path);
  EXPECT_EQ(r.statistics().message_count, 0u);
  EXPECT_TRUE(r.ReadMessages().empty());
}

TEST(McapTest, CrcDetectsFlippedByteInChunk) {
  const std::string path = TempPath("flip");
  WriteRecording(path, 5000);  // 5 chunks
  std::string b = Slurp(path);
  const McapReader good = McapReader::OpenBytes(b);
  ASSERT_EQ(good.chunk_indexes().size(), 5u);
  const McapChunkIndex c = good.chunk_indexes().at(1);
  const std::uint64_t at = c.chunk_start_offset + c.chunk_length - 3;  // in a payload
  b[at] = static_cast<char>(b[at] ^ 0x10);
  // the data section CRC catches it on open
  try {
    McapReader::OpenBytes(b);
    FAIL() << "flipped byte not detected";
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find("data section CRC mismatch"), std::string::npos)
        << e.what();
  }
  // recovery checks the chunk CRC, skips the damaged chunk (naming its offset) and keeps the
  // four intact ones, before and after it
  const McapReader rec = McapReader::RecoverBytes(b);
  EXPECT_EQ(rec.chunk_indexes().size(), 4u);
  EXPECT_NE(rec.recovery_note().find("chunk CRC mismatch"), std::string::npos)
      << rec.recovery_note();
  EXPECT_NE(rec.recovery_note().find(std::to_string(c.chunk_start_offset)), std::string::npos);
  ASSERT_EQ(rec.skipped().size(), 1u);
  const McapSkipped& skipped = rec.skipped()[0];
  EXPECT_EQ(skipped.begin, c.chunk_start_offset);
  EXPECT_EQ(skipped.end, c.chunk_start_offset + c.chunk_length);
  // the skipped chunk's messages, counted from its message indexes, are exactly those lost
  std::uint64_t in_chunk = 0;
  for (const McapMessage& m : good.ReadMessages()) {
    in_chunk += m.log_time >= c.message_start_time && m.log_time <= c.message_end_time;
  }
  EXPECT_TRUE(skipped.messages_known);
  EXPECT_EQ(skipped.messages, in_chunk);
  EXPECT_EQ(rec.ReadMessages().size(), 5000u - in_chunk);
}

TEST(McapTest, RecoveryResynchronisesAfterADamagedRecordHeader) {
  const std::string path = TempPath("flip_header");
  WriteRecording(path, 3000);
  std::string b = Slurp(path);
  const McapReader good = McapReader::OpenBytes(b);
  // the header's length (byte 9: after the magic and the opcode): the scan cannot step over it
  b[9] = static_cast<char>(b[9] ^ 0x40);
  const McapReader rec = McapReader::RecoverBytes(b);
  ASSERT_EQ(rec.skipped().size(), 1u);
  EXPECT_EQ(rec.skipped()[0].begin, 8u);
  // everything after the header is kept: schemas, channels, every chunk and message
  EXPECT_EQ(rec.schemas().size(), good.schemas().size());
  EXPECT_EQ(rec.channels().size(), good.channels().size());
  EXPECT_EQ(rec.chunk_indexes().size(), good.chunk_indexes().size());
  EXPECT_EQ(rec.ReadMessages().size(), 3000u);
}

TEST(McapTest, CrcDetectsFlippedByteInSummary) {
  const std::string path = TempPath("flip_summary");
  WriteRecording(path, 100);
  std::string b = Slurp(path);
  const std::uint64_t footer = b.size() - 8 - 29;
  const std::uint64_t summary_start = Le(b, footer + 9, 8);
  b[summary_start + 20] = static_cast<char>(b[summary_start + 20] ^ 0x01);
  try {
    McapReader::OpenBytes(b);
    FAIL() << "flipped byte not detected";
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find("summary CRC mismatch"), std::string::npos) << e.what();
    EXPECT_EQ(e.offset(), summary_start);
  }
}

TEST(McapTest, TruncatedFileRecoversEveryCompleteChunk) {
  const std::string path = TempPath("full");
  const std::vector<Sent> sent = WriteRecording(path, 5000);  // 5 chunks
  const std::string b = Slurp(path);
  const McapReader full = McapReader::OpenBytes(b);
  ASSERT_EQ(full.chunk_indexes().size(), 5u);
  const McapChunkIndex& third = full.chunk_indexes()[2];

  // cut in the middle of the third chunk, as a SIGKILL during its write would
  const std::string cut_path = TempPath("cut");
  Spit(cut_path, b.substr(0, third.chunk_start_offset + third.chunk_length / 2));
  try {
    McapReader::Open(cut_path);
    FAIL() << "truncated file opened as complete";
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find("trailing magic"), std::string::npos) << e.what();
  }
  const McapReader r = McapReader::Recover(cut_path);
  EXPECT_TRUE(r.recovered());
  EXPECT_EQ(r.recovered_bytes(), third.chunk_start_offset);
  EXPECT_EQ(r.chunk_indexes().size(), 2u);
  EXPECT_EQ(r.channels().size(), 3u);
  EXPECT_EQ(r.schemas().size(), 2u);
  const std::vector<McapMessage> got = r.ReadMessages();
  // the first two chunks hold the first two seconds of log time
  std::uint64_t expected = 0;
  for (const Sent& s : sent) expected += s.log_time <= full.chunk_indexes()[1].message_end_time;
  ASSERT_EQ(got.size(), expected);
  EXPECT_EQ(r.statistics().message_count, expected);
  for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i].log_time, sent[i].log_time);

  // a cut just after a chunk's message indexes keeps that chunk too
  Spit(cut_path,
       b.substr(0, third.chunk_start_offset + third.chunk_length + third.message_index_length));
  EXPECT_EQ(McapReader::Recover(cut_path).chunk_indexes().size(), 3u);

  // a complete file recovers fully and is not marked as recovered
  const McapReader whole = McapReader::RecoverBytes(b);
  EXPECT_FALSE(whole.recovered());
  EXPECT_EQ(whole.ReadMessages().size(), sent.size());
}

TEST(McapTest, FlushedChunksAreOnDiskBeforeClose) {
  const std::string path = TempPath("killed");
  McapWriter w;
  w.Open(path);
  const auto c = w.AddChannel(0, "/clock");
  for (int i = 0; i <= 2500; ++i) {  // 2.5 s: two chunks closed, the third open
    const std::uint64_t t = kT0 + static_cast<std::uint64_t>(i) * kMs;
    w.Write(c, static_cast<std::uint32_t>(i), t, t, Payload(c, static_cast<std::uint32_t>(i)));
  }
  // what a SIGKILL now would leave on disk
  const McapReader r = McapReader::Recover(path);
  EXPECT_TRUE(r.recovered());
  EXPECT_EQ(r.chunk_indexes().size(), 2u);
  EXPECT_EQ(r.statistics().message_count, 2000u);
  w.Flush();  // a timer-driven flush writes the open chunk too
  EXPECT_EQ(McapReader::Recover(path).statistics().message_count, 2501u);
  w.Close();
  EXPECT_EQ(McapReader::Open(path).statistics().message_count, 2501u);
}

TEST(McapTest, ErrorsNameTheOffsetAndNeverCrash) {
  const std::string path = TempPath("fuzz");
  WriteRecording(path, 300);
  const std::string b = Slurp(path);
  EXPECT_THROW(McapReader::OpenBytes("not an mcap file at all, sorry"), McapError);
  EXPECT_THROW(McapReader::RecoverBytes("\x89MCAP0\r"), McapError);
  // every prefix length: Open throws McapError, Recover returns a consistent prefix
  for (std::size_t n = 0; n < b.size(); n += 97) {
    const std::string prefix = b.substr(0, n);
    EXPECT_THROW(McapReader::OpenBytes(prefix), McapError) << n;
    if (n >= 8 + 9 + 18) {
      const McapReader r = McapReader::RecoverBytes(prefix);
      EXPECT_LE(r.ReadMessages().size(), 300u);
    }
  }
  // single flipped bytes anywhere: an McapError (never a crash) or, for bytes no CRC
  // covers (a CRC field itself set to something else), a successful open
  for (std::size_t at = 0; at < b.size(); at += 13) {
    std::string bad = b;
    bad[at] = static_cast<char>(bad[at] ^ 0x40);
    try {
      McapReader::OpenBytes(bad).ReadMessages();
    } catch (const McapError&) {
    }
  }
}

TEST(McapTest, NothingRecoveredOnlyWhenNoMessageSurvivesTheDamage) {
  // the magic alone: the header is cut off, nothing survives
  const McapReader magic = McapReader::RecoverBytes(std::string("\x89MCAP0\r\n", 8));
  EXPECT_EQ(NothingRecovered(magic),
            "nothing to recover: no intact chunk (no message survives the 1 byte ranges "
            "skipped)");
  // a whole file: nothing skipped; one cut off inside its first chunk: nothing survives
  const std::string path = TempPath("nothing");
  WriteRecording(path, 300);
  const std::string b = Slurp(path);
  EXPECT_EQ(NothingRecovered(McapReader::RecoverBytes(b)), "");
  const McapChunkIndex first = McapReader::OpenBytes(b).chunk_indexes().at(0);
  const McapReader cut =
      McapReader::RecoverBytes(b.substr(0, first.chunk_start_offset + first.chunk_length / 2));
  EXPECT_EQ(NothingRecovered(cut),
            "nothing to recover: no intact chunk (no message survives the 1 byte ranges "
            "skipped)");
}

TEST(McapTest, ByteLayoutMatchesTheSpecification) {
  const std::string path = TempPath("layout");
  {
    McapWriter w;
    w.Open(path, "ros2");
    const auto s = w.AddSchema("pkg/msg/T", "ros2msg", "int32 a\n");
    const auto c = w.AddChannel(s, "/t", "cdr", {});
    w.Write(c, 7, 1000, 999, std::vector<std::uint8_t>{0, 1, 0, 0, 42, 0, 0, 0});
    w.Close();
  }
  const std::string b = Slurp(path);
  const unsigned char magic[8] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};
  ASSERT_GT(b.size(), 16u);
  EXPECT_EQ(std::memcmp(b.data(), magic, 8), 0);
  EXPECT_EQ(std::memcmp(b.data() + b.size() - 8, magic, 8), 0);

  // header: opcode 0x01, u64 length, profile "ros2", library "towsim"
  std::size_t p = 8;
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x01);
  EXPECT_EQ(Le(b, p + 1, 8), 4u + 4u + 4u + 6u);
  EXPECT_EQ(Le(b, p + 9, 4), 4u);
  EXPECT_EQ(b.substr(p + 13, 4), "ros2");
  EXPECT_EQ(Le(b, p + 17, 4), 6u);
  EXPECT_EQ(b.substr(p + 21, 6), "towsim");
  p += 9 + Le(b, p + 1, 8);

  // schema 0x03: id u16 = 1, name, encoding, u32-prefixed data
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x03);
  EXPECT_EQ(Le(b, p + 9, 2), 1u);
  EXPECT_EQ(Le(b, p + 11, 4), 9u);
  EXPECT_EQ(b.substr(p + 15, 9), "pkg/msg/T");
  p += 9 + Le(b, p + 1, 8);
  // channel 0x04: id 0, schema 1, topic, encoding, empty map (u32 0)
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x04);
  EXPECT_EQ(Le(b, p + 1, 8), 2u + 2u + (4 + 2) + (4 + 3) + 4u);
  EXPECT_EQ(Le(b, p + 9, 2), 0u);
  EXPECT_EQ(Le(b, p + 11, 2), 1u);
  p += 9 + Le(b, p + 1, 8);

  // chunk 0x06: start, end, uncompressed size, crc, compression "", u64 records length
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x06);
  const std::size_t chunk_start = p;
  const std::uint64_t records = Le(b, p + 9 + 16, 8);
  const std::uint64_t message_record = 9 + 2 + 4 + 8 + 8 + 8;
  EXPECT_EQ(records, message_record);
  EXPECT_EQ(Le(b, p + 9, 8), 1000u);
  EXPECT_EQ(Le(b, p + 17, 8), 1000u);
  EXPECT_EQ(Le(b, p + 37, 4), 0u);  // compression "" = none
  EXPECT_EQ(Le(b, p + 41, 8), records);
  const std::size_t rec = p + 49;
  EXPECT_EQ(Le(b, p + 33, 4), mcap::ComputeCrc32(b.data() + rec, records));
  // the message 0x05 inside: channel, sequence, log_time, publish_time, data
  EXPECT_EQ(static_cast<unsigned char>(b[rec]), 0x05);
  EXPECT_EQ(Le(b, rec + 9, 2), 0u);
  EXPECT_EQ(Le(b, rec + 11, 4), 7u);
  EXPECT_EQ(Le(b, rec + 15, 8), 1000u);
  EXPECT_EQ(Le(b, rec + 23, 8), 999u);
  EXPECT_EQ(static_cast<unsigned char>(b[rec + 35]), 42);
  p += 9 + Le(b, p + 1, 8);
  const std::size_t chunk_length = p - chunk_start;

  // message index 0x07: channel 0, one (log_time, offset 0) entry
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x07);
  EXPECT_EQ(Le(b, p + 1, 8), 2u + 4u + 16u);
  EXPECT_EQ(Le(b, p + 11, 4), 16u);
  EXPECT_EQ(Le(b, p + 15, 8), 1000u);
  EXPECT_EQ(Le(b, p + 23, 8), 0u);
  const std::size_t message_index = p;
  p += 9 + Le(b, p + 1, 8);

  // data end 0x0F: CRC of every byte before it
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x0F);
  EXPECT_EQ(Le(b, p + 1, 8), 4u);
  EXPECT_EQ(Le(b, p + 9, 4), mcap::ComputeCrc32(b.data(), p));
  p += 13;
  const std::size_t summary_start = p;

  // summary: schema, channel, statistics, chunk index groups
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x03);
  p += 9 + Le(b, p + 1, 8);
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x04);
  p += 9 + Le(b, p + 1, 8);
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x0B);
  const std::size_t statistics = p;
  EXPECT_EQ(Le(b, p + 9, 8), 1u);  // message_count
  p += 9 + Le(b, p + 1, 8);
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x08);
  EXPECT_EQ(Le(b, p + 9, 8), 1000u);
  EXPECT_EQ(Le(b, p + 25, 8), chunk_start);
  EXPECT_EQ(Le(b, p + 33, 8), chunk_length);
  EXPECT_EQ(Le(b, p + 41, 4), 10u);  // one (u16, u64) entry
  EXPECT_EQ(Le(b, p + 45, 2), 0u);
  EXPECT_EQ(Le(b, p + 47, 8), message_index);
  EXPECT_EQ(Le(b, p + 55, 8), 9u + 22u);  // message_index_length
  p += 9 + Le(b, p + 1, 8);

  // summary offsets 0x0E: (group opcode, start, length) for the four groups
  const std::size_t summary_offset_start = p;
  const unsigned char groups[] = {0x03, 0x04, 0x0B, 0x08};
  for (unsigned char g : groups) {
    EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x0E);
    EXPECT_EQ(Le(b, p + 1, 8), 17u);
    EXPECT_EQ(static_cast<unsigned char>(b[p + 9]), g);
    if (g == 0x0B) {
      EXPECT_EQ(Le(b, p + 10, 8), statistics);
    }
    p += 9 + 17;
  }

  // footer 0x02: summary_start, summary_offset_start, summary CRC, then the magic
  EXPECT_EQ(static_cast<unsigned char>(b[p]), 0x02);
  EXPECT_EQ(Le(b, p + 1, 8), 20u);
  EXPECT_EQ(Le(b, p + 9, 8), summary_start);
  EXPECT_EQ(Le(b, p + 17, 8), summary_offset_start);
  EXPECT_EQ(Le(b, p + 25, 4), mcap::ComputeCrc32(b.data() + summary_start, p + 25 - summary_start));
  EXPECT_EQ(p + 29 + 8, b.size());
}

TEST(McapTest, DataCrcFromAfterTheMagicIsAccepted) {
  // some writers start the data section CRC after the leading magic; both are accepted
  const std::string path = TempPath("crc8");
  WriteRecording(path, 100);
  std::string b = Slurp(path);
  const std::uint64_t footer = b.size() - 8 - 29;
  const std::uint64_t data_end = Le(b, footer + 9, 8) - 13;
  ASSERT_EQ(static_cast<unsigned char>(b[data_end]), 0x0F);
  const std::uint32_t crc8 = mcap::ComputeCrc32(b.data() + 8, data_end - 8);
  for (int k = 0; k < 4; ++k) b[data_end + 9 + k] = static_cast<char>(crc8 >> 8 * k);
  EXPECT_EQ(McapReader::OpenBytes(b).ReadMessages().size(), 100u);
  b[data_end + 9] = static_cast<char>(b[data_end + 9] ^ 1);  // and a wrong one is not
  EXPECT_THROW(McapReader::OpenBytes(b), McapError);
}

TEST(McapTest, FsyncOptionWritesTheSameFile) {
  McapWriter::Options options;
  options.fsync = true;
  WriteRecording(TempPath("fsync"), 2500, options);
  WriteRecording(TempPath("nofsync"), 2500);
  EXPECT_EQ(Slurp(TempPath("fsync")), Slurp(TempPath("nofsync")));
}

TEST(McapTest, Crc32MatchesTheStandardCheckValue) {
  // the CRC-32/ISO-HDLC check value of "123456789"
  EXPECT_EQ(mcap::ComputeCrc32("123456789", 9), 0xCBF43926u);
}

TEST(McapTest, WriterRejectsUnknownIds) {
  McapWriter w;
  w.Open(TempPath("ids"));
  EXPECT_THROW(w.AddChannel(3, "/x"), std::invalid_argument);
  EXPECT_THROW(w.Write(0, 0, 0, 0, nullptr, 0), std::invalid_argument);
  w.Close();
  EXPECT_THROW(w.Open(TempPath("ids2")), std::runtime_error);  // one file per writer
}

}  // namespace
}  // namespace towsim::io
