#include "io/cdr_reader.h"

#include <cstdio>
#include <cstring>
#include <utility>

namespace towsim::io::cdr {

CdrError::CdrError(const std::string& what, std::size_t offset)
    : std::runtime_error(what + " (at byte offset " + std::to_string(offset) + ")"),
      offset_(offset) {}

CdrReader::CdrReader(const std::uint8_t* data, std::size_t size, std::string type)
    : data_(data), size_(size), type_(std::move(type)) {
  if (size_ < kHeaderSize) {
    throw CdrError(type_ + ": " + std::to_string(size_) +
                       " bytes, too short for the 4-byte CDR encapsulation header",
                   0);
  }
  // representation identifier, big endian: 0x0000 CDR_BE, 0x0001 CDR_LE
  if (data_[0] != 0x00 || data_[1] > 0x01) {
    char id[16];
    std::snprintf(id, sizeof id, "0x%02x%02x", data_[0], data_[1]);
    throw CdrError(type_ + ": encapsulation " + id +
                       " is not XCDR1 (0x0000 big endian or 0x0001 little endian)",
                   0);
  }
  little_endian_ = data_[1] == 0x01;
  pos_ = kHeaderSize;
}

void CdrReader::Fail(const std::string& what, const char* field) const {
  throw CdrError(type_ + "." + field + ": " + what, pos_);
}

void CdrReader::Need(std::size_t n, const char* field) const {
  if (n > size_ - pos_) {
    Fail("needs " + std::to_string(n) + " bytes, the payload has " + std::to_string(size_ - pos_) +
             " left of " + std::to_string(size_),
         field);
  }
}

// alignment is relative to the body, i.e. to the byte after the encapsulation header
void CdrReader::Align(std::size_t n, const char* field) {
  const std::size_t pad = (n - (pos_ - kHeaderSize) % n) % n;
  Need(pad, field);
  pos_ += pad;
}

std::uint64_t CdrReader::Unsigned(std::size_t n, const char* field) {
  Align(n, field);
  Need(n, field);
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t byte = data_[pos_ + i];
    v |= little_endian_ ? byte << (8 * i) : byte << (8 * (n - 1 - i));
  }
  pos_ += n;
  return v;
}

std::uint8_t CdrReader::U8(const char* field) {
  return static_cast<std::uint8_t>(Unsigned(1, field));
}
std::uint16_t CdrReader::U16(const char* field) {
  return static_cast<std::uint16_t>(Unsigned(2, field));
}
std::uint32_t CdrReader::U32(const char* field) {
  return static_cast<std::uint32_t>(Unsigned(4, field));
}
std::uint64_t CdrReader::U64(const char* field) { return Unsigned(8, field); }

double CdrReader::F64(const char* field) {
  const std::uint64_t bits = Unsigned(8, field);
  double v;
  std::memcpy(&v, &bits, sizeof v);  // IEEE 754 binary64
  return v;
}

std::string CdrReader::String(const char* field) {
  const std::uint32_t n = U32(field);  // bytes including the terminating NUL
  if (n == 0) Fail("string length 0 (XCDR1 strings include their NUL)", field);
  Need(n, field);
  if (data_[pos_ + n - 1] != 0)
    Fail("string of " + std::to_string(n) + " bytes without NUL", field);
  std::string s(reinterpret_cast<const char*>(data_ + pos_), n - 1);
  pos_ += n;
  return s;
}

std::uint32_t CdrReader::SequenceLength(const char* field, std::size_t min_element_size) {
  const std::uint32_t n = U32(field);
  if (min_element_size > 0 && n > (size_ - pos_) / min_element_size) {
    Fail("sequence of " + std::to_string(n) + " elements does not fit in the " +
             std::to_string(size_ - pos_) + " bytes left",
         field);
  }
  return n;
}

void CdrReader::Finish() {
  if (size_ - pos_ > 3) {
    throw CdrError(type_ + ": " + std::to_string(size_ - pos_) +
                       " bytes left after the last field (at most 3 of padding expected)",
                   pos_);
  }
}

}  // namespace towsim::io::cdr
