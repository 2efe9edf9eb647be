#pragma once
// A reader of XCDR1 ("plain CDR", OMG DDS-XTypes 1.3 §7.4.1 / CORBA CDR) payloads as DDS
// puts them on the wire and rosbag2 stores them in MCAP (message encoding "cdr"):
//
//   <encapsulation header: 0x00, kind (0x00 big endian, 0x01 little endian), options u16>
//   <body>
//
// In the body every primitive is aligned to its own size (1, 2, 4 or 8 bytes), counted from
// the first byte after the header; a string is a u32 length that includes the terminating NUL,
// then the bytes and the NUL; a sequence is a u32 element count, then the elements; a fixed
// array is its elements. The byte order is the header's. XCDR2 (kinds 0x10..0x15), and
// parameter lists (0x02, 0x03) are rejected: towsim's types are @final, published as XCDR1.
//
// Every read checks the bounds first: a short or malformed buffer throws CdrError naming the
// field and the byte offset (in the payload, header included), never reads past the end.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace towsim::io::cdr {

class CdrError : public std::runtime_error {
 public:
  CdrError(const std::string& what, std::size_t offset);
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

class CdrReader {
 public:
  // `data` (size bytes) must outlive the reader; `type` names the message in errors.
  // Throws CdrError if the encapsulation header is missing or not XCDR1.
  CdrReader(const std::uint8_t* data, std::size_t size, std::string type);

  bool little_endian() const { return little_endian_; }
  std::size_t offset() const { return pos_; }             // in the payload [bytes]
  std::size_t remaining() const { return size_ - pos_; }  // [bytes]

  std::uint8_t U8(const char* field);
  std::uint16_t U16(const char* field);
  std::uint32_t U32(const char* field);
  std::uint64_t U64(const char* field);
  std::int32_t I32(const char* field) { return static_cast<std::int32_t>(U32(field)); }
  std::int64_t I64(const char* field) { return static_cast<std::int64_t>(U64(field)); }
  double F64(const char* field);
  std::string String(const char* field);
  // a sequence length, checked against the bytes left: each element needs at least
  // `min_element_size` bytes, so a corrupt count cannot make the caller allocate gigabytes
  std::uint32_t SequenceLength(const char* field, std::size_t min_element_size);

  // after the last field: at most 3 bytes of padding may follow (XCDR1 pads the payload to a
  // multiple of 4); more means the bytes are not this type. Throws CdrError.
  void Finish();

 private:
  void Align(std::size_t n, const char* field);
  void Need(std::size_t n, const char* field) const;
  std::uint64_t Unsigned(std::size_t n, const char* field);
  [[noreturn]] void Fail(const std::string& what, const char* field) const;

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string type_;
  bool little_endian_ = true;
  static constexpr std::size_t kHeaderSize = 4;
};

}  // namespace towsim::io::cdr
