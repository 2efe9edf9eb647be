#pragma once
// The ROS 2 graph (ROS 2 Jazzy's rmw_cyclonedds and rmw_dds_common; docs/ros2_graph.md): what
// makes `ros2 node list`, `ros2 node info` and rqt_graph show a towsim process as a node.
//
//   - the participant carries USER_DATA "enclave=/;" (ParticipantQos), as rmw_cyclonedds sets
//     it for the default enclave;
//   - a writer on the DDS topic "ros_discovery_info" (no "rt/" prefix) of
//     rmw_dds_common/msg/ParticipantEntitiesInfo, reliable, transient local, keep last 1,
//     holds one sample: the participant's GID and one NodeEntitiesInfo (namespace, name, the
//     GIDs of the node's readers and writers);
//   - a GID is the 16-byte DDS GUID of the entity (dds_get_guid), Jazzy's Gid layout.
//
// Only the C API of Cyclone DDS: used by sim_node, the controllers, the tests and the tools.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dds/dds.h"

namespace towsim::wire {

inline constexpr const char* kDiscoveryTopic = "ros_discovery_info";
inline constexpr const char* kEnclaveUserData = "enclave=/;";

using Gid = std::array<std::uint8_t, 16>;

// a new participant QoS with USER_DATA "enclave=/;"; free with dds_delete_qos
dds_qos_t* NewParticipantQos();

// the GID of a participant, reader or writer; throws std::runtime_error if it has none
Gid EntityGid(dds_entity_t entity);

// The node's entry in ros_discovery_info. Not copyable; deletes its writer and topic.
class RosGraphNode {
 public:
  // creates the ros_discovery_info writer of `participant` (which it does not list) and
  // publishes the node `ns` (e.g. "/towsim") / `name` (e.g. "sim_node") with `readers` and
  // `writers`; throws std::runtime_error naming the failed call
  RosGraphNode(dds_entity_t participant, const std::string& ns, const std::string& name,
               const std::vector<dds_entity_t>& readers, const std::vector<dds_entity_t>& writers);
  ~RosGraphNode();
  RosGraphNode(const RosGraphNode&) = delete;
  RosGraphNode& operator=(const RosGraphNode&) = delete;

  dds_entity_t writer() const { return writer_; }

 private:
  dds_entity_t topic_ = 0, writer_ = 0;
};

}  // namespace towsim::wire
