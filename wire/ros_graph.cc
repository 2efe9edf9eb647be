#include "wire/ros_graph.h"

#include <cstring>
#include <stdexcept>

#include "rmw_dds_common.h"

namespace towsim::wire {
namespace {

dds_entity_t Check(dds_entity_t e, const std::string& what) {
  if (e < 0) throw std::runtime_error(what + ": " + dds_strretcode(e));
  return e;
}

}  // namespace

dds_qos_t* NewParticipantQos() {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_userdata(qos, kEnclaveUserData, std::strlen(kEnclaveUserData));
  return qos;
}

Gid EntityGid(dds_entity_t entity) {
  dds_guid_t guid;
  const dds_return_t rc = dds_get_guid(entity, &guid);
  if (rc < 0) throw std::runtime_error(std::string("dds_get_guid: ") + dds_strretcode(rc));
  Gid gid;
  static_assert(sizeof(guid.v) == sizeof(Gid), "a DDS GUID is 16 bytes");
  std::memcpy(gid.data(), guid.v, gid.size());
  return gid;
}

RosGraphNode::RosGraphNode(dds_entity_t participant, const std::string& ns, const std::string& name,
                           const std::vector<dds_entity_t>& readers,
                           const std::vector<dds_entity_t>& writers) {
  topic_ =
      Check(dds_create_topic(participant, &rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc,
                             kDiscoveryTopic, nullptr, nullptr),
            std::string("creating topic ") + kDiscoveryTopic);
  // reliable, transient local, keep last 1 (rmw_cyclonedds' QoS of this topic), XCDR1
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_durability_service(qos, 0, DDS_HISTORY_KEEP_LAST, 1, DDS_LENGTH_UNLIMITED,
                              DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  dds_qset_writer_data_lifecycle(qos, false);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(qos, 1, &xcdr1);
  writer_ = dds_create_writer(participant, topic_, qos, nullptr);
  dds_delete_qos(qos);
  Check(writer_, std::string("creating a writer for ") + kDiscoveryTopic);

  // the sample: the participant and its one node
  auto to_msg = [](const Gid& gid) {
    rmw_dds_common_msg_dds__Gid_ g;
    std::memcpy(g.data, gid.data(), gid.size());
    return g;
  };
  std::vector<rmw_dds_common_msg_dds__Gid_> reader_gids, writer_gids;
  for (dds_entity_t r : readers) reader_gids.push_back(to_msg(EntityGid(r)));
  for (dds_entity_t w : writers) writer_gids.push_back(to_msg(EntityGid(w)));
  // bounded strings (string<=256): char arrays in the generated type
  if (ns.size() > 256 || name.size() > 256) {
    throw std::runtime_error("ROS 2 node name or namespace longer than 256 characters");
  }
  rmw_dds_common_msg_dds__NodeEntitiesInfo_ node{};
  std::strncpy(node.node_namespace, ns.c_str(), sizeof node.node_namespace - 1);
  std::strncpy(node.node_name, name.c_str(), sizeof node.node_name - 1);
  node.reader_gid_seq = {static_cast<uint32_t>(reader_gids.size()),
                         static_cast<uint32_t>(reader_gids.size()),
                         reader_gids.empty() ? nullptr : reader_gids.data(), false};
  node.writer_gid_seq = {static_cast<uint32_t>(writer_gids.size()),
                         static_cast<uint32_t>(writer_gids.size()),
                         writer_gids.empty() ? nullptr : writer_gids.data(), false};
  rmw_dds_common_msg_dds__ParticipantEntitiesInfo_ info{};
  info.gid = to_msg(EntityGid(participant));
  info.node_entities_info_seq = {1, 1, &node, false};
  const dds_return_t rc = dds_write(writer_, &info);
  if (rc < 0) {
    throw std::runtime_error(std::string("writing ") + kDiscoveryTopic + ": " + dds_strretcode(rc));
  }
}

RosGraphNode::~RosGraphNode() {
  if (writer_ > 0) dds_delete(writer_);
  if (topic_ > 0) dds_delete(topic_);
}

}  // namespace towsim::wire
