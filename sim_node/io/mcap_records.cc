#include "io/mcap_records.h"

namespace towsim::io::mcap {

RecordView RecordAt(const std::string& bytes, std::uint64_t pos, std::uint64_t limit) {
  Decoder d(bytes, pos, limit, "record header");
  RecordView r{};
  r.start = pos;
  r.op = static_cast<Op>(d.U8());
  r.length = d.U64();
  r.content = d.pos();
  if (r.length > limit - r.content) {
    throw McapError("record (opcode " + Hex(static_cast<unsigned>(r.op)) + ") of " +
                        std::to_string(r.length) + " bytes runs past the end (" +
                        std::to_string(limit) + ")",
                    pos);
  }
  return r;
}

RecordView RecordIterator::Next() {
  const RecordView r = RecordAt(bytes_, pos_, end_);
  pos_ = r.end();
  return r;
}

ChunkView ParseChunk(const std::string& bytes, const RecordView& r) {
  Decoder d(bytes, r.content, r.end(), "chunk record");
  ChunkView c{};
  c.start_time = d.U64();
  c.end_time = d.U64();
  c.uncompressed_size = d.U64();
  c.crc = d.U32();
  c.compression = d.Str();
  const std::uint64_t n = d.U64();
  if (n > d.remaining()) throw McapError("chunk records run past the chunk record", d.pos());
  c.records_begin = d.pos();
  c.records_end = d.pos() + n;
  if (!c.compression.empty()) {
    throw McapError("unsupported chunk compression \"" + c.compression + "\"", r.start);
  }
  if (c.uncompressed_size != n) {
    throw McapError("chunk uncompressed_size " + std::to_string(c.uncompressed_size) +
                        " != records length " + std::to_string(n),
                    r.start);
  }
  if (c.crc != 0) {
    const std::uint32_t computed = ComputeCrc32(bytes.data() + c.records_begin, n);
    if (computed != c.crc) {
      throw McapError("chunk CRC mismatch: stored " + Hex(c.crc) + ", computed " + Hex(computed),
                      r.start);
    }
  }
  return c;
}

ChunkView WalkChunk(const std::string& bytes, const RecordView& r,
                    const std::function<void(const RecordView&)>& fn) {
  const ChunkView c = ParseChunk(bytes, r);
  for (RecordIterator it(bytes, c.records_begin, c.records_end); !it.done();) fn(it.Next());
  return c;
}

}  // namespace towsim::io::mcap
