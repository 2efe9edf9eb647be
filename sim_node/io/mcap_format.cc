#include "io/mcap_format.h"

#include <array>
#include <sstream>

namespace towsim::io::mcap {
namespace {

std::array<std::uint32_t, 256> MakeCrcTable() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
    table[i] = c;
  }
  return table;
}

}  // namespace

void Crc32::Update(const void* data, std::size_t size) {
  static const std::array<std::uint32_t, 256> kTable = MakeCrcTable();
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint32_t c = state_;
  for (std::size_t i = 0; i < size; ++i) c = kTable[(c ^ p[i]) & 0xFFu] ^ (c >> 8);
  state_ = c;
}

std::uint32_t ComputeCrc32(const void* data, std::size_t size) {
  Crc32 crc;
  crc.Update(data, size);
  return crc.value();
}

void Encoder::Le(std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void Encoder::Str(const std::string& s) {
  U32(static_cast<std::uint32_t>(s.size()));
  out_.append(s);
}

void Encoder::Raw(const void* data, std::size_t size) {
  out_.append(static_cast<const char*>(data), size);
}

void Encoder::Map(const StringMap& m) {
  Encoder entries;
  for (const auto& [key, value] : m) {
    entries.Str(key);
    entries.Str(value);
  }
  U32(static_cast<std::uint32_t>(entries.size()));
  out_.append(entries.bytes());
}

void AppendRecord(std::string& out, Op op, const std::string& content) {
  Encoder prefix;
  prefix.U8(static_cast<std::uint8_t>(op));
  prefix.U64(content.size());
  out.append(prefix.bytes());
  out.append(content);
}

McapError::McapError(const std::string& what, std::uint64_t offset)
    : std::runtime_error(what + " (at byte offset " + std::to_string(offset) + ")"),
      offset_(offset) {}

std::string Hex(std::uint32_t v) {
  std::ostringstream s;
  s << "0x" << std::hex << v;
  return s.str();
}

Decoder::Decoder(const std::string& bytes, std::uint64_t begin, std::uint64_t end,
                 const char* what)
    : b_(bytes), pos_(begin), end_(end), what_(what) {
  if (begin > end || end > bytes.size()) {
    throw McapError(std::string(what) + " lies outside the file (ends at " + std::to_string(end) +
                        " of " + std::to_string(bytes.size()) + ")",
                    begin);
  }
}

std::string Decoder::Bytes(std::uint64_t n) {
  Need(n);
  std::string s = b_.substr(pos_, n);
  pos_ += n;
  return s;
}

StringMap Decoder::Map() {
  const std::uint64_t n = U32();
  Need(n);
  Decoder entries(b_, pos_, pos_ + n, what_);
  pos_ += n;
  StringMap m;
  while (!entries.done()) {
    std::string key = entries.Str();
    m[key] = entries.Str();
  }
  return m;
}

void Decoder::Need(std::uint64_t n) const {
  if (n > end_ - pos_) {
    throw McapError(std::string("truncated ") + what_ + ": need " + std::to_string(n) +
                        " bytes, " + std::to_string(end_ - pos_) + " left",
                    pos_);
  }
}

std::uint64_t Decoder::Le(int n) {
  Need(n);
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) {
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b_[pos_ + i])) << (8 * i);
  }
  pos_ += n;
  return v;
}

}  // namespace towsim::io::mcap
