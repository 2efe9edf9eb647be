#pragma once
// MCAP container format, major version 0 (https://mcap.dev/spec): the constants shared by
// McapWriter and McapReader, a CRC-32 and little-endian encoding helpers.
//
// Every record is <opcode u8><content length u64><content>; integers are little-endian;
// a String is <u32 byte length><utf-8>, a Map / Array is <u32 byte length><entries>.
// A file is <magic><Header><data section><DataEnd>[<summary>][<summary offsets>]<Footer><magic>.

#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

namespace towsim::io::mcap {

// 0x89 "MCAP" '0' "\r\n": '0' is the major version
inline constexpr unsigned char kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
inline constexpr std::size_t kMagicSize = 8;
inline constexpr std::size_t kRecordPrefixSize = 9;    // opcode u8 + content length u64
inline constexpr std::size_t kFooterContentSize = 20;  // summary_start, summary_offset_start, crc

enum class Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

using StringMap = std::map<std::string, std::string>;

// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, as zlib's crc32), incremental
class Crc32 {
 public:
  void Update(const void* data, std::size_t size);
  std::uint32_t value() const { return ~state_; }

 private:
  std::uint32_t state_ = 0xFFFFFFFFu;
};
std::uint32_t ComputeCrc32(const void* data, std::size_t size);

// appends little-endian fields to a byte string (the serialized record content)
class Encoder {
 public:
  void U8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void U16(std::uint16_t v) { Le(v, 2); }
  void U32(std::uint32_t v) { Le(v, 4); }
  void U64(std::uint64_t v) { Le(v, 8); }
  void Str(const std::string& s);  // u32 length + bytes
  void Raw(const void* data, std::size_t size);
  void Map(const StringMap& m);  // u32 byte length + (string, string) tuples
  std::string& bytes() { return out_; }
  std::size_t size() const { return out_.size(); }

 private:
  void Le(std::uint64_t v, int n);
  std::string out_;
};

// serializes a whole record (<opcode><u64 length><content>) onto `out`
void AppendRecord(std::string& out, Op op, const std::string& content);

// an error in an MCAP file: the message names the byte offset where it was found
class McapError : public std::runtime_error {
 public:
  McapError(const std::string& what, std::uint64_t offset);
  std::uint64_t offset() const { return offset_; }

 private:
  std::uint64_t offset_;
};

// "0x1f": a CRC or an opcode in an error message
std::string Hex(std::uint32_t v);

// reads little-endian fields from bytes [begin, end) of a buffer, Encoder's counterpart; a
// read past `end` throws McapError "truncated <what>: need n bytes, m left" at the absolute
// offset
class Decoder {
 public:
  // throws McapError "<what> lies outside the file" unless begin <= end <= bytes.size()
  Decoder(const std::string& bytes, std::uint64_t begin, std::uint64_t end, const char* what);
  std::uint8_t U8() { return static_cast<std::uint8_t>(Le(1)); }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Le(2)); }
  std::uint32_t U32() { return static_cast<std::uint32_t>(Le(4)); }
  std::uint64_t U64() { return Le(8); }
  std::string Bytes(std::uint64_t n);
  std::string Str() { return Bytes(U32()); }
  StringMap Map();
  bool done() const { return pos_ >= end_; }
  std::uint64_t pos() const { return pos_; }
  std::uint64_t remaining() const { return end_ - pos_; }

 private:
  void Need(std::uint64_t n) const;
  std::uint64_t Le(int n);

  const std::string& b_;
  std::uint64_t pos_;
  std::uint64_t end_;
  const char* what_;
};

}  // namespace towsim::io::mcap
