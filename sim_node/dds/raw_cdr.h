#pragma once
// Raw CDR plumbing: samples as the exact bytes that travel on the wire, so that a
// recording holds what was published and a replay publishes what was recorded, without
// re-serializing.
//
//   RawType odom(participant, &nav_msgs_msg_dds__Odometry__desc);
//   CdrSample s = CdrSample::FromSample(odom, &msg);   // serialized once by Cyclone
//   s.Write(writer, dds_time());                       // the same bytes on DDS ...
//   s.CopyTo(&bytes);                                  // ... and into the recording
//   TakeRaw(reader, [](const uint8_t* p, size_t n, const dds_sample_info_t& info) {...});
//
// The bytes are the serialized payload including the 4-byte encapsulation header
// ({0x00, 0x01, 0, 0} = CDR little endian, XCDR1), as rosbag2 stores them in MCAP (`cdr`).
//
// Cyclone 0.10 has no public call that returns the sertype (Cyclone's description of a type
// for serialization) of a topic. Sertypes are interned per domain: every topic of the same
// type in a domain shares one sertype. RawType obtains it once by a probe: a private topic of
// the type, a writer and a reader in the same participant, one zeroed sample written and
// taken back with dds_takecdr, whose serdata names the sertype; the probe entities are deleted
// again. Serialization (ddsi_serdata_from_sample), reconstruction from bytes
// (ddsi_serdata_from_ser_iov, which also validates them) and the write (dds_forwardcdr, which
// keeps the source timestamp given) then go through that sertype. A serdata of another sertype
// of the same type name is converted by Cyclone from its bytes, so writing stays correct even
// if a writer derived its own sertype.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dds/dds.h"
#include "dds/entities.h"

struct ddsi_sertype;
struct ddsi_serdata;

namespace towsim::dds {

// the sertype of a generated type (a topic descriptor of msgs/) in a participant's domain
class RawType {
 public:
  // throws DdsError if the probe fails
  RawType(const Participant& participant, const dds_topic_descriptor_t* descriptor);
  ~RawType();
  RawType(RawType&& other) noexcept;
  RawType& operator=(RawType&& other) noexcept;
  RawType(const RawType&) = delete;
  RawType& operator=(const RawType&) = delete;

  const ddsi_sertype* get() const { return sertype_; }
  const dds_topic_descriptor_t* descriptor() const { return descriptor_; }
  // the DDS type name, e.g. "nav_msgs::msg::dds_::Odometry_"
  std::string type_name() const { return descriptor_->m_typename; }

  // bytes -> a sample of the generated C type (test and diagnostics): `sample` must point to
  // zeroed storage of descriptor()->m_size bytes; free its contents with dds_sample_free(...,
  // DDS_FREE_CONTENTS). False if the bytes are not a valid sample of the type.
  bool Deserialize(const void* data, std::size_t size, void* sample) const;

 private:
  const dds_topic_descriptor_t* descriptor_ = nullptr;
  ddsi_sertype* sertype_ = nullptr;  // counted reference
};

// one serialized sample: owns a reference to a Cyclone serdata
class CdrSample {
 public:
  CdrSample() = default;
  ~CdrSample();
  CdrSample(CdrSample&& other) noexcept;
  CdrSample& operator=(CdrSample&& other) noexcept;
  CdrSample(const CdrSample&) = delete;
  CdrSample& operator=(const CdrSample&) = delete;

  // serializes `sample` (a pointer to the generated C type of `type`); throws DdsError
  static CdrSample FromSample(const RawType& type, const void* sample);
  // the serialized bytes (with the encapsulation header) of a sample of `type`; throws
  // std::invalid_argument if Cyclone rejects them (too short, bad header, not a valid sample)
  static CdrSample FromBytes(const RawType& type, const void* data, std::size_t size);

  bool valid() const { return serdata_ != nullptr; }
  // serialized size including the 4-byte encapsulation header [bytes]
  std::size_t size() const;
  // replaces *out with the bytes (keeps its capacity)
  void CopyTo(std::vector<std::uint8_t>* out) const;
  std::vector<std::uint8_t> bytes() const;

  // writes the sample on `writer` with `source_timestamp` [ns since the Unix epoch, as
  // dds_time()]; the bytes are sent as they are. Returns Cyclone's return code. Write a
  // sample once (the writer's history keeps the serdata, whose timestamp this sets).
  dds_return_t Write(dds_entity_t writer, dds_time_t source_timestamp) const;

 private:
  explicit CdrSample(ddsi_serdata* serdata) : serdata_(serdata) {}
  ddsi_serdata* serdata_ = nullptr;
};

// Takes every available sample of `reader` (oldest first) in serialized form and calls
// f(const uint8_t* data, size_t size, const dds_sample_info_t& info) for each one with valid
// data (the bytes are valid during the call only; info.source_timestamp is the writer's).
// Returns the number passed to f, or Cyclone's error code (< 0).
template <class F>
int TakeRaw(dds_entity_t reader, F&& f);

// the serialized bytes of a serdata (helper of TakeRaw)
void SerdataBytes(const ddsi_serdata* serdata, std::vector<std::uint8_t>* out);
void UnrefSerdata(ddsi_serdata* serdata);

template <class F>
int TakeRaw(dds_entity_t reader, F&& f) {
  constexpr int kBatch = 32;
  int delivered = 0;
  std::vector<std::uint8_t> bytes;
  for (;;) {
    ddsi_serdata* samples[kBatch] = {};
    dds_sample_info_t infos[kBatch];
    const dds_return_t n = dds_takecdr(reader, samples, kBatch, infos, DDS_ANY_STATE);
    if (n < 0) return n;
    for (int i = 0; i < n; ++i) {
      if (infos[i].valid_data) {
        SerdataBytes(samples[i], &bytes);
        f(bytes.data(), bytes.size(), infos[i]);
        ++delivered;
      }
      UnrefSerdata(samples[i]);
    }
    if (n < kBatch) break;
  }
  return delivered;
}

}  // namespace towsim::dds
