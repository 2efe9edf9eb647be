#include "dds/qos.h"

#include <utility>

#include "common/dds_qos.h"

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

Qos StateQos(int depth) { return Qos(controllers::ReliableQos(depth, false)); }

Qos CommandQos() { return Qos(controllers::ReliableQos(controllers::kCommandDepth, false)); }

Qos ControlQos() { return Qos(controllers::ReliableQos(controllers::kControlDepth, false)); }

Qos SceneInfoQos() { return Qos(controllers::ReliableQos(1, true)); }

}  // namespace towsim::dds
