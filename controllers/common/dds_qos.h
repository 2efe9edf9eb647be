#pragma once
// The QoS a participant beside the node uses for its readers and writers (docs/topics.md:
// reliable, keep last `depth`, XCDR1 so that ROS 2 reads the samples; scene_info is transient
// local). Returns a new dds_qos_t the caller deletes (dds_delete_qos).

#include "dds/dds.h"

namespace towsim::controllers {

dds_qos_t* ReliableQos(int depth, bool transient_local);

}  // namespace towsim::controllers
