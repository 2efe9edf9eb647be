#pragma once
// The QoS of the towsim topics (issue 4):
//   state, /clock, status   reliable, keep last 1, volatile: a reliable writer matches both
//                           reliable and best-effort ROS 2 subscribers, and keep-last 1
//                           never blocks the node on a slow subscriber;
//   commands                reliable, keep last 1: the newest command wins;
//   sim_control             reliable, keep last 32: no request is lost in a burst;
//   scene_info, /tf_static  reliable, transient local, keep last 1: late joiners get it.
// Every one fixes the data representation to XCDR1 (plain CDR), which ROS 2 expects.

#include "dds/dds.h"

namespace towsim::dds {

// an owned dds_qos_t, move-only
class Qos {
 public:
  Qos();
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

// history depth of the reader side, for readers that must not lose samples (tests, loggers)
Qos StateQos(int depth = 1);
Qos CommandQos();
Qos ControlQos();
Qos SceneInfoQos();

}  // namespace towsim::dds
