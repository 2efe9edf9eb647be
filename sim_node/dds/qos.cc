#include "dds/qos.h"

#include <utility>

namespace towsim::dds {
namespace {

// reliable, keep last `depth`, XCDR1; a writer blocks at most this long on a full history
// (never with keep-last)
constexpr dds_duration_t kMaxBlocking = DDS_MSECS(100);

Qos Reliable(int depth) {
  Qos q;
  dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, kMaxBlocking);
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, depth);
  dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q.get(), 1, &xcdr1);
  return q;
}

}  // namespace

Qos::Qos() : qos_(dds_create_qos()) {}
Qos::~Qos() {
  if (qos_ != nullptr) dds_delete_qos(qos_);
}
Qos::Qos(Qos&& other) noexcept : qos_(std::exchange(other.qos_, nullptr)) {}
Qos& Qos::operator=(Qos&& other) noexcept {
  if (this != &other) {
    if (qos_ != nullptr) dds_delete_qos(qos_);
    qos_ = std::exchange(other.qos_, nullptr);
  }
  return *this;
}

Qos StateQos(int depth) { return Reliable(depth); }

Qos CommandQos() { return Reliable(1); }

Qos ControlQos() { return Reliable(32); }

Qos SceneInfoQos() {
  Qos q = Reliable(1);
  dds_qset_durability(q.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
  return q;
}

}  // namespace towsim::dds
