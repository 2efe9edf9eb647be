#pragma once
// The QoS of the towsim topics (docs/topics.md), the one definition the node (its C++
// wrapper sim_node/dds/qos.h), the client library and the tests' participants use:
//   state, /clock, status   reliable, keep last `depth`, volatile: a reliable writer matches
//                           both reliable and best-effort ROS 2 subscribers, and keep-last
//                           never blocks the node on a slow subscriber;
//   commands                reliable, keep last 1 (kCommandDepth): the newest command wins;
//   sim_control             reliable, keep last 32 (kControlDepth): no request lost in a burst;
//   scene_info, /tf_static  reliable, transient local, keep last 1: late joiners get it.
// Every one fixes the data representation to XCDR1 (plain CDR), which ROS 2 expects; a writer
// blocks at most 100 ms on a full history (never with keep-last). Returns a new dds_qos_t the
// caller deletes (dds_delete_qos).

#include "dds/dds.h"

namespace towsim::controllers {

inline constexpr int kCommandDepth = 1;
inline constexpr int kControlDepth = 32;

dds_qos_t* ReliableQos(int depth, bool transient_local);

}  // namespace towsim::controllers
