#include "app/common/topic_types.h"

#include <algorithm>
#include <stdexcept>

#include "app/common/node_topics.h"
#include "dds/messages.h"
#include "io/ros2_schemas.h"

namespace towsim::app {

const std::vector<const dds_topic_descriptor_t*>& ContractTypes() {
  // the types of the node's topic table (app/common/node_topics.h), each once
  static const std::vector<const dds_topic_descriptor_t*> types = [] {
    std::vector<const dds_topic_descriptor_t*> all;
    for (const TopicRow& row : NodeTopicTable()) {
      if (std::find(all.begin(), all.end(), row.type) == all.end()) all.push_back(row.type);
    }
    return all;
  }();
  return types;
}

const dds_topic_descriptor_t* DescriptorOfRos2Type(const std::string& ros2_type) {
  for (const dds_topic_descriptor_t* d : ContractTypes()) {
    try {
      if (io::Ros2TypeName(d->m_typename) == ros2_type) return d;
    } catch (const std::invalid_argument&) {
    }
  }
  return nullptr;
}

std::vector<NodeTopic> NodeTopics(const dds::TopicNames& names,
                                  const std::vector<std::string>& bodies, bool with_scene_info) {
  std::vector<NodeTopic> all;
  for (const TopicRow& row : NodeTopicTable()) {
    if (row.per_body) continue;
    if (!with_scene_info && row.type == &towsim_msgs_msg_dds__SceneInfo__desc) continue;
    all.push_back({row.name(names, ""), row.type, row.transient_local()});
  }
  for (const std::string& b : bodies) {
    for (const TopicRow& row : NodeTopicTable()) {
      if (row.per_body) all.push_back({row.name(names, b), row.type, row.transient_local()});
    }
  }
  return all;
}

}  // namespace towsim::app
