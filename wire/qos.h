#pragma once
// The QoS of the towsim topics (docs/topics.md), the one definition the node (its C++
// wrapper sim_node/dds/qos.h), the client library, the test fixture, the tests' participants and
// the benchmarks use; each row of wire/topic_table.h names its profile:
//   kState     state, /clock, status   reliable, keep last `depth` (1 for writers), volatile: a
//                                      reliable writer matches both reliable and best-effort
//                                      ROS 2 subscribers, and keep-last never blocks the node
//                                      on a slow subscriber;
//   kCommand   commands                reliable, keep last 1 (kCommandDepth): the newest
//                                      command wins;
//   kControl   sim_control             reliable, keep last 32 (kControlDepth): no request lost
//                                      in a burst;
//   kLatched   scene_info, /tf_static  reliable, transient local, keep last 1: late joiners
//                                      get it.
// Every one fixes the data representation to XCDR1 (plain CDR), which ROS 2 expects; a writer
// blocks at most 100 ms on a full history (never with keep-last). ros_discovery_info keeps the
// QoS rmw_cyclonedds gives it (wire/ros_graph.cc). The functions return a new dds_qos_t the
// caller deletes (dds_delete_qos).

#include "dds/dds.h"

namespace towsim::wire {

inline constexpr int kCommandDepth = 1;
inline constexpr int kControlDepth = 32;

enum class QosProfile { kState, kLatched, kCommand, kControl };

dds_qos_t* ReliableQos(int depth, bool transient_local);

// the QoS of `profile`; `state_depth`: the history of a kState reader that must not lose
// samples (tests, loggers), ignored for the other profiles
dds_qos_t* ProfileQos(QosProfile profile, int state_depth = 1);

}  // namespace towsim::wire
