#include "app/common/topic_types.h"

#include <algorithm>
#include <stdexcept>

#include "dds/messages.h"
#include "io/ros2_schemas.h"

namespace towsim::app {

const std::vector<const dds_topic_descriptor_t*>& ContractTypes() {
  // the types of the wire's topic table (wire/topic_table.h), each once
  static const std::vector<const dds_topic_descriptor_t*> types = [] {
    std::vector<const dds_topic_descriptor_t*> all;
    for (const wire::TopicSpec& row : wire::TopicTable()) {
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

std::vector<NodeTopic> NodeTopics(const wire::TopicNames& names,
                                  const std::vector<std::string>& bodies, bool with_scene_info,
                                  const std::vector<std::string>& cables,
                                  const std::vector<std::string>& winches) {
  std::vector<NodeTopic> all;
  auto add = [&](const wire::TopicSpec& row, const std::string& owner) {
    all.push_back({names.Name(row.topic, owner), row.type, row.qos == wire::QosProfile::kLatched});
  };
  const std::vector<std::string> one_cable = {wire::kOneCable};
  for (const wire::TopicSpec& row : wire::TopicTable()) {
    if (row.scope == wire::Scope::kBody) continue;
    if (!with_scene_info && row.topic == wire::Topic::kSceneInfo) continue;
    if (row.scope == wire::Scope::kCable) {
      for (const std::string& c : cables.empty() ? one_cable : cables) add(row, c);
      continue;
    }
    if (row.scope == wire::Scope::kWinch && !winches.empty()) {
      for (const std::string& w : winches) add(row, w);
      continue;
    }
    add(row, "");
  }
  for (const std::string& b : bodies) {
    for (const wire::TopicSpec& row : wire::TopicTable()) {
      if (row.scope == wire::Scope::kBody) add(row, b);
    }
  }
  return all;
}

}  // namespace towsim::app
