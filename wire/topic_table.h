#pragma once
// The topics of the wire contract (docs/contract.md §3 and §7, docs/topics.md) in one table: one row per
// topic with its scope, its name below the scope, its type and its QoS profile. The node
// (sim_node/app/node_topics.cc adds the translator and the rate of each row it publishes), the
// controllers' client, the test fixture, the tests and the benchmarks name topics through it
// (wire/topic_names.h), so a new topic is one row here.
//
// The scope says where a row's name sits (with <ns> the node's namespace):
//   kRoot    rt/<name>                   /clock, /tf: where ROS 2 tools look
//   kNode    rt/<ns>/<name>              one per node: status, sim_control, ...
//   kBody    rt/<ns>/<body>/<name>       one per body: odom, command, ...
//   kCable   rt/<ns>/<cable>/<name>      one per cable; the one cable is "cable" (kOneCable)
//   kWinch   rt/<ns>/<winch>/<name>      one per winch; the one winch is "winch" (kOneWinch)
// so a per-cable topic rt/<ns>/<cable>/state keeps the one-cable name rt/<ns>/cable/state.
// A row of a topic that exists only for some owners (a cable end's force: a held end, or a
// body's attachment among several) is named for every owner; the node writes the ones its
// scene has (sim_node/app/common/node_topics.cc), a subscriber to another one hears nothing.

#include <vector>

#include "dds/dds.h"
#include "wire/qos.h"

namespace towsim::wire {

enum class Scope { kRoot, kNode, kBody, kCable, kWinch };

// the owner of kCable and kWinch rows in a scene with one cable and one winch
inline constexpr const char* kOneCable = "cable";
inline constexpr const char* kOneWinch = "winch";

// every topic of the contract, in the order of TopicTable()
enum class Topic {
  kSceneInfo,
  kClock,
  kStatus,
  kCableState,
  kCableStartForce,
  kCableEndForce,
  kSimControl,
  kWinchCommand,
  kTf,
  kTfStatic,
  kMarkers,
  kOdom,
  kCableForce,
  kAltitude,
  kPressure,
  kEnvironment,
  kActuatorState,
  kCommand,
  kPoseCommand,
};

// which way a topic flows, seen from the node
enum class Direction { kOut, kIn };

struct TopicSpec {
  Topic topic;
  Scope scope;
  const char* name;  // below the scope: "odom", "state", "sim_control"
  const dds_topic_descriptor_t* type;
  QosProfile qos;
  Direction direction;
};

// every row, scene_info first, then the node's topics, then the topics of each body
const std::vector<TopicSpec>& TopicTable();

// the row of `topic`
const TopicSpec& SpecOf(Topic topic);

}  // namespace towsim::wire
