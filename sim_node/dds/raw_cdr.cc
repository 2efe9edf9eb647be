#include "dds/raw_cdr.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "dds/ddsi/ddsi_serdata.h"
#include "dds/ddsi/ddsi_sertype.h"
#include "dds/qos.h"

namespace towsim::dds {
namespace {

// the probe's topic: not under rt/, so ROS 2 tools do not list it; unique per process and type
std::string ProbeTopicName(const dds_topic_descriptor_t* descriptor) {
  static int counter = 0;
  std::string name = descriptor->m_typename;
  for (char& c : name) {
    if (c == ':') c = '_';
  }
  return "towsim_sertype_probe/" + std::to_string(static_cast<long>(::getpid())) + "/" +
         std::to_string(++counter) + "/" + name;
}

}  // namespace

RawType::RawType(const Participant& participant, const dds_topic_descriptor_t* descriptor)
    : descriptor_(descriptor) {
  const std::string what = std::string("finding the serializer of ") + descriptor->m_typename;
  const dds_entity_t t = dds_create_topic(participant.get(), descriptor,
                                          ProbeTopicName(descriptor).c_str(), nullptr, nullptr);
  if (t < 0) throw DdsError(what + " (probe topic)", t);
  Entity topic(t);
  // the same QoS as the towsim topics (XCDR1), so the sertype is theirs
  Qos qos = StateQos(1);
  const dds_entity_t w = dds_create_writer(participant.get(), t, qos.get(), nullptr);
  if (w < 0) throw DdsError(what + " (probe writer)", w);
  Entity writer(w);
  const dds_entity_t r = dds_create_reader(participant.get(), t, qos.get(), nullptr);
  if (r < 0) throw DdsError(what + " (probe reader)", r);
  Entity reader(r);

  // a zeroed sample (null strings and empty sequences serialize as empty); local delivery is
  // synchronous, so the reader holds it when dds_write returns
  void* sample = std::calloc(1, descriptor->m_size);
  const dds_return_t rc = dds_write(w, sample);
  std::free(sample);
  if (rc < 0) throw DdsError(what + " (probe write)", rc);
  ddsi_serdata* serdata[1] = {nullptr};
  dds_sample_info_t info[1];
  const dds_return_t n = dds_takecdr(r, serdata, 1, info, DDS_ANY_STATE);
  if (n < 0) throw DdsError(what + " (probe take)", n);
  if (n != 1 || serdata[0] == nullptr) throw DdsError(what + " (probe took no sample)", -1);
  sertype_ = ddsi_sertype_ref(serdata[0]->type);
  ddsi_serdata_unref(serdata[0]);
}

RawType::~RawType() {
  if (sertype_ != nullptr) ddsi_sertype_unref(sertype_);
}

RawType::RawType(RawType&& other) noexcept
    : descriptor_(other.descriptor_), sertype_(std::exchange(other.sertype_, nullptr)) {}

RawType& RawType::operator=(RawType&& other) noexcept {
  if (this != &other) {
    if (sertype_ != nullptr) ddsi_sertype_unref(sertype_);
    descriptor_ = other.descriptor_;
    sertype_ = std::exchange(other.sertype_, nullptr);
  }
  return *this;
}

bool RawType::Deserialize(const void* data, std::size_t size, void* sample) const {
  if (size < 4) return false;
  ddsrt_iovec_t iov;
  iov.iov_base = const_cast<void*>(data);
  iov.iov_len = static_cast<ddsrt_iov_len_t>(size);
  ddsi_serdata* d = ddsi_serdata_from_ser_iov(sertype_, SDK_DATA, 1, &iov, size);
  if (d == nullptr) return false;
  // a serdata of this sertype converts to the generated C type (mallocs strings, sequences)
  const bool ok = ddsi_serdata_to_sample(d, sample, nullptr, nullptr);
  ddsi_serdata_unref(d);
  return ok;
}

CdrSample::~CdrSample() {
  if (serdata_ != nullptr) ddsi_serdata_unref(serdata_);
}

CdrSample::CdrSample(CdrSample&& other) noexcept
    : serdata_(std::exchange(other.serdata_, nullptr)) {}

CdrSample& CdrSample::operator=(CdrSample&& other) noexcept {
  if (this != &other) {
    if (serdata_ != nullptr) ddsi_serdata_unref(serdata_);
    serdata_ = std::exchange(other.serdata_, nullptr);
  }
  return *this;
}

CdrSample CdrSample::FromSample(const RawType& type, const void* sample) {
  ddsi_serdata* d = ddsi_serdata_from_sample(type.get(), SDK_DATA, sample);
  if (d == nullptr) {
    throw DdsError("serializing a sample of " + type.type_name(), DDS_RETCODE_BAD_PARAMETER);
  }
  return CdrSample(d);
}

CdrSample CdrSample::FromBytes(const RawType& type, const void* data, std::size_t size) {
  // 4 bytes of encapsulation header, then the payload
  if (size < 4) {
    throw std::invalid_argument("a serialized " + type.type_name() + " of " + std::to_string(size) +
                                " bytes: shorter than the 4-byte header");
  }
  ddsrt_iovec_t iov;
  iov.iov_base = const_cast<void*>(data);
  iov.iov_len = static_cast<ddsrt_iov_len_t>(size);
  ddsi_serdata* d = ddsi_serdata_from_ser_iov(type.get(), SDK_DATA, 1, &iov, size);
  if (d == nullptr) {
    throw std::invalid_argument("the " + std::to_string(size) + " bytes are not a valid CDR " +
                                type.type_name());
  }
  return CdrSample(d);
}

std::size_t CdrSample::size() const {
  return serdata_ == nullptr ? 0 : ddsi_serdata_size(serdata_);
}

void CdrSample::CopyTo(std::vector<std::uint8_t>* out) const {
  if (serdata_ == nullptr) {
    out->clear();
    return;
  }
  SerdataBytes(serdata_, out);
}

std::vector<std::uint8_t> CdrSample::bytes() const {
  std::vector<std::uint8_t> out;
  CopyTo(&out);
  return out;
}

dds_return_t CdrSample::Write(dds_entity_t writer, dds_time_t source_timestamp) const {
  if (serdata_ == nullptr) return DDS_RETCODE_BAD_PARAMETER;
  // dds_forwardcdr consumes one reference and sends the timestamp and status info as they
  // are. The serdata then sits in the writer's history: write a CdrSample once.
  serdata_->timestamp.v = source_timestamp;
  serdata_->statusinfo = 0;
  return dds_forwardcdr(writer, ddsi_serdata_ref(serdata_));
}

void SerdataBytes(const ddsi_serdata* serdata, std::vector<std::uint8_t>* out) {
  const std::size_t n = ddsi_serdata_size(serdata);
  out->resize(n);
  if (n > 0) ddsi_serdata_to_ser(serdata, 0, n, out->data());
}

void UnrefSerdata(ddsi_serdata* serdata) {
  if (serdata != nullptr) ddsi_serdata_unref(serdata);
}

}  // namespace towsim::dds
