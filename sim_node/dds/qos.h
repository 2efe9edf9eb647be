#pragma once
// The QoS of the towsim topics, owned (RAII) for the node's entities. The definition is
// wire/qos.h (shared with the controllers, the tests and the tools): see there.

#include "dds/dds.h"
#include "wire/qos.h"

namespace towsim::dds {

// an owned dds_qos_t, move-only
class Qos {
 public:
  Qos();
  explicit Qos(dds_qos_t* owned);  // takes ownership
  ~Qos();
  Qos(Qos&& other) noexcept;
  Qos& operator=(Qos&& other) noexcept;
  Qos(const Qos&) = delete;
  Qos& operator=(const Qos&) = delete;
  const dds_qos_t* get() const { return qos_; }
  dds_qos_t* get() { return qos_; }

 private:
  dds_qos_t* qos_;
};

// the QoS of a profile (wire::ProfileQos); `state_depth`: the history of a kState reader
Qos QosOf(wire::QosProfile profile, int state_depth = 1);
// history depth of the reader side, for readers that must not lose samples (tests, loggers)
Qos StateQos(int depth = 1);
Qos CommandQos();
Qos ControlQos();
Qos SceneInfoQos();

}  // namespace towsim::dds
