// RecordIterator and WalkChunk (sim_node/io/mcap_records): a file McapWriter wrote, walked
// record by record; a cut-off file and a corrupt length, with the offset and text of the error.
#include "io/mcap_records.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/mcap_format.h"
#include "io/mcap_writer.h"

namespace towsim::io::mcap {
namespace {

// a message record with a 4-byte payload: prefix, channel, sequence, log and publish time, data
constexpr std::uint64_t kMessageRecord = 9 + 2 + 4 + 8 + 8 + 4;
// a chunk's fields before its records: start, end, uncompressed size, CRC, compression "",
// records length
constexpr std::uint64_t kChunkFields = 8 + 8 + 8 + 4 + (4 + 0) + 8;

// header, schema, channel, metadata, then three messages 1 us apart in one chunk; closed
std::string WrittenFile() {
  const std::string path = ::testing::TempDir() + "towsim_mcap_records.mcap";
  {
    McapWriter w;
    w.Open(path, "ros2");
    const auto s = w.AddSchema("pkg/msg/T", "ros2msg", "int32 a\n");
    const auto c = w.AddChannel(s, "/t", "cdr", {});
    w.AddMetadata("towsim", {{"scene", "case1.yaml"}});
    for (std::uint32_t i = 0; i < 3; ++i) {
      w.Write(c, i, 1000 + 1000 * i, 1000 + 1000 * i, std::vector<std::uint8_t>{0, 1, 0, 0});
    }
    w.Close();
  }
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// every record between the magics, in order
std::vector<RecordView> Walk(const std::string& b) {
  std::vector<RecordView> records;
  for (RecordIterator it(b, kMagicSize, b.size() - kMagicSize); !it.done();) {
    records.push_back(it.Next());
  }
  return records;
}

std::uint64_t RecordOffset(const std::vector<RecordView>& records, Op op) {
  for (const RecordView& r : records) {
    if (r.op == op) return r.start;
  }
  ADD_FAILURE() << "no record of opcode " << Hex(static_cast<unsigned>(op));
  return 0;
}

TEST(McapRecordsTest, WalksAWrittenFileRecordByRecord) {
  const std::string b = WrittenFile();
  const std::vector<RecordView> records = Walk(b);
  // the data section, the summary (one group per record kind), its offsets, the footer
  const std::vector<Op> expected = {Op::kHeader,        Op::kSchema,        Op::kChannel,
                                    Op::kMetadata,      Op::kChunk,         Op::kMessageIndex,
                                    Op::kDataEnd,       Op::kSchema,        Op::kChannel,
                                    Op::kStatistics,    Op::kMetadataIndex, Op::kChunkIndex,
                                    Op::kSummaryOffset, Op::kSummaryOffset, Op::kSummaryOffset,
                                    Op::kSummaryOffset, Op::kSummaryOffset, Op::kFooter};
  ASSERT_EQ(records.size(), expected.size());
  std::uint64_t pos = kMagicSize;
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(records[i].op, expected[i]) << i;
    EXPECT_EQ(records[i].start, pos) << i;  // back to back
    EXPECT_EQ(records[i].content, pos + kRecordPrefixSize) << i;
    pos = records[i].end();
  }
  EXPECT_EQ(pos, b.size() - kMagicSize);
  EXPECT_EQ(records.back().length, kFooterContentSize);
  EXPECT_EQ(records[6].length, 4u);  // the data end holds its CRC

  // the chunk walk: the three messages, back to back from the chunk's records
  const RecordView& chunk = records[4];
  std::vector<RecordView> inner;
  const ChunkView c = WalkChunk(b, chunk, [&](const RecordView& r) { inner.push_back(r); });
  EXPECT_EQ(c.start_time, 1000u);
  EXPECT_EQ(c.end_time, 3000u);
  EXPECT_EQ(c.compression, "");
  EXPECT_EQ(c.records_begin, chunk.content + kChunkFields);
  EXPECT_EQ(c.records_end, chunk.end());
  ASSERT_EQ(inner.size(), 3u);
  for (std::size_t i = 0; i < inner.size(); ++i) {
    EXPECT_EQ(inner[i].op, Op::kMessage);
    EXPECT_EQ(inner[i].start, c.records_begin + i * kMessageRecord);
    EXPECT_EQ(inner[i].end() - inner[i].start, kMessageRecord);
  }
  EXPECT_EQ(c.uncompressed_size, 3 * kMessageRecord);
}

TEST(McapRecordsTest, StopsAtTheLastWholeRecordOfACutFile) {
  const std::string b = WrittenFile();
  const std::uint64_t chunk = RecordOffset(Walk(b), Op::kChunk);

  // cut in the chunk's content: the four records before it, then the error at its start
  const std::string cut = b.substr(0, chunk + 30);
  RecordIterator it(cut, kMagicSize, cut.size());
  std::vector<Op> ops;
  try {
    while (!it.done()) ops.push_back(it.Next().op);
    FAIL() << "the cut chunk was returned";
  } catch (const McapError& e) {
    EXPECT_EQ(e.offset(), chunk);
    EXPECT_EQ(std::string(e.what()), "record (opcode 0x6) of " +
                                         std::to_string(kChunkFields + 3 * kMessageRecord) +
                                         " bytes runs past the end (" + std::to_string(chunk + 30) +
                                         ") (at byte offset " + std::to_string(chunk) + ")");
  }
  EXPECT_EQ(ops, (std::vector<Op>{Op::kHeader, Op::kSchema, Op::kChannel, Op::kMetadata}));
  EXPECT_EQ(it.pos(), chunk);  // the end of the last whole record

  // cut in the chunk's length field: the prefix itself does not fit
  const std::string cut_prefix = b.substr(0, chunk + 4);
  RecordIterator at_prefix(cut_prefix, chunk, cut_prefix.size());
  try {
    at_prefix.Next();
    FAIL() << "a 4-byte record prefix was read";
  } catch (const McapError& e) {
    EXPECT_EQ(std::string(e.what()),
              "truncated record header: need 8 bytes, 3 left (at byte offset " +
                  std::to_string(chunk + 1) + ")");
  }
  EXPECT_EQ(at_prefix.pos(), chunk);
}

// writes `v` as the u64 at `at`
void PutU64(std::string& b, std::uint64_t at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) b[at + i] = static_cast<char>((v >> (8 * i)) & 0xFFu);
}

TEST(McapRecordsTest, ACorruptLengthIsAnErrorAtItsRecord) {
  const std::string b = WrittenFile();
  const std::vector<RecordView> records = Walk(b);
  const std::uint64_t schema = RecordOffset(records, Op::kSchema);

  // the schema's length grown past the data section: the walk stops at the schema
  std::string bad = b;
  PutU64(bad, schema + 1, 1ull << 40);
  RecordIterator it(bad, kMagicSize, bad.size());
  EXPECT_EQ(it.Next().op, Op::kHeader);
  try {
    it.Next();
    FAIL() << "a schema of 2^40 bytes was returned";
  } catch (const McapError& e) {
    EXPECT_EQ(e.offset(), schema);
    EXPECT_EQ(std::string(e.what()),
              "record (opcode 0x3) of 1099511627776 bytes runs past the end (" +
                  std::to_string(bad.size()) + ") (at byte offset " + std::to_string(schema) + ")");
  }
  EXPECT_EQ(it.pos(), schema);

  // the last message's length in the chunk one byte longer: the chunk CRC catches it, and with
  // the CRC cleared (0: not computed) the chunk walk stops at that message, the chunk's end
  const RecordView chunk = records[4];
  ASSERT_EQ(chunk.op, Op::kChunk);
  const std::uint64_t records_begin = chunk.content + kChunkFields;
  const std::uint64_t last = records_begin + 2 * kMessageRecord;
  bad = b;
  PutU64(bad, last + 1, kMessageRecord - kRecordPrefixSize + 1);
  const auto ignore = [](const RecordView&) {};
  try {
    WalkChunk(bad, chunk, ignore);
    FAIL() << "the changed chunk passed its CRC";
  } catch (const McapError& e) {
    EXPECT_EQ(e.offset(), chunk.start);
    EXPECT_NE(std::string(e.what()).find("chunk CRC mismatch: stored 0x"), std::string::npos)
        << e.what();
  }
  for (int i = 0; i < 4; ++i) bad[chunk.content + 24 + i] = 0;  // the CRC field
  std::vector<std::uint64_t> walked;
  try {
    WalkChunk(bad, chunk, [&](const RecordView& r) { walked.push_back(r.start); });
    FAIL() << "a message past the chunk's end was returned";
  } catch (const McapError& e) {
    EXPECT_EQ(e.offset(), last);
    EXPECT_EQ(std::string(e.what()),
              "record (opcode 0x5) of " + std::to_string(kMessageRecord - kRecordPrefixSize + 1) +
                  " bytes runs past the end (" + std::to_string(chunk.end()) +
                  ") (at byte offset " + std::to_string(last) + ")");
  }
  EXPECT_EQ(walked, (std::vector<std::uint64_t>{records_begin, records_begin + kMessageRecord}));
}

}  // namespace
}  // namespace towsim::io::mcap
