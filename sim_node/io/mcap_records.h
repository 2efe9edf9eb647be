#pragma once
// Walking the records of an MCAP file (https://mcap.dev/spec, "Records"): the one record
// iterator and the one chunk walk that McapReader's three paths share (the summary section,
// the linear scan of the data section, and the recovery's search for where records resume).
//
// A record is <opcode u8><content length u64><content> (mcap_format.h); a chunk record's
// content ends in <records length u64><records>, the records of the chunk back to back.

#include <cstdint>
#include <functional>
#include <string>

#include "io/mcap_format.h"

namespace towsim::io::mcap {

// one record in a buffer: where it starts, where its content lies
struct RecordView {
  Op op;
  std::uint64_t start;    // offset of the opcode
  std::uint64_t content;  // offset of the content
  std::uint64_t length;   // content length
  std::uint64_t end() const { return content + length; }
};

// the record at `pos`, which must lie within [pos, limit); throws McapError "truncated record
// header: ..." if its 9-byte prefix does not fit, "record (opcode 0x6) of n bytes runs past the
// end (limit)" if its content does not, both at `pos`
RecordView RecordAt(const std::string& bytes, std::uint64_t pos, std::uint64_t limit);

// The records of bytes [begin, end), in order. Next() returns the record at pos() and steps
// over it; a record that does not fit throws McapError (RecordAt) and leaves pos() at its
// start, the end of the last whole record.
class RecordIterator {
 public:
  RecordIterator(const std::string& bytes, std::uint64_t begin, std::uint64_t end)
      : bytes_(bytes), pos_(begin), end_(end) {}
  bool done() const { return pos_ >= end_; }
  RecordView Next();
  std::uint64_t pos() const { return pos_; }
  std::uint64_t end() const { return end_; }
  // continues at `pos` (recovery resumes past a damaged record)
  void Seek(std::uint64_t pos) { pos_ = pos; }

 private:
  const std::string& bytes_;
  std::uint64_t pos_;
  std::uint64_t end_;
};

// the fields of a chunk record before its records
struct ChunkView {
  std::uint64_t start_time, end_time, uncompressed_size;
  std::uint32_t crc;
  std::string compression;
  std::uint64_t records_begin, records_end;  // the chunk's records [offsets in the file]
};

// parses the chunk record `r` and checks it: uncompressed (compression ""), uncompressed_size
// equal to the records' length, the CRC of the records when it is not 0; throws McapError
ChunkView ParseChunk(const std::string& bytes, const RecordView& r);

// The chunk walk: parses and checks the chunk record `r` (ParseChunk), then calls `fn` for
// every record inside it, in order; a record that does not fit throws McapError.
ChunkView WalkChunk(const std::string& bytes, const RecordView& r,
                    const std::function<void(const RecordView&)>& fn);

}  // namespace towsim::io::mcap
