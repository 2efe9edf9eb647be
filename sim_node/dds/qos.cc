#include "dds/qos.h"

#include <utility>

namespace towsim::dds {

Qos::Qos() : qos_(dds_create_qos()) {}
Qos::Qos(dds_qos_t* owned) : qos_(owned) {}
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

Qos QosOf(wire::QosProfile profile, int state_depth) {
  return Qos(wire::ProfileQos(profile, state_depth));
}

Qos StateQos(int depth) { return QosOf(wire::QosProfile::kState, depth); }

Qos CommandQos() { return QosOf(wire::QosProfile::kCommand); }

Qos ControlQos() { return QosOf(wire::QosProfile::kControl); }

Qos SceneInfoQos() { return QosOf(wire::QosProfile::kLatched); }

}  // namespace towsim::dds
