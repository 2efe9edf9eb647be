#include "wire/topic_names.h"

#include <cctype>
#include <stdexcept>
#include <utility>

namespace towsim::wire {
namespace {

// the ROS 2 prefix of topics on DDS (rmw_cyclonedds: "rt" for ROS topics)
constexpr const char* kRosTopicPrefix = "rt";

bool IsNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// [A-Za-z_][A-Za-z0-9_]*
bool IsName(const std::string& s, size_t begin, size_t end) {
  if (begin >= end || !IsNameStart(s[begin])) return false;
  for (size_t i = begin + 1; i < end; ++i) {
    if (!IsNameChar(s[i])) return false;
  }
  return true;
}

}  // namespace

std::string CheckNamespace(const std::string& ns) {
  if (ns.empty() || ns[0] != '/') return "must start with '/' (e.g. /towsim)";
  if (ns == "/") return "";
  if (ns.back() == '/') return "must not end with '/'";
  size_t begin = 1;
  while (begin <= ns.size()) {
    size_t end = ns.find('/', begin);
    if (end == std::string::npos) end = ns.size();
    if (!IsName(ns, begin, end)) {
      return "segment '" + ns.substr(begin, end - begin) + "' must match [A-Za-z_][A-Za-z0-9_]*";
    }
    begin = end + 1;
  }
  return "";
}

std::string CheckBodyName(const std::string& name) {
  if (!IsName(name, 0, name.size())) return "must match [A-Za-z_][A-Za-z0-9_]*";
  return "";
}

std::string RosTopicName(const std::string& dds_topic) {
  const std::string prefix = std::string(kRosTopicPrefix) + "/";
  if (dds_topic.rfind(prefix, 0) == 0) return dds_topic.substr(prefix.size() - 1);
  return dds_topic.empty() || dds_topic[0] != '/' ? "/" + dds_topic : dds_topic;
}

std::string DdsTopicName(const std::string& ros_topic) {
  return kRosTopicPrefix + (ros_topic.empty() || ros_topic[0] != '/' ? "/" + ros_topic : ros_topic);
}

TopicNames::TopicNames(std::string ns)
    : ns_(std::move(ns)), prefix_(ns_ == "/" ? DdsTopicName("/") : DdsTopicName(ns_) + "/") {}

std::string TopicNames::Name(Topic topic, const std::string& owner) const {
  const TopicSpec& s = SpecOf(topic);
  switch (s.scope) {
    case Scope::kRoot:
      return DdsTopicName(s.name);
    case Scope::kNode:
      return prefix_ + s.name;
    case Scope::kBody:
      if (owner.empty()) throw std::invalid_argument(std::string(s.name) + ": needs a body");
      return prefix_ + owner + "/" + s.name;
    case Scope::kCable:
      return prefix_ + (owner.empty() ? kOneCable : owner) + "/" + s.name;
    case Scope::kWinch:
      return prefix_ + (owner.empty() ? kOneWinch : owner) + "/" + s.name;
  }
  return "";
}

std::optional<std::string> TopicNames::Owner(Topic topic, const std::string& dds_topic) const {
  const TopicSpec& s = SpecOf(topic);
  if (s.scope == Scope::kRoot || s.scope == Scope::kNode) return std::nullopt;
  const std::string suffix = std::string("/") + s.name;
  if (dds_topic.size() <= prefix_.size() + suffix.size() || dds_topic.rfind(prefix_, 0) != 0 ||
      dds_topic.compare(dds_topic.size() - suffix.size(), std::string::npos, suffix) != 0) {
    return std::nullopt;
  }
  return dds_topic.substr(prefix_.size(), dds_topic.size() - prefix_.size() - suffix.size());
}

}  // namespace towsim::wire
